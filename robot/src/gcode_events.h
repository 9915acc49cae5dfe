#pragma once
// What slicing's G-code reader leaves out and a robot program needs: the feed rate in effect on each line and
// the temperature and fan commands, in line order. (The moves themselves come from slicing::parseGcode.)
#include <string>
#include <vector>

#include "multidir/core/common/result.h"

namespace multidir::robot::detail {

struct GcodeEvent {
  enum class Kind { NozzleTemperature, NozzleTemperatureWait, FanOn, FanOff };
  Kind kind;
  int line = 0;          // 1-based
  double value = 0.0;    // degrees C (temperatures), fan duty 0..255 (FanOn)
};

struct GcodeSideInfo {
  std::vector<double> feedMmPerMinByLine;  // index: line (1-based; [0] unused); the feed after that line
  std::vector<GcodeEvent> events;          // in line order
  std::vector<int> layerChangeLines;       // ";LAYER_CHANGE" comments (PrusaSlicer)
};

// Errors: CheckFailed naming `name` and the line of a G28 (homing: a fixed-nozzle cell has no printer axes to
// home; the profile's start G-code must not home) or of a malformed F or S word.
core::Result<GcodeSideInfo> scanGcodeSideInfo(const std::string& text, const std::string& name);

}  // namespace multidir::robot::detail

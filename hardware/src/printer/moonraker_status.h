#pragma once
// Reads the reply of Moonraker's /printer/objects/query (the "result" object: {"eventtime", "status": {...}}).
#include <nlohmann/json.hpp>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"

namespace multidir::hardware {

struct MoonrakerReading {
  PrinterJobState state = PrinterJobState::Unknown;
  std::string firmwareState;
  std::string message;
  double progress = 0.0;
  std::string currentFile;
  HeaterReading extruder;
  HeaterReading bed;
};

// "standby" ... "error" -> the state; anything else is Unknown.
PrinterJobState parsePrinterJobState(const std::string& text);

// Errors: DeviceFault naming `printer` when the reply has no status.print_stats.state (not Klipper's Moonraker).
core::Result<MoonrakerReading> readMoonrakerStatus(const nlohmann::json& result, const std::string& printer);

}  // namespace multidir::hardware

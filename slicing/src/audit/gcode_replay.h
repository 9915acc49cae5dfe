#pragma once
// The audit's own reading of G-code (not parseGcode: the audit should not share what it checks): every move
// in printer coordinates with the platform's angle, the filament pushed and whether the filament was
// retracted when the move began. The machine's state is passed in and out, so programs that run one after
// another on one machine (a Modbus platform's step programs) carry the nozzle and the filament over.
//
// Understood: G0/G1 (X Y Z E F and the rotary axes' letters), G90/G91, M82/M83, G92, G28, G10/G11 (firmware
// retraction), Klipper's MANUAL_STEPPER STEPPER=name ... SET_POSITION= / MOVE=, PrusaSlicer's ";TYPE:" comments
// and MultiDir's section markers. Arcs (G2/G3) are refused: the audit would have to guess their path.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"

namespace multidir::slicing::audit {

// A firmware rotary axis the replay follows: its G-code letter and its Klipper [manual_stepper] (empty: any
// MANUAL_STEPPER line drives it, as for the one firmware axis).
struct ReplayAxis {
  char letter = 'A';
  std::string stepper;
};
constexpr std::size_t kMaxRotaryAxes = 2;  // firmware-2axis: tilt (0) and rotation (1)

struct MachineState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // printer coordinates, mm
  double e = 0.0;                                      // the E register
  std::array<double, kMaxRotaryAxes> axesDegrees{};    // the rotary axes, in the order they were given
  bool absoluteXyz = true;                             // G90; G91 makes every axis relative, E too
  bool absoluteE = true;           // M82; M83 makes E relative whatever G90 says (Marlin's and Klipper's rule)
  double retractedMm = 0.0;        // filament pulled back and not yet pushed again
  bool firmwareRetracted = false;  // G10 without G11
};

struct ReplayMove {
  int line = 0;
  Eigen::Vector3d from = Eigen::Vector3d::Zero();
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  std::array<double, kMaxRotaryAxes> axesFrom{};  // the rotary axes before and after the move, degrees
  std::array<double, kMaxRotaryAxes> axesTo{};
  double filamentMm = 0.0;  // E pushed (negative: pulled back)
  int step = 0;             // 0: before any marker, in the start or the end sequence
  bool inTransition = false;
  bool skirt = false;             // under ";TYPE:Skirt/Brim" (or Skirt, Brim)
  std::string feature;            // the slicer's ";TYPE:" it lies under ("External perimeter"), empty if none
  bool retractedAtStart = false;  // an extrusion that began with the filament retracted: (d)

  bool movesXy() const { return (to.head<2>() - from.head<2>()).squaredNorm() > 1e-12; }
  bool turns(std::size_t axis) const { return std::abs(axesTo[axis] - axesFrom[axis]) > 1e-9; }
  bool turns() const {
    for (std::size_t k = 0; k < kMaxRotaryAxes; ++k)
      if (turns(k)) return true;
    return false;
  }
  bool extrudes() const { return filamentMm > 1e-9 && movesXy(); }
};

struct Replay {
  std::vector<ReplayMove> moves;  // motion and extrusion only
  int lineCount = 0;
};

// `axes`: the rotary axes followed (at most kMaxRotaryAxes), in MachineState::axesDegrees' order.
// Errors: MalformedFile naming `name` and the line (a word that is not a number, an arc move).
core::Result<Replay> replayGcode(const std::string& text, const std::string& name, const std::vector<ReplayAxis>& axes,
                                 double retractToleranceMm, MachineState& state);

// The value of "; key = value" in the settings the slicer writes at the end of its G-code; empty when absent.
std::string slicerSetting(const std::string& gcode, const std::string& key);

}  // namespace multidir::slicing::audit

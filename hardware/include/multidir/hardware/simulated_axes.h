#pragma once
// The rotary axes a simulated printer has beside X, Y, Z and E (an Open5x-style tilt and rotation, a 4-DOF
// printer's A axis), and what the simulators record of them, so tests can check where the platform stood while
// each line of a job printed. docs/hardware.md ("Rotary axes in the printer simulators") gives the sources.
//
// Which axes a printer has is configuration, as on the real firmware: Marlin 2.1 and RepRapFirmware take extra
// axes as G-code letters (AXIS4_NAME.., M584), Klipper as [manual_stepper NAME] sections moved by MANUAL_STEPPER.
// A word for an axis the printer does not have is what that firmware makes of it: Marlin's and Klipper's G0/G1
// skip a letter they do not know; Klipper refuses MANUAL_STEPPER for a stepper it lacks ("The value 'x' is not
// valid for STEPPER", which ends a job from the SD card in "error").
#include <cstddef>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"

namespace multidir::hardware {

// At most this many rotary axes per simulated printer (Open5x has two; Marlin allows six).
inline constexpr std::size_t kMaxSimulatedRotaryAxes = 3;

struct SimulatedRotaryAxes {
  // G-code letters of rotary axes (Marlin, RepRapFirmware, and so OctoPrint): any of A B C U V W, e.g. {"U", "V"}.
  std::vector<std::string> letters;
  // Klipper's [manual_stepper NAME]s (the Moonraker simulator), e.g. {"tilt", "rotation"}.
  std::vector<std::string> manualSteppers;
};

// InvalidParameter (where `option`) for a letter outside A B C U V W, a letter or name given twice, a name that is
// empty or holds a space or '=', or more than kMaxSimulatedRotaryAxes axes.
core::Status validate(const SimulatedRotaryAxes& axes, const std::string& option);

// "U,V" or "tilt,rotation" (as the command line takes them) into names; empty text gives none.
std::vector<std::string> splitAxisList(const std::string& text);

// One move the simulated printer made, recorded when it ended.
struct SimulatedMove {
  std::size_t sequence = 0;   // the line's index among those the printer ran in this job (file lines or streamed
                              // commands, blank and comment lines counted where the file has them), from 0
  double startSeconds = 0.0;  // simulated seconds since the job started
  double endSeconds = 0.0;
  double xMm = 0.0, yMm = 0.0, zMm = 0.0;  // where the nozzle stands at the move's end (the G-code's coordinates)
  // Each rotary axis' coordinate at the move's end (degrees, the firmware's own), in the options' order
  // (letters, else manual steppers). For an extrusion, where it stood while the plastic went down.
  std::vector<double> axisDegrees;
};

struct SimulatedAxisLog {
  std::vector<SimulatedMove> extrusions;  // moves in X/Y/Z that pushed filament forward
  std::vector<SimulatedMove> turns;       // moves that changed a rotary axis' coordinate
  double printSeconds = 0.0;              // the job's simulated time so far
};

}  // namespace multidir::hardware

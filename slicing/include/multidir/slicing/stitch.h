#pragma once
// One program for a printer whose platform is a firmware axis: the step programs in printing order, one start
// and one end sequence, and between two steps: retract (to the profile's retract_length, counting what the
// slicer's own end of print drew back), lift to the turn's clearance, park, turn the platform (per dialect),
// return above the next step's first point, prime (push back what is drawn back plus retract_restart_extra),
// reset E.
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/slicing/estimates.h"
#include "multidir/slicing/gcode_checks.h"
#include "multidir/slicing/gcode_program.h"
#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/two_axis_motion.h"

namespace multidir::slicing {

// A step's G-code as the slicer wrote it with MultiDir's markers ("; MULTIDIR START SEQUENCE", "; MULTIDIR
// STEP k", "; MULTIDIR END SEQUENCE").
struct StepGcode {
  int step = 1;
  std::string text;
};

struct TurnPlan {
  int fromStep = 1;
  // The platform's angle while step fromStep prints and while the next one does, as its drive counts it:
  // a firmware axis' A (positive tilts the platform's top towards +Y), else the plan's rotaryDegrees.
  double fromDegrees = 0.0;
  double toDegrees = 0.0;
  double sweptTopZMm = 0.0;   // printer z of the highest point the printed part reaches while turning
  double clearanceZMm = 0.0;  // sweptTopZMm plus the profile's margin: where the nozzle waits
  // firmware-2axis: both axes' coordinates before and after, and the moves in the order that keeps the swept part
  // (and the platform's body) lowest; fromDegrees / toDegrees are then the tilt's.
  std::optional<TwoAxisTurn> twoAxis;
};

// The platform's axes as the profile's programs name them: the tilt and the rotation axis of a firmware-2axis
// printer (letters and Klipper steppers), else the one rotary axis.
std::vector<RotaryAxisName> rotaryAxisNames(const PrinterProfile& profile);

// How a step is primed after its filament was drawn back: the profile's retraction (or `--set`'s).
struct PrimeSettings {
  double retractLengthMm = 2.0;  // retract_length: drawn back while the platform turns
  double restartExtraMm = 0.0;   // retract_restart_extra: pushed on top when priming (may be negative)
  double speedMmPerS = 40.0;     // deretract_speed, or retract_speed when that is 0
};

// The lines that push the filament back before a step's first extrusion, from `state` (how the previous
// program left it): G11 after a firmware retraction, else G1 E by what is drawn back plus restartExtraMm,
// between two G92 E0 (so they work in M82 and M83 alike). A comment when there is nothing to push.
std::string primeCommands(const FilamentState& state, const PrimeSettings& prime);

// The lines that turn the platform to `degrees` (Klipper: MANUAL_STEPPER ... MOVE=, Marlin and RRF: G1 A),
// each preceded by M400 so that the queued moves end first.
std::string turnCommands(const PrinterProfile& profile, Dialect dialect, double degrees);

// The same for two firmware axes: each of the turn's moves in order, one axis per line (Klipper: the axis'
// manual_stepper; Marlin and RRF: G1 with its letter), M400 before the first and after each.
std::string twoAxisTurnCommands(const PrinterProfile& profile, Dialect dialect, const TwoAxisTurn& turn);

// The lines that declare where the axes stand when the program starts: at rest (G92 with each letter's rest
// coordinate; Klipper: each manual_stepper enabled with SET_POSITION).
std::string axisSetupCommands(const PrinterProfile& profile, Dialect dialect);

// The stitched program. The closing comments give the totals of `total` in PrusaSlicer's words, so
// parseEstimate reads them. Errors: InvalidParameter when a step lacks a marker, `turns` does not have one
// entry per gap, or a step has no XY move to return to.
core::Result<std::string> stitchProgram(const std::vector<StepGcode>& steps, const std::vector<TurnPlan>& turns,
                                        const PrinterProfile& profile, Dialect dialect, const Estimate& total,
                                        const PrimeSettings& prime);

}  // namespace multidir::slicing

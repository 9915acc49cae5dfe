#pragma once
// The checks `multidir slice` ran on each step's own program (step-NN.gcode), run again on the files as they
// are now: `multidir run` uploads them hours later, and a file edited by hand or replaced since (G1 A30,
// MANUAL_STEPPER ... MOVE=, G1 Z-5 E3) must be refused before anything moves. The same checkStepProgram, with
// the same bounds, in the same order (the filament as the previous step left it).
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/slicing/gcode_checks.h"
#include "multidir/slicing/printer_profile.h"

namespace multidir::slicing {

// The bounds `slice` checks step `step` against: the profile's bed and height, the step's base plane (printer
// z, mm) and the retract tolerance its prime allows (0.01 mm plus a negative retract_restart_extra).
StepBounds stepBoundsFor(const PrinterProfile& profile, double retractRestartExtraMm, int step, double baseZMm);

// One step's program as the job folder holds it now.
struct StepProgramText {
  int step = 1;
  std::string fileName;  // "step-01.gcode", named in errors
  std::string text;
  double baseZMm = 0.0;                   // print-job.json slicing.steps[].baseZMm
  std::optional<double> endClearanceZMm;  // the next turn's clearance (slicing.turns[].clearanceZMm), if one follows
};

// Every program in order, as `slice` checked them (retract_restart_extra from the profile's own settings).
// Errors: those of parseGcode and checkStepProgram, naming the file, step and line.
core::Status recheckStepPrograms(const std::vector<StepProgramText>& programs, const PrinterProfile& profile);

}  // namespace multidir::slicing

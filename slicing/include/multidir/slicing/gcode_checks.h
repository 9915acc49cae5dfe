#pragma once
// Checks on G-code read back by parseGcode (nothing a slicer writes is trusted). A failing check is a
// CheckFailed error naming the step, the file and line, and the reason:
//   "job.gcode: step 3, line 10234: extrusion at z 12.20 mm below the step's base plane (z 14.00 mm)".
#include <Eigen/Core>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/slicing/gcode_program.h"

namespace multidir::slicing {

// Where step k may put plastic (printer coordinates, mm).
struct StepBounds {
  int step = 1;
  double baseZMm = 0.0;  // the step's base plane (its region's lowest z once posed)
  Eigen::Vector2d bedMin = Eigen::Vector2d::Zero();
  Eigen::Vector2d bedMax = Eigen::Vector2d::Zero();
  double maxZMm = 0.0;     // the printer's height
  double toleranceMm = 1e-3;
};

// The platform's turn from step `fromStep` to the next, and the nozzle height it needs.
struct TurnClearance {
  int fromStep = 1;
  double clearanceZMm = 0.0;  // printer z the nozzle must be at or above while the platform turns
};

// What a program (or one step of it) lays down.
struct StepTotals {
  int step = 1;
  int extrusions = 0;
  double filamentMm = 0.0;   // pushed while moving in XY
  double lowestZMm = 0.0;    // of its extrusions
  double highestZMm = 0.0;
};

// One step's own program (step-NN.gcode): every extrusion of the step (the start sequence's purge included)
// lies inside the printer's volume, and those after the "; MULTIDIR STEP k" marker on or above the base
// plane. With `endClearanceZMm` (a Modbus platform turns after this step) the program must end with the
// nozzle at or above it. Errors: CheckFailed; also when the step extrudes nothing.
core::Result<StepTotals> checkStepProgram(const GcodeProgram& program, const StepBounds& bounds,
                                          const std::string& fileName, const double* endClearanceZMm = nullptr);

// A stitched program (job.gcode): each step's section checked as above; the platform turns only inside a
// transition section, by a move that moves nothing else, with the nozzle at or above that turn's clearance;
// inside a transition nothing is extruded and the nozzle moves in XY only at or above the clearance (retract,
// lift, park, turn, return, unretract). `bounds` has one entry per step in order, `turns` one per transition.
// Errors: CheckFailed.
core::Result<std::vector<StepTotals>> checkStitchedProgram(const GcodeProgram& program,
                                                           const std::vector<StepBounds>& bounds,
                                                           const std::vector<TurnClearance>& turns,
                                                           const std::string& fileName);

}  // namespace multidir::slicing

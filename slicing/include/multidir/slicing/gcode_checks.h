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

// How far the filament is drawn back from the nozzle, as a program's E moves leave it. A retraction (E going
// back) adds to retractedMm; pushing filament first takes it back to 0 (unretract, prime), only then does it
// extrude; a push beyond that is extrusion (or, without an XY move, a prime's extra). G10 / G11 draw it back and
// push it again by the firmware's own length. G92 E only renames the position: the filament stays where it is.
// Positions are tracked through M82 / M83 and G90 / G91 by parseGcode (GcodeMove::filamentMm).
struct FilamentState {
  double retractedMm = 0.0;
  bool firmwareRetracted = false;
  bool retracted(double toleranceMm) const { return firmwareRetracted || retractedMm > toleranceMm; }
};

// The state after `move`.
void advance(FilamentState& state, const GcodeMove& move);

// The state at the end of `program`, from `start`.
FilamentState filamentAtEnd(const GcodeProgram& program, FilamentState start = {});

// Where step k may put plastic (printer coordinates, mm).
struct StepBounds {
  int step = 1;
  double baseZMm = 0.0;  // the step's base plane (its region's lowest z once posed)
  Eigen::Vector2d bedMin = Eigen::Vector2d::Zero();
  Eigen::Vector2d bedMax = Eigen::Vector2d::Zero();
  double maxZMm = 0.0;     // the printer's height
  double toleranceMm = 1e-3;
  // Filament still drawn back at an extruding move up to this much (mm) is accepted: rounding of E to five
  // decimals, and a profile's negative retract_restart_extra (it unretracts less on purpose).
  double retractToleranceMm = 0.01;
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
  FilamentState filamentAtEnd;  // as the program leaves the filament (the next program starts with it)
};

// One step's own program (step-NN.gcode): every extrusion of the step (the start sequence's purge included)
// lies inside the printer's volume, and those after the "; MULTIDIR STEP k" marker on or above the base
// plane; no extrusion (the purge's included) happens with the filament drawn back (FilamentState, from
// `start`: how the previous step's program left it on the same printer); no move (travel too) goes below the
// bed (z 0); no move commands the platform's axis (G1 A.., MANUAL_STEPPER ... MOVE=), even to where the
// parser believes it stands. With `endClearanceZMm` (a Modbus
// platform turns after this step) the program must end with the nozzle at or above it. Errors: CheckFailed;
// also when the step extrudes nothing.
core::Result<StepTotals> checkStepProgram(const GcodeProgram& program, const StepBounds& bounds,
                                          const std::string& fileName, const double* endClearanceZMm = nullptr,
                                          FilamentState start = {});

// A stitched program (job.gcode): each step's section checked as above; the platform turns only inside a
// transition section, by a move that moves nothing else, with the nozzle at or above that turn's clearance;
// no move goes below the bed;
// no extrusion happens with the filament drawn back (from a primed start); inside a transition nothing is extruded and
// the nozzle moves in XY only at or above the clearance (retract, lift, park, turn, return, unretract). `bounds` has
// one entry per step in order, `turns` one per transition. Errors: CheckFailed.
core::Result<std::vector<StepTotals>> checkStitchedProgram(const GcodeProgram& program,
                                                           const std::vector<StepBounds>& bounds,
                                                           const std::vector<TurnClearance>& turns,
                                                           const std::string& fileName);

}  // namespace multidir::slicing

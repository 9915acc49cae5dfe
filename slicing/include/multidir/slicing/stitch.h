#pragma once
// One program for a printer whose platform is a firmware axis: the step programs in printing order, one start
// and one end sequence, and between two steps: retract, lift to the turn's clearance, park, turn the
// platform (per dialect), return above the next step's first point, unretract, reset E.
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/slicing/estimates.h"
#include "multidir/slicing/printer_profile.h"

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
};

// The lines that turn the platform to `degrees` (Klipper: MANUAL_STEPPER ... MOVE=, Marlin and RRF: G1 A),
// each preceded by M400 so that the queued moves end first.
std::string turnCommands(const PrinterProfile& profile, Dialect dialect, double degrees);

// The stitched program. The closing comments give the totals of `total` in PrusaSlicer's words, so
// parseEstimate reads them. Errors: InvalidParameter when a step lacks a marker, `turns` does not have one
// entry per gap, or a step has no XY move to return to.
core::Result<std::string> stitchProgram(const std::vector<StepGcode>& steps, const std::vector<TurnPlan>& turns,
                                        const PrinterProfile& profile, Dialect dialect, const Estimate& total);

}  // namespace multidir::slicing

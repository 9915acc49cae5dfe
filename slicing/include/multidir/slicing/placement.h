#pragma once
// Where the part stands on the platform, and whether every step of it fits the printer, decided before the
// slicer runs (docs/slicing.md, "Placement and fit").
//
// The part is fixed to the platform from its first layer on, so one placement serves every step: the part is
// moved by one offset d in the platform plane (the rest pose's XY), and step k's pose then moves it by Q_k d,
// Q_k the platform's rotation from the rest pose to step k's (about the pivot, which stays put). That is the
// job core::buildPrintJob would build with the pivot at the old one minus d (model frame): the step meshes,
// modelToFile, lowestHeightMm and the pivot are moved together.
#include <string>
#include <vector>

#include "multidir/core/plan/print_job.h"
#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/stitch.h"

namespace multidir::slicing {

// Step k's supports in the half-space above its base plane (machine frame: z >= baseZMm), closed: below the
// base plane lies the lower regions' plastic or air, and the nozzle prints nothing below step k's first layer.
// Each closed solid of `supports` (a strut's prism or frustum) is clipped by core::clipByPlane. Empty supports
// give an empty mesh. Errors: those of core::clipByPlane for a strut that is not a closed solid, naming the step.
core::Result<core::TriangleMesh> supportsAboveBasePlane(const core::TriangleMesh& supports, double baseZMm, int step);

// The job with every step's supports clipped to its base plane (supportsAboveBasePlane; supportVolumeMm3 is the
// clipped volume). Errors: those of supportsAboveBasePlane.
core::Result<core::PrintJob> withSupportsOnTheirBasePlanes(const core::PrintJob& job);

struct Placement {
  core::Vec3 offsetMm = core::Vec3::Zero();  // d: the part moved on the platform, rest pose (z = 0)
  core::PrintJob job;                        // the job moved by it
  std::vector<TurnPlan> turns;               // planTurns of `job`: the clearance of every turn, as checked
};

// The part placed on the platform so that it fits the printer with the most room: 3-DOF its footprint
// centred on the bed; 4-DOF moved along the rotation axis only (a move across it would raise every turn's
// swept part and change the heights) so that everything printed and swept lies centred along the axis; 5-DOF
// where the plan put it (the first region's footprint centred on the platform) when it fits there, else the
// offset with the most room over every step (a move raises, lowers and swings every tilted step). Then every
// step is checked against the bed's bounding box and max_print_height: its part (region and supports) as
// posed for it, on a rotary platform the part printed so far swept through the turn that follows it (exactly,
// over the arc; a robot arm's turns are bounded in height by planTurns, in XY by the poses), and each turn's
// clearance (planTurns). Also refused: a step that would print below the bed (z 0).
// Errors: TooLarge when it cannot fit (nothing is sliced), naming the step, the side and by how much, the scale factor that
// would fit and the bed and height a printer would need; InvalidParameter for a job not in the machine frame
// or without steps; Internal from planTurns.
core::Result<Placement> placeOnPlatform(const core::PrintJob& job, const PrinterProfile& profile);

}  // namespace multidir::slicing

#pragma once
// From print job to machine code: every step of a print job sliced by a real slicer (its region and its
// projected supports clipped to its base plane as one solid, posed as the machine holds it, layers starting on
// its base plane), the part placed where it fits the printer first, the steps sliced side by side, the G-code
// checked by parsing it, every step after the first primed, the stitched program for a firmware-axis platform,
// and the estimates.
//
// Written into the output folder (docs/plan-format.md, "slicing" in print-job.json):
//   step-01-region.stl ...   the print job (core::writePrintJob)
//   step-01.gcode ...        one program per step
//   job.gcode                the stitched program, when the platform is a firmware axis
//   print-job.json           the job, with a "slicing" object: estimates per step and in total, the turns
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/plan/print_job.h"
#include "multidir/slicing/estimates.h"
#include "multidir/slicing/gcode_checks.h"
#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/stitch.h"

namespace multidir::slicing {

struct SliceJobOptions {
  std::optional<Dialect> dialect;  // overrides the profile's multidir.dialect
  // Extra slicer settings applied after the profile (key, value as in a .ini), e.g. {"layer_height", "0.3"}.
  std::vector<std::pair<std::string, std::string>> settings;
  // Also slice the whole model along up with the slicer's own supports (the fixed-direction comparison).
  bool fixedDirection = true;
  std::string slicerExecutable = "prusa-slicer";
  // Write into an output folder that holds files other than a MultiDir job's (`multidir slice --force`): the
  // job's files replace those of the same names, the others stay. Without it such a folder is refused.
  bool writeIntoOtherFolder = false;
};

struct SlicedStep {
  int index = 1;
  std::string gcodeFile;   // "step-01.gcode"
  Estimate estimate;
  StepTotals totals;       // from the checks
  double baseZMm = 0.0;    // printer z of the step's base plane
  double zOffsetMm = 0.0;  // given to the slicer: where its layers start from (the base plane)
  double firstLayerZMm = 0.0;  // printer z of the step's first extrusion after its marker (its first layer)
  double sliceSeconds = 0.0;
  // Takes the plan's model coordinates to the printer's, as this step prints (the machine's pose of the part,
  // then the profile's platform centre and height): its inverse lays the step's G-code over its region.
  Eigen::Isometry3d modelToPrinter = Eigen::Isometry3d::Identity();
  // firmware-2axis: the axes' coordinates while this step prints (two_axis.h).
  std::optional<TwoAxisAngles> axisDegrees;
};

struct SlicedJob {
  std::string engine;             // "PrusaSlicer"
  PrinterProfile profile;
  Dialect dialect = Dialect::Marlin;
  std::vector<SlicedStep> steps;
  std::vector<TurnPlan> turns;    // one per gap between steps
  Estimate total;                 // sum over the steps
  std::optional<Estimate> fixedDirection;  // the whole model along up, the slicer's supports on
  double fixedDirectionSliceSeconds = 0.0;
  std::string stitchedFile;       // "job.gcode", empty when the platform is not a firmware axis
  // Where the part was placed on the platform (placeOnPlatform): the offset in the rest pose's XY, mm. The
  // steps' poses (modelToPrinter, the written print job) include it.
  Eigen::Vector3d placementMm = Eigen::Vector3d::Zero();
};

// The clearance of every turn between two steps (printer z): the printed regions and supports of steps 1..k
// posed for step k, turned to step k + 1 (4-DOF: exactly over the arc about the rotation axis; 5-DOF: any turn
// about the pivot; 3-DOF: no turn; two firmware axes: each axis' move exactly about its line, in the order that
// keeps the top lowest, the platform's disc and cradle included, the disc where the part was placed by
// `placementMm` when the profile gives no table: two_axis_motion.h), plus the profile's margin. Errors: Internal
// when consecutive poses do not differ by a turn about the axis; those of twoAxisAngles.
core::Result<std::vector<TurnPlan>> planTurns(const core::PrintJob& job, const PrinterProfile& profile,
                                               const Eigen::Vector3d& placementMm = Eigen::Vector3d::Zero());

// Slices `job` (frame Machine) for `profile` into `directory` (created when missing). The whole job is written
// into a fresh folder beside `directory` (core::StagedFolder) and put in its place only when complete: an empty
// folder or an earlier job (job_folder.h) is replaced as a whole in one step, so a slice that fails, is
// cancelled or is killed leaves `directory` as it was. A folder holding other files is refused before anything
// is done (InvalidParameter naming the folder and one such file), unless options.writeIntoOtherFolder: then the
// job's files are moved into it, print-job.json last, and the other files stay. First every step's
// supports are clipped to its base plane and the part is placed where it fits (placeOnPlatform, which refuses
// a part that cannot fit before any slicer runs); the job written and sliced is the placed one. The steps and
// the fixed-direction print are then sliced side by side, one slicer per usable CPU, each confined to its CPU
// and one thread (side_by_side.h: the same G-code on every run), and checked in printing order:
// each step after the first is primed by what the previous one left drawn back (plus retract_restart_extra).
// Progress: one share per step and one for the fixed-direction print, each filled as its slicer goes (their
// sum), one for stitching; the phase names the runs under way. Cancellation reaches every running slicer
// within about 50 ms. A G-code that fails a check is not kept (no step-NN.gcode, no job.gcode) and the job is
// refused; the work folder (.slicing-PID, inside the fresh folder) is removed however the job ends.
// Errors: InvalidParameter (a folder holding files that are not a MultiDir job, the job is in the model frame, the printer cannot turn its platform and the job has
// several steps, a firmware axis asked to print a 5-DOF plan), FileNotFound / ExternalToolFailed (the slicer),
// TooLarge (the part does not fit the printer, before anything is sliced), CheckFailed (a check of the G-code,
// naming step, line and reason), WriteFailed, Cancelled.
core::Result<SlicedJob> sliceJob(const core::PrintJob& job, const PrinterProfile& profile,
                                 const SliceJobOptions& options, const std::string& directory,
                                 core::JobContext& context);

// A plan (read from its folder, or made in memory) sliced as `multidir slice` and the studio do: its print job
// built in the machine frame with its supports (core::buildPrintJob), then sliceJob. Errors: those of both.
core::Result<SlicedJob> slicePlan(const core::LoadedPlan& plan, const PrinterProfile& profile,
                                  const SliceJobOptions& options, const std::string& directory,
                                  core::JobContext& context);

// What sliceJob is doing when its progress reads `fraction` (its shares: one per step, one for the
// fixed-direction print when asked for, one for stitching), so a caller can say it in its own words. Steps are
// sliced side by side, so "step k" is the number of steps' worth of slicing done, plus one.
struct SliceStage {
  enum class Kind { Step, FixedDirection, Stitching, Done };
  Kind kind = Kind::Step;
  int step = 1;  // Kind::Step: the step being sliced, from 1
};
SliceStage sliceStageAt(double fraction, int stepCount, bool fixedDirection);

}  // namespace multidir::slicing

#pragma once
// The sliced print job `multidir run` executes: print-job.json (docs/plan-format.md) with its "slicing" object
// from `multidir slice`, and the step G-code files beside it. Read and checked in full before anything moves;
// the machine limits it carries describe the plan, not the platform, and are not trusted for motion
// (run_job_checks.h checks the job against the platform's own profile).
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/search/machine.h"
#include "multidir/hardware/print_run.h"

namespace multidir::cli {

// A step's print time beyond this (a year) is no slicer's estimate: the job file is refused.
constexpr double kMaxStepPrintSeconds = 365.0 * 24.0 * 3600.0;

struct RunJobStep {
  int index = 1;
  hardware::PlatformOrientation orientation;
  std::string anglesField;       // "steps[0].angles", named in errors
  std::string gcodeField;        // "slicing.steps[0].gcode"
  std::string gcodePath;         // absolute or relative to the working directory: the job folder + the file name
  double estimateSeconds = 0.0;  // the slicer's estimate, 0 when the job has none
  double baseZMm = 0.0;          // slicing.steps[].baseZMm: the printer z its region starts at
  std::optional<double> turnClearanceZMm;  // slicing.turns[]: the nozzle's height before the next turn
};

// A job sliced for a platform the printer's firmware turns (slicing.printer.platform "firmware-axis" or
// "firmware-2axis"): one stitched program (slicing.stitched) turns the axes between the steps itself.
struct RunStitchedProgram {
  std::string platform;   // "firmware-axis" or "firmware-2axis"
  std::string dialect;    // slicing.printer.dialect: "klipper", "marlin", "rrf" ("" when absent)
  std::string gcodeName;  // slicing.stitched: "job.gcode"
  std::string gcodePath;  // the job folder + gcodeName
  std::vector<double> stepEstimateSeconds;  // slicing.steps[].estimate.printSeconds (0 where absent)
};

struct RunJob {
  std::string jobFile;  // the print-job.json read
  std::string folder;   // the folder it lies in
  core::MachineSpec machine;
  std::string printerProfile;  // slicing.printer.profile as `multidir slice` recorded it ("" when absent)
  std::vector<RunJobStep> steps;  // empty for a stitched job
  std::optional<RunStitchedProgram> stitched;
};

// Reads `path` (a job folder or its print-job.json) and checks everything the job alone can say. Throws
// FileError naming the file, the field and what is allowed: not JSON (naming the field of a number such as
// 1e999 or NaN), not a MultiDir print job, a version other than 1..kPrintJobFormatVersion, no "slicing" (run
// `multidir slice` first), a job for a firmware-turned platform without its stitched program (slicing.stitched
// missing, not a plain file name, or the file missing, a link or not a regular file), a 3-DOF job, a step without angles or G-code, a printSeconds outside [0, kMaxStepPrintSeconds], two steps
// naming the same G-code file, a G-code file that is missing, a symbolic link or not a regular file.
RunJob readRunJob(const std::string& path);

}  // namespace multidir::cli

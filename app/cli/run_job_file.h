#pragma once
// The sliced print job `multidir run` executes: print-job.json (docs/plan-format.md) with its "slicing" object
// from `multidir slice`, and the step G-code files beside it.
#include <string>
#include <vector>

#include "multidir/core/search/machine.h"
#include "multidir/hardware/print_run.h"

namespace multidir::cli {

struct RunJobStep {
  int index = 1;
  hardware::PlatformOrientation orientation;
  std::string gcodePath;         // absolute or relative to the working directory: the job folder + the file name
  double estimateSeconds = 0.0;  // the slicer's estimate, 0 when the job has none
};

struct RunJob {
  std::string jobFile;  // the print-job.json read
  core::MachineSpec machine;
  std::vector<RunJobStep> steps;
};

// Reads `path` (a job folder or its print-job.json). Throws FileError naming the file and the field: not a
// MultiDir print job, a newer version, no "slicing" (run `multidir slice` first), a stitched job for a
// firmware-axis platform (run job.gcode on the printer instead), a 3-DOF job, a step without angles or G-code,
// a G-code file that is missing.
RunJob readRunJob(const std::string& path);

}  // namespace multidir::cli

#pragma once
// A job for the devices: the plan whose regions the platform turns to, and the G-code a printer prints for
// each of them when the plan was sliced. The studio document holds the sliced job (StudioDocument::slicedJob)
// and the job the device session runs (StudioDocument::sessionJob), which a running print run pins.
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/search/decomposition.h"

namespace multidir::ui {

// One step's G-code of the sliced job, and the slicer's estimate of its printing time.
struct StepGcode {
  std::string path;
  double estimateSeconds = 0.0;
};

struct PrintJob {
  // The plan the job prints, region by region in printing order (null: no plan, nothing to run).
  std::shared_ptr<const core::Decomposition> plan;
  // The G-code of every region of the plan, in printing order; empty when the plan is not sliced (the operator
  // then prints each region by hand).
  std::vector<StepGcode> steps;
  // Keeps the G-code files on disk while any copy of the job is held.
  std::shared_ptr<const void> files;
};

}  // namespace multidir::ui

#pragma once
// The time left of a print run, from the slicer's estimate of each step's printing time (print-job.json's
// slicing.steps[].estimate.printSeconds, SlicedStep::estimate) and the printer's progress through the
// current step's file. Platform moves and settling are not in the estimates and not counted.
#include <cstddef>
#include <optional>
#include <vector>

namespace multidir::ui {

// Seconds left: the current step's estimate times the part not yet printed (`stepProgress` in [0, 1], clamped)
// plus every later step's estimate. nullopt when there is no estimate for every step (or `step` is past them).
std::optional<double> remainingJobSeconds(const std::vector<double>& stepEstimates, std::size_t step,
                                          double stepProgress);

}  // namespace multidir::ui

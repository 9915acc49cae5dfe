#include "ui/device/job_eta.h"

#include <algorithm>
#include <cmath>

namespace multidir::ui {

std::optional<double> remainingJobSeconds(const std::vector<double>& stepEstimates, std::size_t step,
                                          double stepProgress) {
  if (step >= stepEstimates.size()) return std::nullopt;
  for (const double estimate : stepEstimates)
    if (!std::isfinite(estimate) || estimate <= 0.0) return std::nullopt;  // a step without an estimate
  const double progress = std::isfinite(stepProgress) ? std::clamp(stepProgress, 0.0, 1.0) : 0.0;
  double seconds = stepEstimates[step] * (1.0 - progress);
  for (std::size_t k = step + 1; k < stepEstimates.size(); ++k) seconds += stepEstimates[k];
  return seconds;
}

}  // namespace multidir::ui

#include "ui/viewer/cell_motion.h"

#include <algorithm>

namespace multidir::ui {
namespace {

int positionsOf(const robot::StepMotion& step) { return std::max(1, static_cast<int>(step.samples.size())); }

}  // namespace

int cellPositionCount(const CellMotion& motion) {
  int count = 0;
  for (const auto& step : motion.steps) count += positionsOf(step);
  return count;
}

CellPosition cellPositionAt(const CellMotion& motion, int index) {
  if (motion.steps.empty()) return {};
  index = std::clamp(index, 0, cellPositionCount(motion) - 1);
  for (std::size_t s = 0; s < motion.steps.size(); ++s) {
    const int n = positionsOf(motion.steps[s]);
    if (index < n) return {static_cast<int>(s), index};
    index -= n;
  }
  return {static_cast<int>(motion.steps.size()) - 1, positionsOf(motion.steps.back()) - 1};
}

}  // namespace multidir::ui

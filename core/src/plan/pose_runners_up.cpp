#include "multidir/core/plan/pose_runners_up.h"

#include <algorithm>

namespace multidir::core {

std::vector<PlanPoseTrial> poseRunnersUp(const PoseSearchResult& result, int used) {
  std::vector<PlanPoseTrial> others;
  for (std::size_t i = 0; i < result.trials.size(); ++i) {
    const PoseTrial& t = result.trials[i];
    if (static_cast<int>(i) == used || t.regions == 0) continue;
    others.push_back({t.pose.up, poseSourceName(t.pose.source), t.jgAfterMm2, t.regions, t.searched,
                      t.pose.contactAreaMm2, t.pose.stabilityMarginMm});
  }
  std::stable_sort(others.begin(), others.end(), [](const PlanPoseTrial& a, const PlanPoseTrial& b) {
    if (a.searched != b.searched) return a.searched;
    return a.jgAfterMm2 < b.jgAfterMm2;
  });
  return others;
}

}  // namespace multidir::core

#pragma once
// The poses a pose search tried besides the one in use, as plan.json records them (PlanPose::runnersUp): the
// CLI and the studio write the same list.
#include <vector>

#include "multidir/core/plan/plan_file.h"
#include "multidir/core/search/pose_search.h"

namespace multidir::core {

// Every trial but `used` that has a plan (a pose ruled out, or cancelled before it was scored, has none: no J_G
// of it was measured), fully searched first, then by J_G; ties keep the candidates' order.
std::vector<PlanPoseTrial> poseRunnersUp(const PoseSearchResult& result, int used);

}  // namespace multidir::core

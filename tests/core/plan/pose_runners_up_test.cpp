// The other poses a pose search tried, as plan.json lists them: only poses with a plan, fully searched first.
#include <gtest/gtest.h>

#include "multidir/core/plan/pose_runners_up.h"

using namespace multidir::core;

namespace {

PoseTrial trial(double x, double jg, int regions, bool searched, bool ruledOut = false) {
  PoseTrial t;
  t.pose.up = Vec3(x, 0, 1).normalized();
  t.pose.source = PoseSource::Resting;
  t.pose.contactAreaMm2 = 10 * x + 1;
  t.pose.stabilityMarginMm = 1.0;
  t.jgAfterMm2 = jg;
  t.cheapJgMm2 = searched ? jg + 5 : jg;
  t.regions = regions;
  t.searched = searched;
  t.ruledOut = ruledOut;
  if (ruledOut) t.unavoidableMm2 = 500.0;
  return t;
}

}  // namespace

TEST(PoseRunnersUp, ListFullySearchedPosesFirstThenTheOthersByJg) {
  PoseSearchResult result;
  result.trials = {trial(0, 30, 3, true), trial(1, 20, 2, false), trial(2, 40, 4, true), trial(3, 10, 1, false),
                   trial(4, 5, 2, true)};
  result.chosenTrial = 4;
  const std::vector<PlanPoseTrial> others = poseRunnersUp(result, result.chosenTrial);
  ASSERT_EQ(others.size(), 4u);
  EXPECT_TRUE(others[0].searched && others[1].searched);
  EXPECT_DOUBLE_EQ(others[0].jgAfterMm2, 30);
  EXPECT_DOUBLE_EQ(others[1].jgAfterMm2, 40);
  EXPECT_DOUBLE_EQ(others[2].jgAfterMm2, 10);
  EXPECT_DOUBLE_EQ(others[3].jgAfterMm2, 20);
  EXPECT_EQ(others[0].source, "resting");
  EXPECT_DOUBLE_EQ(others[0].contactAreaMm2, 1.0);
}

TEST(PoseRunnersUp, LeaveOutThePoseInUseAndPosesWithoutAPlan) {
  // A pose ruled out by its bound, or never scored before a cancel, has no plan and no J_G to record.
  PoseSearchResult result;
  result.trials = {trial(0, 30, 3, true), trial(1, 0, 0, false, true), trial(2, 0, 0, false), trial(3, 12, 2, false)};
  const std::vector<PlanPoseTrial> others = poseRunnersUp(result, 3);
  ASSERT_EQ(others.size(), 1u);
  EXPECT_TRUE(others[0].up.isApprox(result.trials[0].pose.up, 1e-12));
}

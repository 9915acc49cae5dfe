// The apart machine's search is two searches, its own and the 5-DOF search for its bound (docs/apart.md):
// one progress runs over both (SearchProgress::fraction, stage of stageCount).
#include <gtest/gtest.h>

#include <mutex>
#include <vector>

#include "multidir/core/search/decompose.h"
#include "support/primitives.h"

using namespace multidir::core;

TEST(ApartProgress, TheFractionNeverGoesDownOverBothSearches) {
  MachineSpec machine;
  machine.kind = MachineKind::Apart;
  machine.rotationAxis = platformFrameX(machine.up);
  std::mutex mutex;
  std::vector<SearchProgress> reports;
  JobContext job;
  const Result<Decomposition> plan =
      decompose(multidir::test::makeInvertedPyramid(40.0, 10.0), machine, SearchOptions{}, job,
                [&](const SearchProgress& p) {
                  std::lock_guard<std::mutex> lock(mutex);
                  reports.push_back(p);
                });
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  ASSERT_FALSE(reports.empty());
  bool sawSecondStage = false;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    EXPECT_EQ(reports[i].stageCount, 2);
    EXPECT_GE(reports[i].fraction, 0.0);
    EXPECT_LE(reports[i].fraction, 1.0);
    if (i > 0) {
      EXPECT_GE(reports[i].fraction, reports[i - 1].fraction) << "report " << i << " of stage " << reports[i].stage;
      EXPECT_GE(reports[i].stage, reports[i - 1].stage) << "report " << i;
    }
    // The 5-DOF search starts where the apart search's half ends.
    if (reports[i].stage == 2) {
      sawSecondStage = true;
      EXPECT_GE(reports[i].fraction, 0.5) << "report " << i;
    }
  }
  EXPECT_TRUE(sawSecondStage);
}

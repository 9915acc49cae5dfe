// What the search reports while it runs (issue 29): the best J_G is always that of a complete plan the search
// has, so it never rises and, on Cancel, is the J_G of the plan delivered; the level is one the searches
// reached, under the bound that progress names as the total.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "multidir/core/search/decompose.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

struct CancelledRun {
  std::vector<SearchProgress> reports;
  Decomposition plan;
};

// The studio's default search (5-DOF, the default options) on `model`, cancelled at its `cancelAt`-th report.
CancelledRun cancelledSearch(const std::string& model, int cancelAt) {
  MachineSpec machine;
  machine.up = Vec3::UnitY();  // the shared models stand on +Y
  JobContext job;
  CancelledRun run;
  auto plan = decompose(multidir::test::loadSharedModel(model), machine, SearchOptions{}, job,
                        [&](const SearchProgress& p) {
                          run.reports.push_back(p);
                          if (static_cast<int>(run.reports.size()) == cancelAt) job.cancel();
                        });
  if (!plan.ok()) throw std::runtime_error(plan.error().describe());
  run.plan = std::move(plan).value();
  return run;
}

}  // namespace

TEST(SearchProgressReports, BestJgNeverRisesAndOnCancelIsTheDeliveredPlansJg) {
  for (int cancelAt : {2, 5}) {
    const CancelledRun run = cancelledSearch("fertility.off", cancelAt);
    ASSERT_TRUE(run.plan.cancelled) << "the search ended before its report " << cancelAt;
    ASSERT_FALSE(run.reports.empty());
    for (std::size_t i = 1; i < run.reports.size(); ++i)
      EXPECT_LE(run.reports[i].bestJgMm2, run.reports[i - 1].bestJgMm2)
          << "report " << i << " of the search cancelled at " << cancelAt;
    EXPECT_NEAR(run.reports.back().bestJgMm2, run.plan.jgAfterMm2, 1e-6 * std::max(1.0, run.plan.jgAfterMm2))
        << "cancelled at report " << cancelAt;
  }
}

TEST(SearchProgressReports, LevelIsOneReachedAndNeverAboveTheTotalProgressNames) {
  const CancelledRun run = cancelledSearch("fertility.off", 4);
  ASSERT_TRUE(run.plan.cancelled);
  const int total = maxSearchLevels(SearchOptions{});
  int previous = 0;
  for (const SearchProgress& p : run.reports) {
    EXPECT_LE(p.level, total);
    EXPECT_LE(p.level, run.plan.statistics.levels) << "a level no search reached";
    EXPECT_GE(p.level, previous) << "the level went back";
    previous = p.level;
  }
}

TEST(SearchProgressReports, TotalLevelsAreTheDeepestOneSearchMayReach) {
  // The searches run side by side, so progress names the deepest level any one of them may reach: the finest
  // scale's, whose regions keep at least V / (w 2^(S-1)), so its plans have at most ceil(w 2^(S-1)) + 1 cuts.
  SearchOptions options;
  options.minVolumeDivisor = 40;
  options.volumeScales = 2;
  EXPECT_EQ(maxSearchLevels(options), 81);
  options.volumeScales = 3;
  options.minVolumeDivisor = 2.5;
  EXPECT_EQ(maxSearchLevels(options), 11);
  options.scheme = SearchScheme::Greedy;  // the greedy schemes run at w alone
  EXPECT_EQ(maxSearchLevels(options), 4);
}

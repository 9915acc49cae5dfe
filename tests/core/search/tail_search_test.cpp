// Searching a polished plan's tails again (core/src/search/tail_search.h; docs/search.md, "Searching the tails
// again"): from each state of the polished plan, the later planes searched again and the best polished.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "multidir/core/search/decompose.h"
#include "multidir/core/search/plan_from_planes.h"
#include "search/search_engine.h"
#include "search/search_schemes.h"
#include "search/tail_search.h"
#include "support/same_planes.h"
#include "support/test_models.h"
#include "support/up_y_machine.h"

using namespace multidir::core;

namespace {

using multidir::test::upY;

SearchOptions withThreads(int threads) {
  SearchOptions options;
  options.threads = threads;
  return options;
}

// The default search's polished plan, and that plan with its tails searched again.
struct PolishedAndTails {
  Decomposition polished;
  Decomposition tails;
};

PolishedAndTails searchedWithTails(const TriangleMesh& model, const SearchOptions& options = SearchOptions{}) {
  JobContext job;
  auto plan = decompose(model, upY(), options, job);
  EXPECT_TRUE(plan.ok()) << plan.error().describe();
  if (!plan.ok()) return {};
  return {*plan, multidir::core::detail::withTailsSearchedAgain(model, upY(), options, *plan, job)};
}

}  // namespace

// The fertility statue's polished plan holds 602.43 mm^2 (4.55 %), mostly in two regions whose faces another
// region's direction would save; the planes after its first, searched again from the polished first region,
// polish to 289.68 mm^2 (2.19 %).
TEST(TailSearch, FindsAPlanForTheFertilityStatueFarBelowItsPolishedPlan) {
  const TriangleMesh fertility = multidir::test::loadSharedModel("fertility.off");
  const auto [polished, tails] = searchedWithTails(fertility);
  EXPECT_LT(tails.jgAfterMm2, 0.75 * polished.jgAfterMm2);
  // A plan the rules allow: its planes cut again with every criterion checked give the same J_G.
  auto recut = planFromClippingPlanes(fertility, upY(), SearchOptions{}, tails.clippingPlanes);
  ASSERT_TRUE(recut.ok()) << recut.error().describe();
  EXPECT_NEAR(recut->jgAfterMm2, tails.jgAfterMm2, 1e-6 * tails.jgBeforeMm2);
}

// No tail of the kitten ends below its polished 11.71 mm^2 (as found they end at 11.80 mm^2 or above): its
// plan stays.
TEST(TailSearch, KeepsThePlanWhenNoTailEndsLower) {
  const auto [polished, tails] = searchedWithTails(multidir::test::loadSharedModel("kitten.off"));
  EXPECT_TRUE(multidir::test::samePlanes(tails, polished));
  EXPECT_EQ(tails.jgAfterMm2, polished.jgAfterMm2);
}

// The knight's plan changes (74.95 -> 64.45 mm^2), by searches whose threads split the work differently.
TEST(TailSearch, GivesTheSamePlanForOneAndTwoThreads) {
  const TriangleMesh knight = multidir::test::loadSharedModel("knight.off");
  const Decomposition one = searchedWithTails(knight, withThreads(1)).tails;
  const Decomposition two = searchedWithTails(knight, withThreads(2)).tails;
  EXPECT_TRUE(multidir::test::samePlanes(one, two));
  EXPECT_EQ(one.jgAfterMm2, two.jgAfterMm2);
}

// A tail's search abandons the states whose regions already hold the J_G it must beat: the knight's beam of two
// from the uncut model, told to beat 100 mm^2, offers no plan whose regions cut off hold that much, while the
// same beam without the bound offers such plans (so the bound is what keeps them out).
TEST(TailSearch, ABeamToldWhatToBeatKeepsNoStateWhoseRegionsHoldAsMuch) {
  using namespace multidir::core::detail;
  const TriangleMesh knight = multidir::test::loadSharedModel("knight.off");
  const SearchOptions options;
  JobContext job;
  SearchEngine engine(knight, upY(), options, job);
  const auto largestPrefix = [&](double mustBeatMm2) {
    BestPlan offered(true);  // keeps every level's best: the offered plans' prefixes are read from them
    BeamScale scale;
    scale.minRegionVolume = engine.minRegionVolume(options.minVolumeDivisor);
    scale.beamWidth = 2;
    scale.maxLevels = 41;
    scale.abandonAtMm2 = mustBeatMm2;
    int levels = 0;
    runBeamSearch(engine, options, scale, offered, {}, levels);
    double largest = 0.0;
    for (const NodePtr& node : offered.finalists())
      if (node) largest = std::max(largest, node->prefixJgMm2);
    return largest;
  };
  EXPECT_GE(largestPrefix(INFINITY), 100.0);
  EXPECT_LT(largestPrefix(100.0), 100.0);
}

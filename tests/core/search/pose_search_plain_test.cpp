// The pose search's full search of a pose is the plain search at that pose (docs/search.md, "The pose search"):
// the same polished plan, on the same proxy for a huge model. So with the given up standing, --pose auto never
// delivers more J_G than `decompose` at the given up.
#include <gtest/gtest.h>

#include <stdexcept>

#include "multidir/core/search/decompose.h"
#include "multidir/core/search/pose_search.h"
#include "support/small_pose_search.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

using multidir::test::fewPoses;
using multidir::test::upY;

// Small searches, polished as decompose polishes.
SearchOptions smallOptions(int proxyFaces) { return multidir::test::smallSearchOptions(2, proxyFaces); }

// The plain search at the given up and the pose search from it, with the same options.
struct PlainAndPosed {
  Decomposition plain;
  PoseSearchResult posed;

  static PlainAndPosed of(const TriangleMesh& model, const SearchOptions& options) {
    JobContext plainJob, posedJob;
    auto plain = decompose(model, upY(), options, plainJob);
    if (!plain.ok()) throw std::runtime_error(plain.error().describe());
    auto posed = decomposeWithPoseSearch(model, upY(), options, fewPoses(), posedJob);
    if (!posed.ok()) throw std::runtime_error(posed.error().describe());
    return PlainAndPosed{std::move(*plain), std::move(*posed)};
  }

  // The trial of the given up, which the kitten stands in along +Y: the first one.
  const PoseTrial& givenTrial() const {
    const PoseTrial& trial = posed.trials.front();
    if (trial.pose.source != PoseSource::Given) throw std::runtime_error("the given up does not stand");
    return trial;
  }
};

// The kitten (10,000 faces) on its full mesh and on proxies of at most 4,000 faces; and on its full mesh with
// the cheap score's scheme, whose plans the pose search reuses.
struct PoseSearchOfTheGivenUp : ::testing::Test {
  static void SetUpTestSuite() {
    const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
    onFullMesh = new PlainAndPosed(PlainAndPosed::of(kitten, smallOptions(0)));
    onProxy = new PlainAndPosed(PlainAndPosed::of(kitten, smallOptions(4000)));
    SearchOptions greedy = smallOptions(0);
    greedy.scheme = fewPoses().cheapScheme;  // the pose search's cheap plans are then its searches
    greedyOnFullMesh = new PlainAndPosed(PlainAndPosed::of(kitten, greedy));
  }
  static void TearDownTestSuite() {
    delete onFullMesh;
    delete onProxy;
    delete greedyOnFullMesh;
  }
  static PlainAndPosed* onFullMesh;
  static PlainAndPosed* onProxy;
  static PlainAndPosed* greedyOnFullMesh;
};
PlainAndPosed* PoseSearchOfTheGivenUp::onFullMesh = nullptr;
PlainAndPosed* PoseSearchOfTheGivenUp::onProxy = nullptr;
PlainAndPosed* PoseSearchOfTheGivenUp::greedyOnFullMesh = nullptr;

}  // namespace

TEST_F(PoseSearchOfTheGivenUp, IsThePlainSearchsPlan) {
  const PoseTrial& given = onFullMesh->givenTrial();
  EXPECT_TRUE(given.searched);
  EXPECT_EQ(given.jgAfterMm2, onFullMesh->plain.jgAfterMm2);
  EXPECT_EQ(given.regions, static_cast<int>(onFullMesh->plain.regions.size()));
}

TEST_F(PoseSearchOfTheGivenUp, DeliversNoMoreJgThanThePlainSearch) {
  EXPECT_LE(onFullMesh->posed.plan.jgAfterMm2, onFullMesh->plain.jgAfterMm2);
}

TEST_F(PoseSearchOfTheGivenUp, IsThePlainSearchsPlanOnTheProxyThePlainSearchUses) {
  ASSERT_GT(onProxy->plain.statistics.proxyFaces, 0);
  const PoseTrial& given = onProxy->givenTrial();
  EXPECT_TRUE(given.searched);
  EXPECT_EQ(given.jgAfterMm2, onProxy->plain.jgAfterMm2);
  EXPECT_EQ(given.regions, static_cast<int>(onProxy->plain.regions.size()));
}

TEST_F(PoseSearchOfTheGivenUp, OnAProxyDeliversNoMoreJgThanThePlainSearch) {
  ASSERT_GT(onProxy->posed.plan.statistics.proxyFaces, 0);
  EXPECT_LE(onProxy->posed.plan.jgAfterMm2, onProxy->plain.jgAfterMm2);
}

TEST_F(PoseSearchOfTheGivenUp, WithTheCheapScoresSchemeIsThePlainSearchsPolishedPlan) {
  const PoseTrial& given = greedyOnFullMesh->givenTrial();
  EXPECT_TRUE(given.searched);
  EXPECT_EQ(given.jgAfterMm2, greedyOnFullMesh->plain.jgAfterMm2);
  EXPECT_EQ(given.regions, static_cast<int>(greedyOnFullMesh->plain.regions.size()));
}

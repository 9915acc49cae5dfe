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

  static PlainAndPosed of(const TriangleMesh& model, const SearchOptions& options, MachineSpec machine = upY(),
                          const PoseOptions& poses = fewPoses()) {
    JobContext plainJob, posedJob;
    auto plain = decompose(model, machine, options, plainJob);
    if (!plain.ok()) throw std::runtime_error(plain.error().describe());
    auto posed = decomposeWithPoseSearch(model, machine, options, poses, posedJob);
    if (!posed.ok()) throw std::runtime_error(posed.error().describe());
    return PlainAndPosed{std::move(*plain), std::move(*posed)};
  }

  // The trial of the given up: the first one.
  const PoseTrial& givenTrial() const {
    const PoseTrial& trial = posed.trials.front();
    if (trial.pose.source != PoseSource::Given) throw std::runtime_error("the first trial is not the given up");
    return trial;
  }

  // Whether the given up's trial was searched in full and ended with the plain search's J_G and regions.
  ::testing::AssertionResult givenTrialIsThePlainSearchs() const {
    const PoseTrial& given = givenTrial();
    if (!given.searched) return ::testing::AssertionFailure() << "the given up was not searched in full";
    if (given.jgAfterMm2 != plain.jgAfterMm2)
      return ::testing::AssertionFailure() << "J_G " << given.jgAfterMm2 << " against the plain search's "
                                           << plain.jgAfterMm2;
    if (given.regions != static_cast<int>(plain.regions.size()))
      return ::testing::AssertionFailure() << given.regions << " regions against the plain search's "
                                           << plain.regions.size();
    return ::testing::AssertionSuccess();
  }
};

// Each case made on first use (ctest runs each test in a process of its own): the kitten (10,000 faces), which
// stands along +Y, on its full mesh and on proxies of at most 4,000 faces; on its full mesh with the cheap
// score's scheme, whose plans the pose search reuses; and the cheburashka on the apart machine, whose plain search
// is its own.
const TriangleMesh& kitten() {
  static const TriangleMesh mesh = multidir::test::loadSharedModel("kitten.off");
  return mesh;
}
const PlainAndPosed& onFullMesh() {
  static const PlainAndPosed result = PlainAndPosed::of(kitten(), smallOptions(0));
  return result;
}
const PlainAndPosed& onProxy() {
  static const PlainAndPosed result = PlainAndPosed::of(kitten(), smallOptions(4000));
  return result;
}
const PlainAndPosed& greedyOnFullMesh() {
  static const PlainAndPosed result = [] {
    SearchOptions greedy = smallOptions(0);
    greedy.scheme = fewPoses().cheapScheme;  // the pose search's cheap plans are then its searches
    return PlainAndPosed::of(kitten(), greedy);
  }();
  return result;
}
// The cheburashka does not stand along +Y, so every pose is searched in full for the given one to be; there the
// apart machine's own choice (a plan printed apart with fewer parts) differs from its search's best.
const PlainAndPosed& apartOnFullMesh() {
  static const PlainAndPosed result = [] {
    MachineSpec apart = upY();
    apart.kind = MachineKind::Apart;
    return PlainAndPosed::of(multidir::test::loadSharedModel("cheburashka.off"), smallOptions(0), apart,
                             fewPoses(3, 3));
  }();
  return result;
}

}  // namespace

TEST(PoseSearchOfTheGivenUp, IsThePlainSearchsPlan) {
  EXPECT_TRUE(onFullMesh().givenTrialIsThePlainSearchs());
}

TEST(PoseSearchOfTheGivenUp, DeliversNoMoreJgThanThePlainSearch) {
  EXPECT_LE(onFullMesh().posed.plan.jgAfterMm2, onFullMesh().plain.jgAfterMm2);
}

TEST(PoseSearchOfTheGivenUp, IsThePlainSearchsPlanOnTheProxyThePlainSearchUses) {
  ASSERT_GT(onProxy().plain.statistics.proxyFaces, 0);
  EXPECT_TRUE(onProxy().givenTrialIsThePlainSearchs());
}

TEST(PoseSearchOfTheGivenUp, OnAProxyDeliversNoMoreJgThanThePlainSearch) {
  ASSERT_GT(onProxy().posed.plan.statistics.proxyFaces, 0);
  EXPECT_LE(onProxy().posed.plan.jgAfterMm2, onProxy().plain.jgAfterMm2);
}

TEST(PoseSearchOfTheGivenUp, WithTheCheapScoresSchemeIsThePlainSearchsPolishedPlan) {
  EXPECT_TRUE(greedyOnFullMesh().givenTrialIsThePlainSearchs());
}

TEST(PoseSearchOfTheGivenUp, OnTheApartMachineIsTheApartSearchsPlan) {
  EXPECT_TRUE(apartOnFullMesh().givenTrialIsThePlainSearchs());
  EXPECT_LE(apartOnFullMesh().posed.plan.jgAfterMm2, apartOnFullMesh().plain.jgAfterMm2);
}

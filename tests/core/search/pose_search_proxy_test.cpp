// The pose search of a model above the proxy's face count: each pose is searched on the proxy decompose at its
// up uses, and each fully searched pose's plan is cut on the full mesh (docs/search.md, "The pose search").
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "multidir/core/search/plan_from_planes.h"
#include "multidir/core/search/pose_search.h"
#include "support/small_pose_search.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

using multidir::test::fewPoses;
using multidir::test::upY;
using multidir::test::smallSearchOptions;

PoseSearchResult poseSearch(const TriangleMesh& model, const SearchOptions& options) {
  JobContext job;
  auto result = decomposeWithPoseSearch(model, upY(), options, fewPoses(), job);
  if (!result.ok()) throw std::runtime_error(result.error().describe());
  return std::move(result).value();
}

// The kitten (10,000 faces) pose-searched on a proxy of at most 4,000 faces with one and with two threads, and on
// its full mesh.
struct PoseSearchOnAProxy : ::testing::Test {
  static void SetUpTestSuite() {
    kitten = new TriangleMesh(multidir::test::loadSharedModel("kitten.off"));
    onProxy = new PoseSearchResult(poseSearch(*kitten, smallSearchOptions(1, 4000)));
    onProxyTwoThreads = new PoseSearchResult(poseSearch(*kitten, smallSearchOptions(2, 4000)));
    onFullMesh = new PoseSearchResult(poseSearch(*kitten, smallSearchOptions(1, 0)));
  }
  static void TearDownTestSuite() {
    delete kitten;
    delete onProxy;
    delete onProxyTwoThreads;
    delete onFullMesh;
  }
  static TriangleMesh* kitten;
  static PoseSearchResult* onProxy;
  static PoseSearchResult* onProxyTwoThreads;
  static PoseSearchResult* onFullMesh;
};
TriangleMesh* PoseSearchOnAProxy::kitten = nullptr;
PoseSearchResult* PoseSearchOnAProxy::onProxy = nullptr;
PoseSearchResult* PoseSearchOnAProxy::onProxyTwoThreads = nullptr;
PoseSearchResult* PoseSearchOnAProxy::onFullMesh = nullptr;

}  // namespace

TEST_F(PoseSearchOnAProxy, SearchesTheProxyAndTheNotesSaySo) {
  EXPECT_GT(onProxy->plan.statistics.proxyFaces, 0);
  EXPECT_LE(onProxy->plan.statistics.proxyFaces, 4000);
  const std::vector<std::string>& notes = onProxy->plan.statistics.notes;
  ASSERT_FALSE(notes.empty());
  EXPECT_NE(notes.front().find("searched the poses on a proxy"), std::string::npos) << notes.front();
  EXPECT_EQ(onFullMesh->plan.statistics.proxyFaces, 0);
}

TEST_F(PoseSearchOnAProxy, EverySearchedPosesJgIsTheFullMeshs) {
  // The chosen plan's planes cut through the full mesh by the plain evaluator give the same J_G.
  const auto again = planFromClippingPlanes(*kitten, machineForPose(upY(), onProxy->chosen.up), SearchOptions{},
                                            onProxy->plan.clippingPlanes);
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_NEAR(again->jgAfterMm2, onProxy->plan.jgAfterMm2, 1e-6 * std::max(1.0, again->jgAfterMm2));
  EXPECT_EQ(onProxy->trials[onProxy->chosenTrial].jgAfterMm2, onProxy->plan.jgAfterMm2);
  // The given up and as many of the poses that could win as there are full searches were searched; the poses
  // ruled out (their bound, measured on the full mesh, above the given up's J_G) were not.
  int searched = 0, ruledOut = 0;
  for (const PoseTrial& trial : onProxy->trials) {
    searched += trial.searched ? 1 : 0;
    ruledOut += trial.ruledOut ? 1 : 0;
    EXPECT_FALSE(trial.searched && trial.ruledOut);
  }
  EXPECT_TRUE(onProxy->trials.front().searched);
  const int couldWin = static_cast<int>(onProxy->trials.size()) - 1 - ruledOut;
  EXPECT_EQ(searched, 1 + std::min(couldWin, fewPoses().fullSearches - 1));
}

TEST_F(PoseSearchOnAProxy, ChoosesThePoseTheFullMeshsPoseSearchChooses) {
  EXPECT_TRUE(onProxy->chosen.up.isApprox(onFullMesh->chosen.up, 1e-12))
      << "proxy: " << onProxy->chosen.up.transpose() << ", full mesh: " << onFullMesh->chosen.up.transpose();
  // The proxy's plan is a draw of its own (docs/search.md): within a tenth of the full mesh's search.
  EXPECT_LE(onProxy->plan.jgAfterMm2, 1.1 * onFullMesh->plan.jgAfterMm2 + 1.0);
}

TEST_F(PoseSearchOnAProxy, GivesTheSameResultForOneAndTwoThreads) {
  EXPECT_EQ(onProxy->chosenTrial, onProxyTwoThreads->chosenTrial);
  EXPECT_EQ(onProxy->plan.jgAfterMm2, onProxyTwoThreads->plan.jgAfterMm2);
  ASSERT_EQ(onProxy->trials.size(), onProxyTwoThreads->trials.size());
  for (std::size_t i = 0; i < onProxy->trials.size(); ++i) {
    EXPECT_EQ(onProxy->trials[i].cheapJgMm2, onProxyTwoThreads->trials[i].cheapJgMm2) << "trial " << i;
    EXPECT_EQ(onProxy->trials[i].jgAfterMm2, onProxyTwoThreads->trials[i].jgAfterMm2) << "trial " << i;
    EXPECT_EQ(onProxy->trials[i].searched, onProxyTwoThreads->trials[i].searched) << "trial " << i;
    EXPECT_EQ(onProxy->trials[i].ruledOut, onProxyTwoThreads->trials[i].ruledOut) << "trial " << i;
  }
}

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "multidir/core/search/contact_patch.h"
#include "multidir/core/search/decompose.h"
#include "multidir/core/search/pose_search.h"
#include "support/primitives.h"
#include "support/small_pose_search.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

using multidir::test::fewPoses;

SearchOptions smallOptions(int threads = 1) { return multidir::test::smallSearchOptions(threads); }

bool parallel(const Vec3& a, const Vec3& b) { return a.normalized().dot(b.normalized()) > 1 - 1e-9; }

// Whether one of the plan's notes contains `text`.
bool hasNote(const Decomposition& plan, const std::string& text) {
  const std::vector<std::string>& notes = plan.statistics.notes;
  return std::any_of(notes.begin(), notes.end(), [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

}  // namespace

TEST(RestingPoses, OfABoxAreItsSixSidesLargestFirst) {
  const TriangleMesh box = multidir::test::makeBox(Vec3(0, 0, 0), Vec3(10, 20, 30));
  auto poses = restingPoses(box);
  ASSERT_TRUE(poses.ok()) << poses.error().describe();
  ASSERT_EQ(poses->size(), 6u);
  // Resting on a 20 x 30 side (up +-x) first, then 10 x 30 (up +-y), then 10 x 20 (up +-z).
  EXPECT_NEAR((*poses)[0].contactAreaMm2, 600.0, 1e-9);
  EXPECT_NEAR((*poses)[1].contactAreaMm2, 600.0, 1e-9);
  EXPECT_NEAR((*poses)[2].contactAreaMm2, 300.0, 1e-9);
  EXPECT_NEAR((*poses)[4].contactAreaMm2, 200.0, 1e-9);
  EXPECT_NEAR(std::abs((*poses)[0].up.x()), 1.0, 1e-9);
  EXPECT_NEAR(std::abs((*poses)[4].up.z()), 1.0, 1e-9);
  EXPECT_NEAR((*poses)[0].stabilityMarginMm, 10.0, 1e-9);  // centre of a 20 x 30 side: 10 from the long edges
  for (const PoseCandidate& p : *poses) EXPECT_EQ(p.source, PoseSource::Resting);
}

TEST(RestingPoses, OfATBarAreItsSidesBarTopSlantsAndStemButNotTheBarEnds) {
  // Stem 4 wide and 20 tall, bar 30 wide and 4 tall, 10 deep; centre of mass 17.2 above the stem's foot.
  const TriangleMesh tbar = multidir::test::makeTBar(4, 20, 30, 4, 10);
  auto poses = restingPoses(tbar);
  ASSERT_TRUE(poses.ok()) << poses.error().describe();
  // The T's profile (its hull: 460 mm^2) twice, the bar's top (300), the two slants from the stem's foot to
  // the bar's ends, the stem's foot (40). A bar's end (4 x 10, from 20 to 24 high) cannot hold it: the centre
  // of mass projects below it.
  ASSERT_EQ(poses->size(), 6u);
  EXPECT_NEAR(std::abs((*poses)[0].up.y()), 1.0, 1e-9);
  EXPECT_NEAR(std::abs((*poses)[1].up.y()), 1.0, 1e-9);
  EXPECT_NEAR((*poses)[0].contactAreaMm2, 460.0, 1e-6);
  EXPECT_TRUE(parallel((*poses)[2].up, Vec3(0, 0, -1)));
  EXPECT_NEAR((*poses)[2].contactAreaMm2, 300.0, 1e-6);
  EXPECT_TRUE(parallel((*poses)[5].up, Vec3(0, 0, 1)));
  EXPECT_NEAR((*poses)[5].contactAreaMm2, 40.0, 1e-6);
  EXPECT_NEAR((*poses)[5].stabilityMarginMm, 2.0, 1e-6);
  for (const PoseCandidate& p : *poses) EXPECT_LT(std::abs(p.up.x()), 1 - 1e-6) << "resting on a bar's end";
}

TEST(CandidatePoses, StartWithTheGivenUpAndAreBoundedAndDistinct) {
  const TriangleMesh tbar = multidir::test::makeTBar(4, 20, 30, 4, 10);
  auto poses = candidatePoses(tbar, Vec3(0, 0, 2), fewPoses(10, 2));
  ASSERT_TRUE(poses.ok()) << poses.error().describe();
  ASSERT_LE(poses->size(), 10u);
  ASSERT_GE(poses->size(), 4u);
  EXPECT_EQ((*poses)[0].source, PoseSource::Given);
  EXPECT_TRUE(parallel((*poses)[0].up, Vec3::UnitZ()));
  EXPECT_NEAR((*poses)[0].riskyAreaMm2, 2 * 13 * 10, 1e-6);  // the bar's two undersides
  for (std::size_t i = 0; i < poses->size(); ++i)
    for (std::size_t j = i + 1; j < poses->size(); ++j)
      EXPECT_LT((*poses)[i].up.dot((*poses)[j].up), std::cos(4.9 * kPi / 180)) << i << " " << j;
}

TEST(CandidatePoses, GivenUpCarriesItsContactAndMarginAndTheOthersAllStand) {
  // On the end of its bar (up +x) the T tips over: its centre of mass is over the stem, far from that end.
  const TriangleMesh tbar = multidir::test::makeTBar(4, 20, 30, 4, 10);
  auto poses = candidatePoses(tbar, Vec3(1, 0, 0), fewPoses(10, 2));
  ASSERT_TRUE(poses.ok()) << poses.error().describe();
  EXPECT_EQ((*poses)[0].source, PoseSource::Given);
  EXPECT_NEAR((*poses)[0].contactAreaMm2, 40.0, 1e-6);  // the bar's 4 x 10 end
  EXPECT_LT((*poses)[0].stabilityMarginMm, 0.0);
  EXPECT_FALSE((*poses)[0].stands());
  for (std::size_t i = 1; i < poses->size(); ++i) EXPECT_TRUE((*poses)[i].stands()) << i;
}

TEST(CandidatePoses, OfTheBunnyAllStandOnAPatchOfTheirHullAndItsGivenUpTouchesInAPoint) {
  const TriangleMesh bunny = multidir::test::loadSharedModel("bunny.off");
  auto poses = candidatePoses(bunny, Vec3::UnitY(), PoseOptions{});
  ASSERT_TRUE(poses.ok()) << poses.error().describe();
  ASSERT_GE(poses->size(), 4u);
  EXPECT_EQ((*poses)[0].contactAreaMm2, 0.0) << "the bunny as scanned rests on one point of its hull";
  EXPECT_LT((*poses)[0].stabilityMarginMm, 0.0);
  std::vector<Vec3> corners;
  for (const Vec3& v : bunny.vertices) corners.push_back(v);
  auto hull = convexHull(corners);
  ASSERT_TRUE(hull.ok());
  const Vec3 centre = solidCentreOfMass(bunny);
  for (std::size_t i = 1; i < poses->size(); ++i) {
    const PoseCandidate& pose = (*poses)[i];
    EXPECT_TRUE(pose.stands()) << i;
    // The contact reported is the one the bed really touches standing that way up.
    const ContactPatch patch = contactPatch(*hull, pose.up, centre);
    EXPECT_NEAR(patch.areaMm2, pose.contactAreaMm2, 1e-6 * std::max(1.0, pose.contactAreaMm2)) << i;
    EXPECT_NEAR(patch.stabilityMarginMm, pose.stabilityMarginMm, 1e-6) << i;
  }
}

TEST(PoseOptions, OutOfRangeCountsAreRefusedWithTheirRange) {
  PoseOptions options;
  options.poses = 0;
  EXPECT_NE(validate(options).error().message.find("between 1 and 200"), std::string::npos);
  options.poses = 4;
  options.fullSearches = 5;
  EXPECT_FALSE(validate(options).ok());
  options.fullSearches = 4;
  EXPECT_TRUE(validate(options).ok());
}

TEST(MachineForPose, TurnsTheRotaryAxisWithUp) {
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  const MachineSpec posed = machineForPose(machine, Vec3(0, 1, 0));
  EXPECT_TRUE(validate(posed).ok());
  EXPECT_TRUE(parallel(posed.up, Vec3::UnitY()));
  EXPECT_NEAR(posed.rotationAxis.dot(posed.up), 0.0, 1e-12);
  EXPECT_TRUE(parallel(poseRotation(Vec3(1, 0, 0), Vec3::UnitZ()) * Vec3(1, 0, 0), Vec3::UnitZ()));
}

TEST(PoseSearch, IsNeverWorseThanTheGivenUp) {
  // Standing on its stem the T's bar overhangs; lying down it does not.
  const TriangleMesh tbar = multidir::test::makeTBar(4, 20, 30, 4, 10);
  MachineSpec machine;
  machine.up = Vec3::UnitZ();
  JobContext job;
  auto given = decompose(tbar, machine, smallOptions(), job);
  ASSERT_TRUE(given.ok());
  JobContext poseJob;
  auto best = decomposeWithPoseSearch(tbar, machine, smallOptions(), fewPoses(), poseJob);
  ASSERT_TRUE(best.ok()) << best.error().describe();
  EXPECT_LE(best->plan.jgAfterMm2, given->jgAfterMm2 + 1e-6);
  EXPECT_TRUE(best->trials[0].searched);
  EXPECT_NEAR(best->trials[0].jgAfterMm2, given->jgAfterMm2, 1e-6);
  EXPECT_EQ(best->trials[best->chosenTrial].pose.up, best->chosen.up);
  EXPECT_TRUE(parallel(best->rotation * best->chosen.up, machine.up));
  EXPECT_FALSE(best->plan.cancelled);
  EXPECT_DOUBLE_EQ(poseJob.progress(), 1.0);
}

TEST(PoseSearch, ChoosesAPoseWithoutOverhangForABox) {
  // Every pose of a box is risk-free; ties go to fewer regions, then the larger contact.
  const TriangleMesh box = multidir::test::makeBox(Vec3(0, 0, 0), Vec3(10, 20, 30));
  MachineSpec machine;
  JobContext job;
  auto best = decomposeWithPoseSearch(box, machine, smallOptions(), fewPoses(4, 3), job);
  ASSERT_TRUE(best.ok());
  EXPECT_NEAR(best->plan.jgAfterMm2, 0.0, 1e-9);
  EXPECT_EQ(best->plan.regions.size(), 1u);
  EXPECT_NEAR(best->chosen.contactAreaMm2, 600.0, 1e-9);
}

TEST(PoseSearch, TriesTheGivenUpEvenWhereTheModelWouldTipOverAndSaysSoWhileEveryOtherPoseStands) {
  const TriangleMesh tbar = multidir::test::makeTBar(4, 20, 30, 4, 10);
  MachineSpec machine;
  machine.up = Vec3::UnitX();  // on the bar's end
  machine.rotationAxis = Vec3::UnitY();
  JobContext job;
  auto best = decomposeWithPoseSearch(tbar, machine, smallOptions(), fewPoses(), job);
  ASSERT_TRUE(best.ok()) << best.error().describe();
  ASSERT_FALSE(best->trials.empty());
  EXPECT_EQ(best->trials.front().pose.source, PoseSource::Given);
  EXPECT_FALSE(best->trials.front().pose.stands());
  EXPECT_TRUE(best->trials.front().searched) << "the given up gets the full search";
  for (std::size_t i = 1; i < best->trials.size(); ++i) EXPECT_TRUE(best->trials[i].pose.stands()) << "trial " << i;
  EXPECT_TRUE(hasNote(best->plan, "the given up does not stand"));
}

TEST(PoseSearch, GivesTheSameResultForOneAndTwoThreads) {
  const TriangleMesh model = multidir::test::makeHook(10);
  MachineSpec machine;
  JobContext a, b;
  auto one = decomposeWithPoseSearch(model, machine, smallOptions(1), fewPoses(), a);
  auto two = decomposeWithPoseSearch(model, machine, smallOptions(2), fewPoses(), b);
  ASSERT_TRUE(one.ok() && two.ok());
  EXPECT_EQ(one->chosenTrial, two->chosenTrial);
  EXPECT_EQ(one->plan.jgAfterMm2, two->plan.jgAfterMm2);
  ASSERT_EQ(one->trials.size(), two->trials.size());
  for (std::size_t i = 0; i < one->trials.size(); ++i) {
    EXPECT_EQ(one->trials[i].cheapJgMm2, two->trials[i].cheapJgMm2);
    EXPECT_EQ(one->trials[i].jgAfterMm2, two->trials[i].jgAfterMm2);
    EXPECT_EQ(one->trials[i].searched, two->trials[i].searched);
    EXPECT_EQ(one->trials[i].ruledOut, two->trials[i].ruledOut);
  }
}

TEST(PoseSearch, CancelledBeforeStartingSaysSo) {
  MachineSpec machine;
  JobContext job;
  job.cancel();
  auto result = decomposeWithPoseSearch(multidir::test::makeHook(10), machine, smallOptions(), fewPoses(), job);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::Cancelled);
}

TEST(PoseSearch, OnARotaryPlatformAPoseWhoseBoundIsAboveTheGivenUpsPlanIsRuledOut) {
  // Lying on its side (the given up, +y) the T has no overhang. Standing on its stem, the bar's underside faces
  // straight down, risky for every direction a platform turning by at most 5 degrees prints along: that pose's
  // bound is above the given up's J_G of 0, so it is neither scored nor searched.
  const TriangleMesh tbar = multidir::test::makeTBar(4, 20, 30, 4, 10);
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitY();
  machine.rotationAxis = Vec3::UnitX();
  machine.minAngleDegrees = -5;
  machine.maxAngleDegrees = 5;
  JobContext job;
  auto best = decomposeWithPoseSearch(tbar, machine, smallOptions(1), fewPoses(6, 6), job);
  ASSERT_TRUE(best.ok()) << best.error().describe();
  EXPECT_NEAR(best->plan.jgAfterMm2, 0.0, 1e-9);
  bool stemPoseTried = false;
  for (const PoseTrial& trial : best->trials)
    if (parallel(trial.pose.up, Vec3::UnitZ())) {
      stemPoseTried = true;
      EXPECT_FALSE(trial.searched);
      EXPECT_TRUE(trial.ruledOut);
    }
  EXPECT_TRUE(stemPoseTried);
  EXPECT_TRUE(hasNote(best->plan, "neither scored nor searched"));
}

TEST(PoseSearch, OnATiltingPlatformAPoseWhoseBoundIsAboveTheGivenUpsPlanIsRuledOutUnscored) {
  // Standing on its base (+y) the kitten's plan keeps 11.71 mm^2 of risky area. On each of its other patches
  // so much of its overhang lies against the platform region that no tilt saves it (731 mm^2 or more): those
  // poses could not win and are neither scored nor searched; the result is the given up's plan, as decompose
  // gives it.
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  MachineSpec machine;
  machine.up = Vec3::UnitY();
  const SearchOptions options;
  JobContext job, poseJob;
  const auto given = decompose(kitten, machine, options, job);
  ASSERT_TRUE(given.ok()) << given.error().describe();
  const auto best = decomposeWithPoseSearch(kitten, machine, options, PoseOptions{}, poseJob);
  ASSERT_TRUE(best.ok()) << best.error().describe();
  EXPECT_EQ(best->chosenTrial, 0);
  EXPECT_EQ(best->plan.jgAfterMm2, given->jgAfterMm2);
  ASSERT_EQ(best->trials.size(), 5u);
  for (std::size_t i = 1; i < best->trials.size(); ++i) {
    const PoseTrial& trial = best->trials[i];
    EXPECT_TRUE(trial.ruledOut) << "trial " << i;
    EXPECT_GT(trial.unavoidableMm2, given->jgAfterMm2) << "trial " << i;
    EXPECT_FALSE(trial.searched) << "trial " << i;
    EXPECT_EQ(trial.regions, 0) << "trial " << i << ": no plan, not even a cheap one";
  }
  EXPECT_TRUE(hasNote(best->plan, "4 poses neither scored nor searched"));
}

TEST(PoseSearch, GivesItsFullSearchesToTheBestScoredOfThePosesThatCouldWin) {
  // Along +y the screwdriver's plan keeps 8.88 mm^2; most of its resting poses keep far more than that against
  // the platform region whatever the tilt. A pose ruled out so takes no full search from one that could win:
  // the full searches go to the given up and the best cheap scores among the poses not ruled out.
  const TriangleMesh screwdriver = multidir::test::loadSharedModel("screwdriver.off");
  MachineSpec machine;
  machine.up = Vec3::UnitY();
  PoseOptions poseOptions;
  poseOptions.fullSearches = 3;
  JobContext job;
  const auto best = decomposeWithPoseSearch(screwdriver, machine, SearchOptions{}, poseOptions, job);
  ASSERT_TRUE(best.ok()) << best.error().describe();
  const std::vector<PoseTrial>& trials = best->trials;
  EXPECT_TRUE(trials.front().searched);
  std::vector<const PoseTrial*> couldWin;
  int ruledOut = 0;
  for (std::size_t i = 1; i < trials.size(); ++i) {
    if (trials[i].ruledOut) {
      ++ruledOut;
      EXPECT_GT(trials[i].unavoidableMm2, trials.front().jgAfterMm2) << "trial " << i;
    } else {
      EXPECT_GT(trials[i].regions, 0) << "trial " << i << " could win and was scored";
      couldWin.push_back(&trials[i]);
    }
  }
  ASSERT_GT(ruledOut, 0);
  ASSERT_GE(couldWin.size(), 3u) << "more poses could win than there are full searches left for them";
  int searched = 0;
  double worstSearchedScore = 0.0, bestUnsearchedScore = INFINITY;
  for (const PoseTrial* trial : couldWin) {
    if (trial->searched)
      ++searched, worstSearchedScore = std::max(worstSearchedScore, trial->cheapJgMm2);
    else
      bestUnsearchedScore = std::min(bestUnsearchedScore, trial->cheapJgMm2);
  }
  EXPECT_EQ(searched, poseOptions.fullSearches - 1);
  EXPECT_LE(worstSearchedScore, bestUnsearchedScore);
  EXPECT_TRUE(hasNote(best->plan, std::to_string(ruledOut) + " poses neither scored nor searched"));
}

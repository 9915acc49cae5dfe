#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "multidir/core/search/decompose.h"
#include "multidir/core/search/plan_from_planes.h"
#include "support/primitives.h"
#include "support/same_planes.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

MachineSpec rotaryUpY() {
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitY();
  machine.rotationAxis = platformFrameX(machine.up);
  return machine;
}

// Twelve axes: more than the second stage searches in full, so both stages run.
Decomposition axisSearch(int threads) {
  SearchOptions options;
  options.threads = threads;
  JobContext job;
  auto plan = decomposeWithAxisSearch(multidir::test::loadSharedModel("bumpy.off"), rotaryUpY(), options, 12, job);
  if (!plan.ok()) throw std::runtime_error(plan.error().describe());
  return std::move(plan).value();
}

}  // namespace

TEST(AxisSearch, OneAndTwoThreadsChooseTheSameAxisAndPlan) {
  const Decomposition one = axisSearch(1), two = axisSearch(2);
  EXPECT_EQ(one.rotationAxis, two.rotationAxis);
  EXPECT_EQ(one.jgAfterMm2, two.jgAfterMm2);
  EXPECT_TRUE(multidir::test::samePlanes(one, two));
}

TEST(AxisSearch, IsNeverWorseThanTheFullSearchOnTheGivenAxis) {
  JobContext job;
  const auto given = decompose(multidir::test::loadSharedModel("bumpy.off"), rotaryUpY(), SearchOptions{}, job);
  ASSERT_TRUE(given.ok());
  EXPECT_LE(axisSearch(0).jgAfterMm2, given->jgAfterMm2 + 1e-9);
}

namespace {

// An arm reaching out from a stem, its underside rising by 28 degrees towards its end (x), 10 mm deep (y): risky
// along up (+Z), and printable without risk along up turned 20 degrees towards +x, about the y axis (28 + 20 >
// 45 degrees); about an axis 45 degrees or less from x no turn within 20 degrees saves it.
TriangleMesh slantedArm() {
  const double rise = 20.0 * std::tan(28.0 * kPi / 180.0);
  return multidir::test::makeExtrudedProfile(
      {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(10, 0, 20), Vec3(30, 0, 20 + rise), Vec3(30, 0, 40), Vec3(0, 0, 40)},
      10.0);
}

}  // namespace

TEST(AxisSearch, AnAxisThatCannotBeatTheBestPlanByItsBoundIsNotSearchedInFull) {
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitZ();
  machine.rotationAxis = Vec3::UnitX();
  machine.minAngleDegrees = -20.0;
  machine.maxAngleDegrees = 20.0;
  SearchOptions options;
  options.threads = 1;  // axes in order: y (axis 2 of 4) comes before 135 degrees (axis 3)
  options.polish = false;
  JobContext job;
  // As many axes as the second stage searches in full: every axis is searched in full unless the bound skips it.
  const auto plan = decomposeWithAxisSearch(slantedArm(), machine, options, 4, job);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  EXPECT_LT(plan->jgAfterMm2, 1.0);  // printed along a turn about an axis near y
  bool skipped = false;
  for (const std::string& note : plan->statistics.notes)
    skipped = skipped || note.find("not searched in full") != std::string::npos;
  EXPECT_TRUE(skipped);
}

TEST(AxisSearch, AnAxisWhoseOverhangsOnlyAPlaneThroughThePlatformRegionCouldSaveIsNotSearchedInFull) {
  // A T on a 5 mm stem, its bar along x: about y the platform turns each half of the bar's underside into a
  // region above a plane that clears the platform region; about x no such plane reaches them (Criterion III),
  // though a 60-degree turn would save their normal. So the x axis's bound is their 300 mm^2, above y's plan.
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitZ();
  machine.rotationAxis = Vec3::UnitY();
  SearchOptions options;
  options.threads = 1;  // axes in order: y (axis 0) before x (axis 2 of 4)
  options.polish = false;
  JobContext job;
  // As many axes as the second stage searches in full: every axis is searched in full unless the bound skips it.
  const auto plan = decomposeWithAxisSearch(multidir::test::makeTBar(10.0, 5.0, 40.0, 5.0, 10.0), machine, options, 4, job);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  EXPECT_LT(plan->jgAfterMm2, 300.0);
  bool skipped = false;
  for (const std::string& note : plan->statistics.notes)
    skipped = skipped || note.find("not searched in full") != std::string::npos;
  EXPECT_TRUE(skipped);
}

TEST(AxisSearch, ScreenedOnACopyFindsTheBestAxisOfTheFullSearchOnEveryAxisOfTheKitten) {
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  MachineSpec machine = rotaryUpY();
  SearchOptions options;
  options.polish = false;
  options.volumeScales = 1;  // a smaller search: the test is about the choice of axes, not the search on one
  options.beamWidth = 4;
  constexpr int kAxes = 12;  // more than the second stage searches in full: both stages run
  JobContext job;
  const auto screened = decomposeWithAxisSearch(kitten, machine, options, kAxes, job);
  ASSERT_TRUE(screened.ok()) << screened.error().describe();
  bool onACopy = false;
  for (const std::string& note : screened->statistics.notes)
    onACopy = onACopy || note.find("screened 12 axes on a copy") != std::string::npos;
  EXPECT_TRUE(onACopy);
  // Every axis searched in full, the axes as the axis search spreads them.
  const Vec3 first = machine.rotationAxis, second = machine.up.cross(first);
  double bestJg = INFINITY;
  for (int a = 0; a < kAxes; ++a) {
    const double angle = kPi * a / kAxes;
    MachineSpec spec = machine;
    spec.rotationAxis = (std::cos(angle) * first + std::sin(angle) * second).normalized();
    const auto plan = decompose(kitten, spec, options, job);
    ASSERT_TRUE(plan.ok());
    bestJg = std::min(bestJg, plan->jgAfterMm2);
  }
  EXPECT_LE(screened->jgAfterMm2, bestJg + 1e-9);
}

TEST(AxisSearch, CancelledAfterTheFirstAxisReportsNoOtherAxisAndSaysSo) {
  SearchOptions options;
  options.threads = 2;
  JobContext job;
  int axesReported = 0;
  int reportedAfterCancel = 0;
  const auto plan = decomposeWithAxisSearch(multidir::test::loadSharedModel("bumpy.off"), rotaryUpY(), options, 12, job,
                                            [&](const SearchProgress& p) {
                                              if (p.axisIndex < 0) return;
                                              if (job.isCancelled()) ++reportedAfterCancel;
                                              ++axesReported;
                                              job.cancel();
                                            });
  // The axis the other thread is on stops part-way; a partial search is no result for its axis.
  EXPECT_EQ(axesReported, 1);
  EXPECT_EQ(reportedAfterCancel, 0);
  if (plan.ok())
    EXPECT_TRUE(plan->cancelled);
  else
    EXPECT_EQ(plan.error().code, ErrorCode::Cancelled);
}

TEST(AxisSearch, ScreenedOnACopyOneAndTwoThreadsChooseTheSameAxisAndPlan) {
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");  // above 5,000 faces: a copy screens
  auto search = [&](int threads) {
    SearchOptions options;
    options.threads = threads;
    options.volumeScales = 1;  // a smaller search: the test is about the order of the work, not the plan's quality
    options.beamWidth = 4;
    JobContext job;
    auto plan = decomposeWithAxisSearch(kitten, rotaryUpY(), options, 12, job);
    if (!plan.ok()) throw std::runtime_error(plan.error().describe());
    return std::move(plan).value();
  };
  const Decomposition one = search(1), two = search(2);
  EXPECT_EQ(one.rotationAxis, two.rotationAxis);
  EXPECT_EQ(one.jgAfterMm2, two.jgAfterMm2);
  EXPECT_TRUE(multidir::test::samePlanes(one, two));
}

TEST(AxisSearch, CancelledWhileScreeningOnACopyDeliversTheBestScreensPlanesCutOnTheModel) {
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");  // above 5,000 faces: a copy screens
  SearchOptions options;
  options.threads = 2;
  JobContext job;
  const auto plan = decomposeWithAxisSearch(kitten, rotaryUpY(), options, 12, job, [&](const SearchProgress& p) {
    if (p.axisIndex >= 0) job.cancel();
  });
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  EXPECT_TRUE(plan->cancelled);
  ASSERT_FALSE(plan->regions.empty());
  // A plan of the model: its planes cut the kitten itself to the same J_G.
  MachineSpec machine = rotaryUpY();
  machine.rotationAxis = plan->rotationAxis;
  const auto again = planFromClippingPlanes(kitten, machine, options, plan->clippingPlanes);
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_NEAR(again->jgAfterMm2, plan->jgAfterMm2, 1e-6);
}

// The bound on J_G: the risky area no direction the machine prints along can save (4-DOF: one axis's range;
// 5-DOF: every tilt within the limit). It must never exceed the J_G of a plan on that machine (or the axis and
// pose searches would skip a winner), and it must see what it claims to.
#include <gtest/gtest.h>

#include <cmath>

#include "multidir/core/search/decompose.h"
#include "multidir/core/search/pose_search.h"
#include "search/unavoidable_risky_area.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

// The bound with the platform region the search uses for `mesh` (its footprint plus the margin).
double unavoidableRiskyAreaMm2(const TriangleMesh& mesh, const MachineSpec& machine, double alphaMaxDegrees,
                               double supportedBandMm) {
  return multidir::core::detail::unavoidableRiskyAreaMm2(mesh, machine, platformRegionFor(mesh, machine),
                                                         alphaMaxDegrees, supportedBandMm);
}

MachineSpec rotaryUpZ(const Vec3& axis, double rangeDegrees) {
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitZ();
  machine.rotationAxis = axis;
  machine.minAngleDegrees = -rangeDegrees;
  machine.maxAngleDegrees = rangeDegrees;
  return machine;
}

MachineSpec tiltingUpZ(double maxTiltDegrees) {
  MachineSpec machine;
  machine.kind = MachineKind::TiltRotate;
  machine.up = Vec3::UnitZ();
  machine.maxTiltDegrees = maxTiltDegrees;
  return machine;
}

// A T on its stem, bar 40 x 10, stem 10 wide, 10 deep: the bar's undersides (2 x 15 x 10 = 300 mm^2) face
// straight down, 20 mm above the bed.
TriangleMesh tBar() { return multidir::test::makeTBar(10.0, 20.0, 40.0, 5.0, 10.0); }

// The same T on a stem of 5 mm: the bar's undersides 5 mm above the bed, over the platform region (the stem's
// footprint, 10 x 10, plus 5 mm: a disc of radius 12.07 mm).
TriangleMesh lowTBar() { return multidir::test::makeTBar(10.0, 5.0, 40.0, 5.0, 10.0); }

}  // namespace

TEST(UnavoidableRiskyArea, IsTheDownFacingAreaWhenNoTurnWithinTheRangeReachesAlphaMax) {
  // Turned by at most 30 degrees, a face looking straight down still faces down by 60 > 45 degrees.
  EXPECT_NEAR(unavoidableRiskyAreaMm2(tBar(), rotaryUpZ(Vec3::UnitX(), 30.0), 45.0, 1.0), 300.0, 1e-9);
  EXPECT_NEAR(unavoidableRiskyAreaMm2(tBar(), rotaryUpZ(Vec3::UnitY(), 30.0), 45.0, 1.0), 300.0, 1e-9);
}

TEST(UnavoidableRiskyArea, IsZeroWhenSomeTurnWithinTheRangeSavesEveryFace) {
  // Turned by 50 degrees, a face looking straight down faces down by 40 < 45 degrees.
  EXPECT_EQ(unavoidableRiskyAreaMm2(tBar(), rotaryUpZ(Vec3::UnitX(), 50.0), 45.0, 1.0), 0.0);
}

TEST(UnavoidableRiskyArea, LeavesOutFacesWithinTheBedsBand) {
  // The box's bottom looks straight down, but lies on the bed.
  const TriangleMesh box = multidir::test::makeBox(Vec3(0, 0, 0), Vec3(10, 10, 10));
  EXPECT_EQ(unavoidableRiskyAreaMm2(box, rotaryUpZ(Vec3::UnitX(), 10.0), 45.0, 1.0), 0.0);
}

TEST(UnavoidableRiskyArea, NeverExceedsTheJgOfTheKittensPlanOnANarrowRange) {
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitY();
  machine.rotationAxis = platformFrameX(machine.up);
  machine.minAngleDegrees = -20.0;
  machine.maxAngleDegrees = 20.0;
  SearchOptions options;
  options.polish = false;
  JobContext job;
  const auto plan = decompose(kitten, machine, options, job);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  const double bound = unavoidableRiskyAreaMm2(kitten, machine, options.alphaMaxDegrees, options.supportedBandMm);
  EXPECT_GT(bound, 0.0);  // the narrow range leaves some of the kitten's overhang unavoidable
  EXPECT_LE(bound, plan->jgAfterMm2);
}

TEST(UnavoidableRiskyArea, CountsTheFacesThatOnlyAPlaneThroughThePlatformRegionCouldCutOff) {
  // About x the platform turns the bar's undersides (normal -z) by up to 60 degrees, enough for alpha_max, but a
  // region printed so lies above a plane tilted by 45 to 60 degrees about x that clears the platform region:
  // the undersides, 5 mm above the bed and at most 5 mm from the stem's middle across the turn, lie below
  // every such plane (Criterion III).
  EXPECT_NEAR(unavoidableRiskyAreaMm2(lowTBar(), rotaryUpZ(Vec3::UnitX(), 60.0), 45.0, 1.0), 300.0, 1e-9);
}

TEST(UnavoidableRiskyArea, IsZeroWhenATurnTowardsTheOverhangsLiftsThemAboveThePlatformRegion) {
  // About y the same turn tilts each plane along the bar: its far end (up to 20 mm out) lies above a plane that
  // clears the platform region, so a region can hold it.
  EXPECT_EQ(unavoidableRiskyAreaMm2(lowTBar(), rotaryUpZ(Vec3::UnitY(), 60.0), 45.0, 1.0), 0.0);
}

TEST(UnavoidableRiskyArea, NeverExceedsTheJgOfTheBunnysPlansOnTheDefaultRange) {
  // At plus and minus 60 degrees a turn saves every face's normal; what stays is what the platform region keeps
  // out of every region that would save it: the bunny's underside near the point it stands on.
  const TriangleMesh bunny = multidir::test::loadSharedModel("bunny.off");
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitY();
  SearchOptions options;
  options.polish = false;
  for (const Vec3& axis : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitZ())}) {
    machine.rotationAxis = axis;
    JobContext job;
    const auto plan = decompose(bunny, machine, options, job);
    ASSERT_TRUE(plan.ok()) << plan.error().describe();
    const double bound = unavoidableRiskyAreaMm2(bunny, machine, options.alphaMaxDegrees, options.supportedBandMm);
    EXPECT_GT(bound, 0.0) << "axis " << axis.transpose();
    EXPECT_LE(bound, plan->jgAfterMm2) << "axis " << axis.transpose();
  }
}

TEST(UnavoidableRiskyArea, OnATiltingPlatformIsTheDownFacingAreaWhenTheTiltLimitStopsShortOfAlphaMax) {
  // Tilted by at most 30 degrees in any direction, a face looking straight down still faces down by 60 > 45.
  EXPECT_NEAR(unavoidableRiskyAreaMm2(tBar(), tiltingUpZ(30.0), 45.0, 1.0), 300.0, 1e-9);
}

TEST(UnavoidableRiskyArea, OnATiltingPlatformIsZeroWhenSomeTiltSavesEveryFace) {
  EXPECT_EQ(unavoidableRiskyAreaMm2(tBar(), tiltingUpZ(90.0), 45.0, 1.0), 0.0);
  // The low T's bar reaches 20 mm out: tilted towards an end, a plane that clears the platform region passes
  // below that end (the 4-DOF machine turning about y does the same).
  EXPECT_EQ(unavoidableRiskyAreaMm2(lowTBar(), tiltingUpZ(90.0), 45.0, 1.0), 0.0);
}

TEST(UnavoidableRiskyArea, OnATiltingPlatformCountsTheOverhangsNoTiltLiftsAboveThePlatformRegion) {
  // A stub of a T: bar 14 wide on a 10 x 10 stem 1.5 mm high. Its undersides (2 x 2 x 10 = 40 mm^2) lie 1.5 mm
  // above the bed and at most 8.6 mm from the stem's axis, inside the platform region (a disc of radius
  // 12.07 mm on the bed). Along a direction tilted by t towards any side, a point r from the axis at height h
  // lies at h cos t + r sin t, the region's top at 12.07 sin t: the underside is below it for every t above
  // 23 degrees, and alpha_max needs t >= 45. No tilt saves it.
  const TriangleMesh stub = multidir::test::makeTBar(10.0, 1.5, 14.0, 5.0, 10.0);
  EXPECT_NEAR(unavoidableRiskyAreaMm2(stub, tiltingUpZ(90.0), 45.0, 1.0), 40.0, 1e-9);
}

TEST(UnavoidableRiskyArea, OnATiltingPlatformNeverExceedsTheJgOfTheKittensPlansInItsStandingPoses) {
  // Lying on any of its four resting patches the kitten keeps much of its overhang against the platform region;
  // the bound must see a good part of it and stay below what the plain search (polished) delivers there.
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  MachineSpec base;
  base.kind = MachineKind::TiltRotate;
  base.up = Vec3::UnitY();
  SearchOptions options;
  const auto poses = candidatePoses(kitten, base.up, PoseOptions{}, options);
  ASSERT_TRUE(poses.ok()) << poses.error().describe();
  int resting = 0;
  for (const PoseCandidate& pose : *poses) {
    if (pose.source != PoseSource::Resting) continue;
    ++resting;
    const MachineSpec machine = machineForPose(base, pose.up);
    JobContext job;
    const auto plan = decompose(kitten, machine, options, job);
    ASSERT_TRUE(plan.ok()) << plan.error().describe();
    const double bound = unavoidableRiskyAreaMm2(kitten, machine, options.alphaMaxDegrees, options.supportedBandMm);
    EXPECT_GT(bound, 0.2 * pose.riskyAreaMm2) << "up " << pose.up.transpose();
    EXPECT_LE(bound, plan->jgAfterMm2) << "up " << pose.up.transpose();
  }
  EXPECT_EQ(resting, 4);
}

TEST(UnavoidableRiskyArea, AskedWhetherItIsAboveAnAreaStopsOnceItIsAndIsWholeBelowIt) {
  // The pose search asks only whether a pose's bound is above the given up's J_G: the sum stops there (largest
  // faces first), above the area asked about and within the whole bound; asked about more than the whole, it is
  // the whole (summed in another order, so to rounding).
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  MachineSpec base;
  base.kind = MachineKind::TiltRotate;
  base.up = Vec3::UnitY();
  const SearchOptions options;
  const auto poses = candidatePoses(kitten, base.up, PoseOptions{}, options);
  ASSERT_TRUE(poses.ok()) << poses.error().describe();
  ASSERT_GE(poses->size(), 2u);
  const MachineSpec machine = machineForPose(base, (*poses)[1].up);
  const PlatformRegion platform = platformRegionFor(kitten, machine);
  const auto bound = [&](double stopAbove) {
    return detail::unavoidableRiskyAreaMm2(kitten, machine, platform, options.alphaMaxDegrees,
                                           options.supportedBandMm, stopAbove);
  };
  const double whole = bound(INFINITY);
  ASSERT_GT(whole, 100.0);
  const double partial = bound(11.71);
  EXPECT_GT(partial, 11.71);
  EXPECT_LT(partial, 0.5 * whole) << "it went on summing past the area asked about";
  EXPECT_NEAR(bound(whole + 1.0), whole, 1e-9 * whole);
}

// The lift height while the platform turns covers the part's swept volume.
#include "multidir/slicing/clearance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "multidir/slicing/slice_job.h"
#include "support/primitives.h"

using namespace multidir;
using core::Vec3;

namespace {

// Highest z of `points` over the turn, sampled every 0.01 degree.
double sampledTop(const std::vector<Vec3>& points, const Vec3& axis, double turnRadians) {
  double top = -1e300;
  const int samples = 20000;
  for (int i = 0; i <= samples; ++i) {
    const Eigen::AngleAxisd r(turnRadians * i / samples, axis);
    for (const Vec3& p : points) top = std::max(top, (r * p).z());
  }
  return top;
}

}  // namespace

TEST(Clearance, SweptTopIsTheExactMaximumOverTheArc) {
  const std::vector<Vec3> points = {{0, 5, 100}, {0, -5, 100}, {3, 40, 10}};
  for (double degrees : {-90.0, -30.0, 10.0, 60.0, 200.0}) {
    const double turn = degrees * M_PI / 180.0;
    const double exact = slicing::sweptTopZ(points, Vec3::UnitX(), turn);
    EXPECT_GE(exact, sampledTop(points, Vec3::UnitX(), turn) - 1e-9) << degrees;
    EXPECT_NEAR(exact, sampledTop(points, Vec3::UnitX(), turn), 1e-3) << degrees;
  }
}

TEST(Clearance, TallRegionTurningLiftsTheNozzleAboveItsSweptCorner) {
  // A 10 x 10 x 100 mm column on the platform, printed first; the second step turns the platform by 60
  // degrees about X through the column's foot. Its top corners swing through the vertical on one side, so
  // the part rises to sqrt(100^2 + 5^2), above its height at rest.
  core::PrintJob job;
  job.machine.kind = core::MachineKind::RotaryPlatform;
  job.machine.up = Vec3::UnitZ();
  job.machine.rotationAxis = Vec3::UnitX();
  core::PrintJobStep first;
  first.index = 1;
  first.region = test::makeBox(Vec3(-5, -5, 0), Vec3(5, 5, 100));
  core::PrintJobStep second;
  second.index = 2;
  second.angles.rotaryDegrees = 60.0;
  second.modelToFile = Eigen::Isometry3d(Eigen::AngleAxisd(-60.0 * M_PI / 180.0, Vec3::UnitX()));
  second.region = test::makeBox(Vec3(-5, -5, 100), Vec3(5, 5, 110));
  job.steps = {first, second};

  slicing::PrinterProfile profile;
  profile.clearanceMarginMm = 5.0;
  profile.platformZMm = 2.0;
  const auto turns = slicing::planTurns(job, profile);
  ASSERT_TRUE(turns.ok()) << turns.error().describe();
  ASSERT_EQ(turns->size(), 1u);
  const slicing::TurnPlan& turn = turns->front();
  const double corner = std::hypot(100.0, 5.0);
  EXPECT_NEAR(turn.sweptTopZMm, corner + 2.0, 1e-6);
  EXPECT_NEAR(turn.clearanceZMm, corner + 2.0 + 5.0, 1e-6);
  EXPECT_GT(turn.clearanceZMm, 100.0 + 2.0 + 5.0);  // more than the column's height at rest plus the margin
  EXPECT_DOUBLE_EQ(turn.toDegrees, 60.0);
}

TEST(Clearance, PosesThatAreNotATurnAboutTheAxisAreRefused) {
  core::PrintJob job;
  job.machine.kind = core::MachineKind::RotaryPlatform;
  job.machine.rotationAxis = Vec3::UnitX();
  core::PrintJobStep first;
  first.region = test::makeBox(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  core::PrintJobStep second = first;
  second.index = 2;
  second.angles.rotaryDegrees = 30.0;  // but its pose is the identity
  job.steps = {first, second};
  const auto turns = slicing::planTurns(job, slicing::PrinterProfile{});
  ASSERT_FALSE(turns.ok());
  EXPECT_EQ(turns.error().code, core::ErrorCode::Internal);
}

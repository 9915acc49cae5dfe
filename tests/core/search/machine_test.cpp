#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "multidir/core/common/units.h"
#include "multidir/core/search/candidate_planes.h"
#include "multidir/core/search/machine.h"
#include "support/primitives.h"

using namespace multidir::core;

namespace {

MachineSpec rotary() {
  MachineSpec spec;
  spec.kind = MachineKind::RotaryPlatform;
  spec.rotationAxis = Vec3::UnitX();
  spec.angleStepDegrees = 1.0;
  return spec;
}

}  // namespace

TEST(Machine, DefaultSpecsOfEveryKindAreValid) {
  for (MachineKind kind : {MachineKind::ThreeAxis, MachineKind::RotaryPlatform, MachineKind::TiltRotate}) {
    MachineSpec spec;
    spec.kind = kind;
    EXPECT_TRUE(validate(spec).ok()) << machineKindName(kind);
  }
}

TEST(Machine, RotaryAxisOutOfThePlatformPlaneIsRefused) {
  MachineSpec spec = rotary();
  spec.rotationAxis = Vec3(0, 1, 1).normalized();
  const Status status = validate(spec);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().where, "rotation axis");
}

TEST(Machine, RotaryRealizesOnlyWholeStepsWithinTheRange) {
  const MachineSpec spec = rotary();
  EXPECT_TRUE(isRealizable(spec, rotaryDirection(spec, 30.0)));
  EXPECT_TRUE(isRealizable(spec, rotaryDirection(spec, -60.0)));
  EXPECT_FALSE(isRealizable(spec, rotaryDirection(spec, 30.5)));
  EXPECT_FALSE(isRealizable(spec, rotaryDirection(spec, 61.0)));
  EXPECT_FALSE(isRealizable(spec, Vec3(1, 0, 1).normalized()));  // not perpendicular to the axis
}

TEST(Machine, RotaryAngleOfADirectionIsTheAngleThatProducedIt) {
  const MachineSpec spec = rotary();
  for (double angle : {-45.0, -1.0, 0.0, 17.0, 60.0})
    EXPECT_NEAR(machineAnglesFor(spec, rotaryDirection(spec, angle)).rotaryDegrees, angle, 1e-9);
}

TEST(Machine, TiltLimitAndForbiddenConesBoundFiveAxisDirections) {
  MachineSpec spec;
  spec.maxTiltDegrees = 60.0;
  spec.forbiddenCones.push_back({Vec3(1, 0, 1).normalized(), 10.0});
  EXPECT_TRUE(isRealizable(spec, Vec3(0, 1, 1).normalized()));
  EXPECT_FALSE(isRealizable(spec, Vec3(1, 0, 1).normalized()));  // inside the cone
  EXPECT_FALSE(isRealizable(spec, Vec3(0, 1, 0.2).normalized()));  // tilted 79 degrees
  const MachineAngles angles = machineAnglesFor(spec, Vec3(0, 1, 1).normalized());
  EXPECT_NEAR(angles.tiltDegrees, 45.0, 1e-9);
  EXPECT_NEAR(angles.azimuthDegrees, 90.0, 1e-9);
}

TEST(Machine, UnknownKindNameIsRefusedWithTheChoices) {
  const auto kind = parseMachineKind("6dof");
  ASSERT_FALSE(kind.ok());
  EXPECT_NE(kind.error().message.find("5dof"), std::string::npos);
}

TEST(Machine, DefaultPlatformRegionCoversTheFootprintPlusMargin) {
  const TriangleMesh box = multidir::test::makeBox(Vec3(0, 0, 0), Vec3(20, 20, 10));
  const PlatformRegion region = platformRegionFor(box, MachineSpec{});
  EXPECT_TRUE(region.center.isApprox(Vec3(10, 10, 0)));
  EXPECT_NEAR(region.radiusMm, std::sqrt(200.0) + 5.0, 1e-9);
  EXPECT_DOUBLE_EQ(region.heightMm, 0.0);
}

TEST(CandidatePlanes, FibonacciSphereIsUnitAndBalanced) {
  const auto points = fibonacciSphere(250);
  ASSERT_EQ(points.size(), 250u);
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : points) {
    EXPECT_NEAR(p.norm(), 1.0, 1e-12);
    sum += p;
  }
  EXPECT_LT(sum.norm(), 1.0);
}

TEST(CandidatePlanes, FiveAxisNormalsStayWithinTheTiltLimit) {
  MachineSpec spec;
  spec.maxTiltDegrees = 90.0;
  const auto normals = candidateNormals(spec, CandidateOptions{});
  EXPECT_GT(normals.size(), 110u);
  EXPECT_LT(normals.size(), 140u);
  for (const Vec3& n : normals) EXPECT_GE(n.dot(spec.up), -1e-12);
}

TEST(CandidatePlanes, RotaryNormalsArePerpendicularToTheAxisAndRealizable) {
  const MachineSpec spec = rotary();
  CandidateOptions options;
  options.rotarySpacingDegrees = 1.0;
  const auto normals = candidateNormals(spec, options);
  EXPECT_EQ(normals.size(), 120u);  // -60..60 in 1 degree steps, 0 left out
  for (const Vec3& n : normals) {
    EXPECT_NEAR(n.dot(spec.rotationAxis), 0.0, 1e-12);
    EXPECT_TRUE(isRealizable(spec, n));
  }
}

TEST(CandidatePlanes, RotarySpacingKeepsWholeMultiplesOfTheStep) {
  MachineSpec spec = rotary();
  spec.angleStepDegrees = 1.8;  // a 200-step motor
  CandidateOptions options;
  options.rotarySpacingDegrees = 5.0;  // rounds to 3 steps: 5.4 degrees
  const auto normals = candidateNormals(spec, options);
  ASSERT_FALSE(normals.empty());
  for (const Vec3& n : normals) {
    EXPECT_TRUE(isRealizable(spec, n));
    const double steps = (machineAnglesFor(spec, n).rotaryDegrees - spec.minAngleDegrees) / 5.4;
    EXPECT_NEAR(steps, std::round(steps), 1e-9);
  }
}

TEST(CandidatePlanes, NoOffsetCutsThePlatformRegion) {
  const TriangleMesh box = multidir::test::makeBox(Vec3(0, 0, 0), Vec3(40, 40, 40));
  MachineSpec spec;
  const PlatformRegion platform = platformRegionFor(box, spec);
  CandidateOptions options;
  for (const Vec3& n : candidateNormals(spec, options)) {
    const OffsetGrid grid = candidateOffsets(box, n, platform, spec.up, options);
    if (grid.count == 0) continue;
    // The highest point of P's rim along n must lie below the first plane.
    const Vec3 inPlane = n - n.dot(spec.up) * spec.up;
    const double platformTop = n.dot(platform.center) + platform.radiusMm * inPlane.norm();
    EXPECT_GT(grid.firstMm, platformTop);
  }
}

TEST(CandidatePlanes, FiveAxisNeighboursLieOnTheConeAroundTheNormal) {
  const MachineSpec spec;  // 5-DOF, tilt up to 90 degrees
  const Vec3 normal = Vec3(1, 0, 1).normalized();
  const double radius = degToRad(5.0);
  const auto neighbours = neighbourNormals(spec, normal, radius);
  EXPECT_EQ(neighbours.size(), 6u);
  for (const Vec3& n : neighbours) {
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_NEAR(std::acos(std::clamp(n.dot(normal), -1.0, 1.0)), radius, 1e-9);
    EXPECT_TRUE(isRealizable(spec, n));
  }
}

TEST(CandidatePlanes, FiveAxisNeighboursBeyondTheTiltLimitAreLeftOut) {
  MachineSpec spec;
  spec.maxTiltDegrees = 60.0;
  const Vec3 atLimit = rotaryDirection(rotary(), 60.0);  // 60 degrees from +Z
  const auto neighbours = neighbourNormals(spec, atLimit, degToRad(5.0));
  EXPECT_FALSE(neighbours.empty());
  EXPECT_LT(neighbours.size(), 6u);
  for (const Vec3& n : neighbours) EXPECT_TRUE(isRealizable(spec, n));
}

TEST(CandidatePlanes, RotaryNeighboursAreWholeStepsOnEitherSide) {
  const MachineSpec spec = rotary();  // 1-degree steps, -60..60
  const auto neighbours = neighbourNormals(spec, rotaryDirection(spec, 30.0), degToRad(2.0));
  ASSERT_EQ(neighbours.size(), 2u);
  EXPECT_NEAR(machineAnglesFor(spec, neighbours[0]).rotaryDegrees, 28.0, 1e-9);
  EXPECT_NEAR(machineAnglesFor(spec, neighbours[1]).rotaryDegrees, 32.0, 1e-9);
  // Below one step there is nothing between the realizable angles.
  EXPECT_TRUE(neighbourNormals(spec, rotaryDirection(spec, 30.0), degToRad(0.4)).empty());
  // Nothing beyond the range.
  EXPECT_EQ(neighbourNormals(spec, rotaryDirection(spec, 60.0), degToRad(1.0)).size(), 1u);
}

// The pose convention (machine.h, docs/hardware.md "Pose convention"): the platform's rotation at a
// direction's angles brings that direction to up, for 1,000 random directions of every kind.
TEST(PlatformRotation, FiveAxisAnglesOfADirectionTurnItToUp) {
  std::srand(7);
  for (const Vec3& up : {Vec3(Vec3::UnitZ()), Vec3(Vec3::UnitY()), Vec3(Vec3(1, 2, -3).normalized())}) {
    MachineSpec spec;
    spec.kind = MachineKind::TiltRotate;
    spec.up = up;
    for (int i = 0; i < 1000; ++i) {
      const Vec3 d = Vec3::Random().normalized();
      const Eigen::Matrix3d r = platformRotation(spec, machineAnglesFor(spec, d));
      EXPECT_LT((r * d - up).norm(), 1e-9) << d.transpose();
      EXPECT_LT((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 1e-12);
      EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
    }
  }
}

TEST(PlatformRotation, FiveAxisPlatformTopTiltsTowardsTheOppositeAzimuth) {
  MachineSpec spec;
  spec.kind = MachineKind::TiltRotate;
  MachineAngles angles;
  angles.tiltDegrees = 30.0;
  angles.azimuthDegrees = 60.0;
  // The platform's normal (up in the part's frame) after the turn.
  const Vec3 top = platformRotation(spec, angles) * spec.up;
  EXPECT_NEAR(radToDeg(std::acos(top.z())), 30.0, 1e-9);
  EXPECT_NEAR(radToDeg(std::atan2(top.y(), top.x())), 60.0 - 180.0, 1e-9);
}

TEST(PlatformRotation, RotaryAnglesOfADirectionTurnItToUpAndThePlatformTopTowardsUpCrossAxis) {
  MachineSpec spec = rotary();
  spec.rotationAxis = Vec3(1, 1, 0).normalized();
  for (double angle = -60.0; angle <= 60.0; angle += 1.0) {
    const Vec3 d = rotaryDirection(spec, angle);
    const Eigen::Matrix3d r = platformRotation(spec, machineAnglesFor(spec, d));
    EXPECT_LT((r * d - spec.up).norm(), 1e-9) << angle;
    if (angle > 0.5) {
      EXPECT_GT((r * spec.up).dot(spec.up.cross(spec.rotationAxis)), 0.0) << angle;
    }
  }
}

TEST(PlatformRotation, ThreeAxisMachineDoesNotTurn) {
  MachineSpec spec;
  spec.kind = MachineKind::ThreeAxis;
  EXPECT_TRUE(platformRotation(spec, MachineAngles{}).isIdentity(0.0));
}

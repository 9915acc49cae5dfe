// Two firmware axes (two_axis.h): the tilt and rotation coordinates chosen for a step turn its printing
// direction to the printer's +Z on the machine as built, stay within the limits, move the least from the
// previous step, and a direction the limits cannot reach is refused naming the step and the angle.
#include "multidir/slicing/two_axis.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "multidir/core/common/units.h"

using namespace multidir;
using namespace multidir::slicing;

namespace {

// The machine as built, written from the device's side rather than from the solver: read the firmware's
// coordinates, undo each axis' zero and direction, turn the platform about its own normal (+Z at rest) by the
// rotation, then the cradle, carrying it, by minus the tilt about the tilt axis' line (the one-axis firmware
// convention: a positive tilt lifts the platform's top towards +Z x axis).
Eigen::Vector3d onTheMachine(const Eigen::Vector3d& direction, const TwoAxisPlatform& axes, const TwoAxisAngles& at) {
  const double tilt = core::degToRad((at.tiltDegrees - axes.tilt.zeroDegrees) / axes.tilt.direction);
  const double rotation = core::degToRad((at.rotationDegrees - axes.rotation.zeroDegrees) / axes.rotation.direction);
  const Eigen::Vector3d tiltLine = axes.tiltAlong == TiltAlong::X ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d onCradle = Eigen::AngleAxisd(rotation, Eigen::Vector3d::UnitZ()) * direction;
  return Eigen::AngleAxisd(-tilt, tiltLine) * onCradle;
}

TwoAxisPlatform open5x() {
  TwoAxisPlatform axes;  // U tilts about X within +-90, V rotates within +-360
  return axes;
}

// Wide limits, a tilt axis along Y, offset zeros and reversed directions: every part of the convention counts.
TwoAxisPlatform reversedAlongY() {
  TwoAxisPlatform axes;
  axes.tiltAlong = TiltAlong::Y;
  axes.tilt = {"B", "tilt", 10.0, -1.0, -200.0, 200.0};
  axes.rotation = {"C", "rotation", 30.0, -1.0, -400.0, 400.0};
  return axes;
}

std::vector<Eigen::Vector3d> randomDirections(int count) {
  std::mt19937 random(26);  // fixed: the same directions every run
  std::normal_distribution<double> normal;
  std::vector<Eigen::Vector3d> directions;
  while (static_cast<int>(directions.size()) < count) {
    const Eigen::Vector3d d(normal(random), normal(random), normal(random));
    if (d.norm() > 1e-6) directions.push_back(d.normalized());
  }
  return directions;
}

bool within(double value, const FirmwareRotaryAxis& axis) {
  return value >= axis.minDegrees && value <= axis.maxDegrees;
}

}  // namespace

TEST(TwoAxisAngles, EveryRandomDirectionIsTurnedToPlusZOnTheMachine) {
  for (const TwoAxisPlatform& axes : {reversedAlongY(), [] {
                                        TwoAxisPlatform wide = open5x();
                                        wide.tilt.minDegrees = -180.0;
                                        wide.tilt.maxDegrees = 180.0;
                                        return wide;
                                      }()}) {
    TwoAxisAngles previous = restAngles(axes);
    int step = 1;
    for (const Eigen::Vector3d& d : randomDirections(1000)) {
      const core::Result<TwoAxisAngles> at = twoAxisAngles(d, axes, previous, step++);
      ASSERT_TRUE(at.ok()) << at.error().describe();
      EXPECT_LT((onTheMachine(d, axes, *at) - Eigen::Vector3d::UnitZ()).norm(), 1e-9)
          << "direction " << d.transpose() << " at " << at->tiltDegrees << ", " << at->rotationDegrees;
      previous = *at;
    }
  }
}

TEST(TwoAxisAngles, TheAnglesStayWithinTheLimitsAndOnlyTheUnreachableIsRefused) {
  // Open5x's tilt of +-90 degrees reaches the upper half of the directions, and only that.
  const TwoAxisPlatform axes = open5x();
  TwoAxisAngles previous = restAngles(axes);
  int step = 1;
  for (const Eigen::Vector3d& d : randomDirections(1000)) {
    const core::Result<TwoAxisAngles> at = twoAxisAngles(d, axes, previous, step++);
    EXPECT_EQ(at.ok(), d.z() >= 0.0) << d.transpose();
    if (!at) continue;
    EXPECT_TRUE(within(at->tiltDegrees, axes.tilt)) << at->tiltDegrees;
    EXPECT_TRUE(within(at->rotationDegrees, axes.rotation)) << at->rotationDegrees;
    EXPECT_LT((onTheMachine(d, axes, *at) - Eigen::Vector3d::UnitZ()).norm(), 1e-9);
    previous = *at;
  }
}

TEST(TwoAxisAngles, ARotationRangeNarrowerThanATurnIsRespected) {
  TwoAxisPlatform axes = open5x();
  axes.rotation.minDegrees = 0.0;
  axes.rotation.maxDegrees = 90.0;
  TwoAxisAngles previous = restAngles(axes);
  int step = 1, refused = 0;
  for (const Eigen::Vector3d& d : randomDirections(1000)) {
    const core::Result<TwoAxisAngles> at = twoAxisAngles(d, axes, previous, step++);
    if (!at) {
      ++refused;
      continue;
    }
    EXPECT_TRUE(within(at->tiltDegrees, axes.tilt)) << at->tiltDegrees;
    EXPECT_TRUE(within(at->rotationDegrees, axes.rotation)) << at->rotationDegrees;
    EXPECT_LT((onTheMachine(d, axes, *at) - Eigen::Vector3d::UnitZ()).norm(), 1e-9);
    previous = *at;
  }
  EXPECT_GT(refused, 0);  // a quarter turn with the two tilt signs reaches half the azimuths
}

TEST(TwoAxisAngles, TheNearerOfTheTwoSolutionsIsChosen) {
  // Tilted 30 degrees towards -Y: (tilt 30, rotation 0) and (tilt -30, rotation 180) both print it.
  const TwoAxisPlatform axes = open5x();
  const Eigen::Vector3d d(0.0, -std::sin(core::degToRad(30.0)), std::cos(core::degToRad(30.0)));
  const auto fromPositive = twoAxisAngles(d, axes, {25.0, 10.0}, 2);
  ASSERT_TRUE(fromPositive.ok()) << fromPositive.error().describe();
  EXPECT_NEAR(fromPositive->tiltDegrees, 30.0, 1e-9);
  EXPECT_NEAR(fromPositive->rotationDegrees, 0.0, 1e-9);

  const auto fromNegative = twoAxisAngles(d, axes, {-25.0, 170.0}, 2);
  ASSERT_TRUE(fromNegative.ok()) << fromNegative.error().describe();
  EXPECT_NEAR(fromNegative->tiltDegrees, -30.0, 1e-9);
  EXPECT_NEAR(fromNegative->rotationDegrees, 180.0, 1e-9);
}

TEST(TwoAxisAngles, TheRotationTakesTheTurnNearestThePreviousOne) {
  // At V = 350 the same pose is nearer at 360 than back at 0.
  const TwoAxisPlatform axes = open5x();
  const Eigen::Vector3d d(0.0, -std::sin(core::degToRad(30.0)), std::cos(core::degToRad(30.0)));
  const auto at = twoAxisAngles(d, axes, {25.0, 350.0}, 2);
  ASSERT_TRUE(at.ok()) << at.error().describe();
  EXPECT_NEAR(at->tiltDegrees, 30.0, 1e-9);
  EXPECT_NEAR(at->rotationDegrees, 360.0, 1e-9);
}

TEST(TwoAxisAngles, ADirectionPastTheTiltLimitIsRefusedNamingTheStepAndTheAngle) {
  const TwoAxisPlatform axes = open5x();
  const double tilt = core::degToRad(104.2);
  const Eigen::Vector3d d(0.0, -std::sin(tilt), std::cos(tilt));
  const auto at = twoAxisAngles(d, axes, restAngles(axes), 3);
  ASSERT_FALSE(at.ok());
  EXPECT_EQ(at.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_EQ(at.error().where, "step 3");
  const std::string text = at.error().describe();
  EXPECT_NE(text.find("needs a tilt of 104.2 deg (axis U)"), std::string::npos) << text;
  EXPECT_NE(text.find("allows -90.0 to 90.0 (multidir.tilt_min, multidir.tilt_max)"), std::string::npos) << text;
}

TEST(TwoAxisAngles, ARotationOutsideItsLimitsIsRefusedNamingTheRotation) {
  // Tilted 45 degrees towards +X, with the tilt axis along X: V at -90 (tilt 45) or 90 (tilt -45), each a turn
  // apart from the others, none in [0, 45]; 90 is the nearer miss.
  TwoAxisPlatform axes = open5x();
  axes.rotation.minDegrees = 0.0;
  axes.rotation.maxDegrees = 45.0;
  const auto at = twoAxisAngles(Eigen::Vector3d(1.0, 0.0, 1.0), axes, restAngles(axes), 4);
  ASSERT_FALSE(at.ok());
  EXPECT_EQ(at.error().where, "step 4");
  EXPECT_NE(at.error().message.find("needs a rotation of 90.0 deg (axis V) at a tilt of -45.0 deg"), std::string::npos)
      << at.error().message;
  EXPECT_NE(at.error().message.find("multidir.rotation_min, multidir.rotation_max"), std::string::npos);
}

TEST(TwoAxisAngles, TiltZeroKeepsThePreviousRotation) {
  // Straight up, any rotation prints it: the platform stays where it is, also for a direction's rounding noise.
  const TwoAxisPlatform axes = reversedAlongY();
  for (const Eigen::Vector3d& up : {Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d(1e-12, -1e-12, 1.0)}) {
    const auto at = twoAxisAngles(up, axes, {-20.0, 123.4}, 5);
    ASSERT_TRUE(at.ok()) << at.error().describe();
    EXPECT_NEAR(at->tiltDegrees, axes.tilt.zeroDegrees, 1e-9);
    EXPECT_DOUBLE_EQ(at->rotationDegrees, 123.4);
  }
}

TEST(TwoAxisAngles, AZeroDirectionIsRefusedNamingTheStep) {
  const auto at = twoAxisAngles(Eigen::Vector3d::Zero(), open5x(), {}, 7);
  ASSERT_FALSE(at.ok());
  EXPECT_EQ(at.error().where, "step 7");
}

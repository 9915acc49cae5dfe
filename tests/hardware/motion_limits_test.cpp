#include "multidir/hardware/motion_limits.h"

#include <gtest/gtest.h>

#include <cmath>

namespace multidir::hardware {
namespace {

core::MachineSpec rotaryMachine() {
  core::MachineSpec spec;
  spec.kind = core::MachineKind::RotaryPlatform;
  spec.minAngleDegrees = -60.0;
  spec.maxAngleDegrees = 60.0;
  spec.angleStepDegrees = 1.8;  // a 200-step motor
  return spec;
}

TEST(MotionLimits, RotaryAnglesAreCountedInStepsFromTheMinimum) {
  const core::MachineSpec spec = rotaryMachine();
  EXPECT_TRUE(checkRotaryTarget(spec, -60.0).ok());
  EXPECT_TRUE(checkRotaryTarget(spec, -60.0 + 10 * 1.8).ok());
  EXPECT_FALSE(checkRotaryTarget(spec, 0.0).ok());  // -60 + 33.33 steps
  EXPECT_FALSE(checkRotaryTarget(spec, 61.0).ok());
  EXPECT_FALSE(checkRotaryTarget(spec, std::nan("")).ok());
}

// Issue 28: an angle of 1e308 from a job file was printed as a 31-digit number.
TEST(MotionLimits, AHugeAngleIsNamedInShortNotation) {
  const core::Status refused = checkRotaryTarget(rotaryMachine(), 1e308);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("the target angle 1e+308 degrees is outside"), std::string::npos)
      << refused.error().message;
}

TEST(MotionLimits, RotaryTargetsAgreeWithCoreRealizability) {
  const core::MachineSpec spec = rotaryMachine();
  for (int i = -40; i <= 40; ++i) {
    const double angle = i * 1.5;
    EXPECT_EQ(checkRotaryTarget(spec, angle).ok(), core::isRealizable(spec, core::rotaryDirection(spec, angle), 1e-9))
        << angle;
  }
}

TEST(MotionLimits, TiltAzimuthDirectionInvertsMachineAngles) {
  core::MachineSpec spec;
  spec.kind = core::MachineKind::TiltRotate;
  const core::Vec3 d = tiltAzimuthDirection(spec, 35.0, -120.0);
  const core::MachineAngles angles = core::machineAnglesFor(spec, d);
  EXPECT_NEAR(angles.tiltDegrees, 35.0, 1e-9);
  EXPECT_NEAR(angles.azimuthDegrees, -120.0, 1e-9);
}

TEST(MotionLimits, TiltAgainstTheWrongMachineIsRefused) {
  const core::Status status = checkTiltTarget(rotaryMachine(), 10.0, 0.0);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("not a tilting arm"), std::string::npos);
}

TEST(MotionLimits, NegativeTiltIsRefused) {
  core::MachineSpec spec;
  spec.kind = core::MachineKind::TiltRotate;
  EXPECT_FALSE(checkTiltTarget(spec, -5.0, 0.0).ok());
  EXPECT_TRUE(checkTiltTarget(spec, 0.0, 0.0).ok());
}

}  // namespace
}  // namespace multidir::hardware

// The pose convention checked by kinematics (docs/hardware.md, "Pose convention"): each machine takes every
// step's angles of a real job, and the simulator's model of what the device does with them (not an echo of
// the angles) shows the step's printing direction pointing straight up, in the orientation of the step's
// G-code frame (modelToFile).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "hardware_test_support.h"
#include "multidir/core/common/units.h"
#include "multidir/core/plan/print_job.h"
#include "multidir/core/search/decompose.h"
#include "multidir/hardware/device_simulator.h"
#include "multidir/hardware/robot_arm.h"
#include "multidir/hardware/rotary_platform.h"
#include "sim/platform_kinematics.h"
#include "support/test_models.h"

namespace multidir::hardware {
namespace {

using namespace test;
using core::Vec3;

// The robot's registers hold 0.01 degree: each angle is rounded by up to 0.005 degree, which moves the
// direction by at most 0.005 * sqrt(2) degrees.
const double kRegisterResolutionRadians = core::degToRad(0.0075);

// The kitten decomposed for `machine` (greedy search: a real plan in well under a second) as a print job in
// the machine frame.
core::PrintJob kittenJob(const core::MachineSpec& machine) {
  core::SearchOptions options;
  options.scheme = core::SearchScheme::Greedy;
  core::JobContext context;
  core::Result<core::Decomposition> plan =
      core::decompose(multidir::test::loadSharedModel("kitten.off"), machine, options, context);
  if (!plan) throw std::runtime_error(plan.error().describe());
  core::LoadedPlan loaded;
  loaded.metadata.machine = machine;
  loaded.metadata.up = machine.up;
  loaded.decomposition = std::move(plan).value();
  core::Result<core::PrintJob> job = core::buildPrintJob(loaded, core::PrintJobOptions{});
  if (!job) throw std::runtime_error(job.error().describe());
  return std::move(job).value();
}

// Model vectors in the platform frame at rest (the machine files' axes): step 1 stands on the platform at
// rest, so its modelToFile has no turn in it.
Eigen::Matrix3d platformFrameOf(const core::PrintJob& job) { return job.steps.front().modelToFile.linear(); }

// The platform frame's axes for `up`, written out here from docs/hardware.md rather than taken from the job.
Eigen::Matrix3d platformFrameFor(const Vec3& up) {
  Vec3 x = Vec3::UnitX() - up.x() * up;
  if (x.norm() < 1e-6) x = Vec3::UnitY() - up.y() * up;
  x.normalize();
  Eigen::Matrix3d rows;
  rows.row(0) = x.transpose();
  rows.row(1) = up.cross(x).transpose();
  rows.row(2) = up.transpose();
  return rows;
}

core::MachineSpec fiveAxis() {
  core::MachineSpec machine;
  machine.kind = core::MachineKind::TiltRotate;
  machine.up = Vec3::UnitY();
  return machine;
}

core::MachineSpec rotaryAboutX() {
  core::MachineSpec machine;
  machine.kind = core::MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitY();
  machine.rotationAxis = Vec3::UnitX();
  machine.minAngleDegrees = -90.0;
  machine.maxAngleDegrees = 90.0;
  return machine;
}

TEST(PoseConvention, TheRobotProgramsTurnBringsEveryDirectionUpExactly) {
  std::srand(11);
  for (const Vec3& up : {Vec3(Vec3::UnitZ()), Vec3(Vec3::UnitY()), Vec3(Vec3(-1, 2, 2).normalized())}) {
    core::MachineSpec machine = fiveAxis();
    machine.up = up;
    machine.maxTiltDegrees = 180.0;
    const Eigen::Matrix3d frame = platformFrameFor(up);
    for (int i = 0; i < 1000; ++i) {
      const Vec3 d = Vec3::Random().normalized();
      const core::MachineAngles angles = core::machineAnglesFor(machine, d);
      const Eigen::Matrix3d q = sim::urscriptTargetOrientation(angles.tiltDegrees, angles.azimuthDegrees);
      EXPECT_LT((q * frame * d - Vec3::UnitZ()).norm(), 1e-9) << d.transpose();
      // And the script reports the angles it was sent.
      const sim::ReportedTilt reported = sim::urscriptReportedTilt(q);
      EXPECT_NEAR(reported.tiltDegrees, angles.tiltDegrees, 1e-6);
      if (angles.tiltDegrees > 0.1 && angles.tiltDegrees < 179.9) {
        EXPECT_NEAR(std::remainder(reported.azimuthDegrees - angles.azimuthDegrees, 360.0), 0.0, 1e-6);
      }
    }
  }
}

TEST(PoseConvention, TheRobotProgramTiltsThePlatformsTopAwayFromTheRequestedAzimuth) {
  // The platform's normal (+z of the platform frame) after a request of tilt 40 towards azimuth 30.
  const Vec3 top = sim::urscriptTargetOrientation(40.0, 30.0) * Vec3::UnitZ();
  EXPECT_NEAR(core::radToDeg(std::acos(top.z())), 40.0, 1e-9);
  EXPECT_NEAR(core::radToDeg(std::atan2(top.y(), top.x())), 30.0 - 180.0, 1e-9);
}

TEST(PoseConvention, RobotArmTurnsEveryKittenStepsPrintingDirectionUp) {
  const core::PrintJob job = kittenJob(fiveAxis());
  ASSERT_GE(job.steps.size(), 2u);
  SimulatorOptions simOptions;
  simOptions.robotMaxSpeedDegreesPerSecond = 720.0;
  DeviceSimulator simulator(simOptions);
  ASSERT_TRUE(simulator.start().ok());
  RobotArmOptions options;
  options.connection = fastSettings(simulator.port(), 255);
  options.machine = job.machine;
  options.speedPercent = 100;
  RobotArm arm(options);
  ASSERT_TRUE(arm.connect().ok());
  ASSERT_TRUE(eventually([&] { return arm.status().programAlive; }));

  const Eigen::Matrix3d frame = platformFrameOf(job);
  ASSERT_LT((frame - platformFrameFor(job.machine.up)).norm(), 1e-12);
  double largestTilt = 0.0;
  for (const core::PrintJobStep& step : job.steps) {
    const double tilt = step.angles.tiltDegrees;
    const double azimuth = step.angles.azimuthDegrees;
    ASSERT_TRUE(outcome(arm.moveTo(tilt, azimuth)).ok()) << "step " << step.index;
    ASSERT_TRUE(eventually([&] { return arm.reached(tilt, azimuth); })) << "step " << step.index;
    const Eigen::Matrix3d platform = simulator.robotState().platformOrientation;
    EXPECT_LT((platform * frame * step.printingDirection - Vec3::UnitZ()).norm(), kRegisterResolutionRadians)
        << "step " << step.index << " (tilt " << tilt << ", azimuth " << azimuth << ")";
    EXPECT_LT((platform * frame - step.modelToFile.linear()).norm(), 2.0 * kRegisterResolutionRadians)
        << "step " << step.index;
    largestTilt = std::max(largestTilt, tilt);
  }
  EXPECT_GT(largestTilt, 10.0) << "the kitten's plan should tilt the platform at least once";
}

TEST(PoseConvention, RotaryPlatformTurnsEveryKittenStepsPrintingDirectionUp) {
  const core::PrintJob job = kittenJob(rotaryAboutX());
  ASSERT_GE(job.steps.size(), 2u);
  const Eigen::Matrix3d frame = platformFrameOf(job);
  SimulatorOptions simOptions;
  simOptions.rotaryShaftAxis = frame * job.machine.rotationAxis;
  simOptions.rotaryHomingSpeedDegreesPerSecond = 720.0;
  DeviceSimulator simulator(simOptions);
  ASSERT_TRUE(simulator.start().ok());
  RotaryPlatformOptions options;
  options.connection = fastSettings(simulator.port(), 1);
  options.machine = job.machine;
  options.speedDegreesPerSecond = 600.0;
  RotaryPlatform platform(options);
  ASSERT_TRUE(platform.connect().ok());
  ASSERT_TRUE(outcome(platform.enable()).ok());
  ASSERT_TRUE(eventually([&] { return platform.status().enabled; }));
  ASSERT_TRUE(outcome(platform.home()).ok());
  ASSERT_TRUE(eventually([&] { return platform.status().homed && !platform.status().homing; }));

  double largestTurn = 0.0;
  for (const core::PrintJobStep& step : job.steps) {
    const double angle = step.angles.rotaryDegrees;
    ASSERT_TRUE(outcome(platform.moveTo(angle)).ok()) << "step " << step.index;
    ASSERT_TRUE(eventually([&] { return platform.reached(angle); })) << "step " << step.index;
    // Whole stepper steps are exact in the controller's 0.01 degree registers.
    const Eigen::Matrix3d turned = simulator.rotaryState().platformOrientation;
    EXPECT_LT((turned * frame * step.printingDirection - Vec3::UnitZ()).norm(), 1e-9)
        << "step " << step.index << " (angle " << angle << ")";
    EXPECT_LT((turned * frame - step.modelToFile.linear()).norm(), 1e-9) << "step " << step.index;
    largestTurn = std::max(largestTurn, std::abs(angle));
  }
  EXPECT_GT(largestTurn, 10.0) << "the kitten's plan should turn the platform at least once";
}

}  // namespace
}  // namespace multidir::hardware

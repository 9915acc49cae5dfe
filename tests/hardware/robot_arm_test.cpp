#include "multidir/hardware/robot_arm.h"

#include <gtest/gtest.h>

#include <memory>

#include "hardware_test_support.h"

namespace multidir::hardware {
namespace {

using namespace test;

class RobotArmTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(sim.start().ok());
    options.connection = fastSettings(sim.port(), 255);
    options.machine.kind = core::MachineKind::TiltRotate;
    options.machine.maxTiltDegrees = 60.0;
    core::ForbiddenCone cone;
    cone.axis = core::Vec3(0.0, -1.0, 0.0);  // azimuth -90 at tilt 90
    cone.halfAngleDegrees = 40.0;
    options.machine.forbiddenCones.push_back(cone);
    options.speedPercent = 100;  // 360 degrees/s in this simulator
    options.programHeartbeatTimeout = 200ms;
  }

  std::unique_ptr<RobotArm> connected() {
    auto arm = std::make_unique<RobotArm>(options);
    const core::Status status = arm->connect();
    EXPECT_TRUE(status.ok()) << messageOf(status);
    EXPECT_TRUE(eventually([&] { return arm->status().programAlive; }));
    return arm;
  }

  static SimulatorOptions fastRobot() {
    SimulatorOptions o;
    o.robotMaxSpeedDegreesPerSecond = 360.0;
    return o;
  }

  DeviceSimulator sim{fastRobot()};
  RobotArmOptions options;
};

TEST_F(RobotArmTest, MovesToATiltAndAzimuthAndReportsReached) {
  auto arm = connected();
  EXPECT_EQ(arm->status().state, RobotProgramState::Idle);
  ASSERT_TRUE(outcome(arm->moveTo(30.0, 120.0)).ok());
  ASSERT_TRUE(eventually([&] { return arm->reached(30.0, 120.0); }));
  const SimulatedRobotState state = sim.robotState();
  EXPECT_NEAR(state.tiltDegrees, 30.0, 1e-9);
  EXPECT_NEAR(state.azimuthDegrees, 120.0, 1e-9);
  EXPECT_EQ(arm->status().acknowledgedSequence, arm->status().sentSequence);
}

TEST_F(RobotArmTest, NegativeAzimuthTravelsAsSignedTwosComplement) {
  auto arm = connected();
  ASSERT_TRUE(outcome(arm->moveTo(20.0, -135.5)).ok());
  ASSERT_TRUE(eventually([&] { return arm->reached(20.0, -135.5); }));
  EXPECT_NEAR(sim.robotState().azimuthDegrees, -135.5, 1e-9);
  EXPECT_NEAR(arm->status().azimuthDegrees, -135.5, 1e-9);
}

TEST_F(RobotArmTest, TiltBeyondTheProfileIsRefusedBeforeAnythingIsSent) {
  auto arm = connected();
  auto future = arm->moveTo(75.0, 0.0);
  ASSERT_TRUE(readyAtOnce(future));
  const core::Status status = future.get();
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("exceeds the machine's maximal tilt of 60.00"), std::string::npos)
      << status.error().message;
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Robot), 0u);
}

TEST_F(RobotArmTest, OrientationInsideAForbiddenConeIsRefusedBeforeAnythingIsSent) {
  auto arm = connected();
  const core::Status status = outcome(arm->moveTo(60.0, -90.0));
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("inside forbidden cone 1"), std::string::npos) << status.error().message;
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Robot), 0u);
}

TEST_F(RobotArmTest, HungProgramIsReportedAndMovesAreRefused) {
  auto arm = connected();
  sim.setHeartbeatAnswering(SimulatedDevice::Robot, false);
  ASSERT_TRUE(eventually([&] { return !arm->status().programAlive; }));
  EXPECT_NE(arm->status().lastError.find("URScript program stopped"), std::string::npos) << arm->status().lastError;
  const core::Status status = outcome(arm->moveTo(10.0, 0.0));
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("press Play"), std::string::npos) << status.error().message;
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Robot), 0u);
}

TEST_F(RobotArmTest, SilentHostMakesTheProgramStop) {
  options.speedPercent = 5;  // 18 degrees/s
  options.programHeartbeatTimeout = 150ms;
  auto arm = connected();
  ASSERT_TRUE(outcome(arm->moveTo(45.0, 0.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 2; }));
  arm->disconnect();
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 6; }));
  EXPECT_EQ(sim.robotState().faultCode, 2);
  EXPECT_LT(sim.robotState().tiltDegrees, 10.0);
}

TEST_F(RobotArmTest, EmergencyStopHaltsUntilTheFaultIsCleared) {
  options.speedPercent = 10;
  auto arm = connected();
  ASSERT_TRUE(outcome(arm->moveTo(45.0, 10.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 2; }));
  ASSERT_TRUE(outcome(arm->emergencyStop()).ok());
  ASSERT_TRUE(eventually([&] { return arm->status().state == RobotProgramState::Halted; }));
  const double tilt = sim.robotState().tiltDegrees;
  EXPECT_LT(tilt, 45.0);
  const core::Status refused = outcome(arm->moveTo(10.0, 10.0));
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("halted"), std::string::npos) << refused.error().message;
  ASSERT_TRUE(outcome(arm->clearFault()).ok());
  ASSERT_TRUE(eventually([&] { return arm->status().state == RobotProgramState::Idle; }));
  const core::Status latched = outcome(arm->moveTo(10.0, 10.0));
  ASSERT_FALSE(latched.ok());
  EXPECT_NE(latched.error().message.find("emergency stop the operator asked for is latched"), std::string::npos)
      << latched.error().message;
  ASSERT_TRUE(arm->clearStop().ok());
  EXPECT_TRUE(outcome(arm->moveTo(10.0, 10.0)).ok());
}

// Issue 14: an e-stop asked for during a short outage used to be dropped and the arm went on to 60 degrees.
TEST_F(RobotArmTest, EmergencyStopDuringAShortOutageIsSentFirstOnReconnectAndTheArmNeverMovesAfterIt) {
  options.speedPercent = 5;                  // 18 degrees/s: 0 -> 60 takes 3.3 s
  options.programHeartbeatTimeout = 1000ms;  // longer than the outage: only the e-stop can stop it
  auto arm = connected();
  ASSERT_TRUE(outcome(arm->moveTo(60.0, 0.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 2; }));
  sim.dropConnections(400ms);
  ASSERT_TRUE(eventually([&] { return arm->status().link == LinkState::Reconnecting; }));

  auto estop = arm->emergencyStop();
  EXPECT_FALSE(readyAtOnce(estop));
  EXPECT_FALSE(arm->clearStop().ok());
  const core::Status stopped = outcome(std::move(estop));
  ASSERT_TRUE(stopped.ok()) << messageOf(stopped);
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 5; }));  // halted
  const double stoppedAt = sim.robotState().tiltDegrees;
  EXPECT_LT(stoppedAt, 50.0);
  const auto polls = arm->status().polls;
  ASSERT_TRUE(eventually([&] { return arm->status().polls > polls + 20; }));
  EXPECT_DOUBLE_EQ(sim.robotState().tiltDegrees, stoppedAt);
  EXPECT_EQ(arm->status().stop.kind, StopKind::EmergencyStop);
  EXPECT_TRUE(arm->status().stop.confirmed);
  ASSERT_TRUE(outcome(arm->clearFault()).ok());
  ASSERT_TRUE(eventually([&] { return arm->status().state == RobotProgramState::Idle; }));
  EXPECT_FALSE(outcome(arm->moveTo(10.0, 0.0)).ok());  // still latched: the reset alone does not allow moves
  EXPECT_DOUBLE_EQ(sim.robotState().tiltDegrees, stoppedAt);
}

// Issue 28: an e-stop answered with a Modbus exception (device failure) was never written again and the arm
// went on to 60 degrees.
TEST_F(RobotArmTest, EmergencyStopRefusedWithAnExceptionIsWrittenAgainUntilTheProgramTakesItAndTheArmHalts) {
  options.speedPercent = 5;                  // 18 degrees/s: 0 -> 60 takes 3.3 s
  options.programHeartbeatTimeout = 1000ms;  // only the e-stop can stop it
  auto arm = connected();
  ASSERT_TRUE(outcome(arm->moveTo(60.0, 0.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 2; }));
  sim.refuseStops(SimulatedDevice::Robot, 4, 3);  // server device failure, three times

  const core::Status first = outcome(arm->emergencyStop());
  ASSERT_FALSE(first.ok());
  EXPECT_NE(first.error().message.find("Modbus exception 4"), std::string::npos) << first.error().message;
  ASSERT_TRUE(eventually([&] { return arm->status().stop.confirmed; })) << arm->status().stop.problem;
  EXPECT_EQ(arm->status().stop.writes, 1u);
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 5; }));  // halted
  const double stoppedAt = sim.robotState().tiltDegrees;
  EXPECT_LT(stoppedAt, 50.0);
  int halts = 0;
  for (const SimulatedCommandRecord& record : sim.commandLog()) halts += record.command == 3 ? 1 : 0;
  EXPECT_EQ(halts, 4);
  const auto polls = arm->status().polls;
  ASSERT_TRUE(eventually([&] { return arm->status().polls > polls + 20; }));
  EXPECT_DOUBLE_EQ(sim.robotState().tiltDegrees, stoppedAt);
  EXPECT_EQ(arm->status().stop.kind, StopKind::EmergencyStop);
}

// Issue 28: one controller at a time, the arm's program too; its halt is still taken from anyone.
TEST_F(RobotArmTest, ASecondDriverIsRefusedControlOfTheArmAndItsEmergencyStopIsStillHonoured) {
  options.speedPercent = 5;  // 18 degrees/s: 0 -> 60 takes 3.3 s
  auto first = connected();
  const std::uint16_t holder = first->status().control.session;
  ASSERT_TRUE(first->status().control.held());
  ASSERT_TRUE(outcome(first->moveTo(60.0, 0.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 2; }));

  RobotArm second(options);
  const core::Status refused = second.connect();
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("is controlled by another run (" + controlSessionText(holder) + ")"),
            std::string::npos)
      << refused.error().message;
  EXPECT_EQ(sim.robotState().controlOwner, holder);

  const core::Status stopped = outcome(second.emergencyStop());
  ASSERT_TRUE(stopped.ok()) << messageOf(stopped);
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 5; }));  // halted
  EXPECT_LT(sim.robotState().tiltDegrees, 50.0);
  EXPECT_EQ(sim.robotState().controlOwner, holder);
}

TEST_F(RobotArmTest, ExceptionReplyFromTheRobotIsReported) {
  auto arm = connected();
  sim.setExceptionReply(SimulatedDevice::Robot, 2);
  const core::Status status = outcome(arm->moveTo(10.0, 0.0));
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("Modbus exception 2"), std::string::npos) << status.error().message;
  EXPECT_NE(status.error().message.find("register map does not match docs/hardware.md"), std::string::npos);
}

}  // namespace
}  // namespace multidir::hardware

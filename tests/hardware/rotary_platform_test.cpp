#include "multidir/hardware/rotary_platform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "hardware_test_support.h"
#include "raw_modbus_client.h"

namespace multidir::hardware {
namespace {

using namespace test;

class RotaryPlatformTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(sim.start().ok());
    options.connection = fastSettings(sim.port(), 1);
    options.machine.kind = core::MachineKind::RotaryPlatform;
    options.machine.minAngleDegrees = -60.0;
    options.machine.maxAngleDegrees = 60.0;
    options.machine.angleStepDegrees = 1.0;
    options.speedDegreesPerSecond = 90.0;
    options.stallTimeout = 250ms;
  }

  std::unique_ptr<RotaryPlatform> connected() {
    auto platform = std::make_unique<RotaryPlatform>(options);
    const core::Status status = platform->connect();
    EXPECT_TRUE(status.ok()) << messageOf(status);
    return platform;
  }

  std::unique_ptr<RotaryPlatform> homed() {
    auto platform = connected();
    EXPECT_TRUE(outcome(platform->enable()).ok());
    EXPECT_TRUE(eventually([&] { return platform->status().enabled; }));
    EXPECT_TRUE(outcome(platform->home()).ok());
    EXPECT_TRUE(eventually([&] { return platform->status().homed && !platform->status().homing; }));
    return platform;
  }

  DeviceSimulator sim;
  RotaryPlatformOptions options;
};

TEST_F(RotaryPlatformTest, ConnectReadsTheControllerState) {
  auto platform = connected();
  const RotaryStatus status = platform->status();
  EXPECT_EQ(status.link, LinkState::Connected);
  EXPECT_NEAR(status.angleDegrees, 7.5, 1e-9);  // the simulator's power-on angle
  EXPECT_FALSE(status.homed);
  EXPECT_TRUE(status.controllerAlive);
  EXPECT_EQ(status.fault, RotaryFault::None);
}

TEST_F(RotaryPlatformTest, HomesThenTurnsToARealizableAngle) {
  auto platform = homed();
  EXPECT_NEAR(sim.rotaryState().angleDegrees, 0.0, 1e-9);
  ASSERT_TRUE(outcome(platform->moveTo(-30.0)).ok());
  ASSERT_TRUE(eventually([&] { return platform->reached(-30.0); }));
  EXPECT_NEAR(sim.rotaryState().angleDegrees, -30.0, 1e-9);
  EXPECT_NEAR(platform->status().angleDegrees, -30.0, 0.01);
}

TEST_F(RotaryPlatformTest, StatusCallbackReportsEveryPoll) {
  auto platform = connected();
  std::atomic<int> calls{0};
  platform->setStatusCallback([&](const RotaryStatus& status) {
    if (status.link == LinkState::Connected) ++calls;
  });
  EXPECT_TRUE(eventually([&] { return calls.load() >= 3; }));
  platform->setStatusCallback({});
}

TEST_F(RotaryPlatformTest, AngleOutsideTheProfileIsRefusedBeforeAnythingIsSent) {
  auto platform = connected();
  auto future = platform->moveTo(75.0);
  ASSERT_TRUE(readyAtOnce(future));
  const core::Status status = future.get();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_NE(status.error().message.find("outside the platform's range [-60.00, 60.00]"), std::string::npos)
      << status.error().message;
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Rotary), 0u);
}

TEST_F(RotaryPlatformTest, AngleBetweenStepperStepsIsRefusedWithTheNearestOnes) {
  auto platform = connected();
  const core::Status status = outcome(platform->moveTo(30.4));
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("nearest realizable angles are 30.00 and 31.00"), std::string::npos)
      << status.error().message;
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Rotary), 0u);
}

TEST_F(RotaryPlatformTest, MoveBeforeHomingIsRefusedBeforeAnythingIsSent) {
  auto platform = connected();
  auto future = platform->moveTo(30.0);
  ASSERT_TRUE(readyAtOnce(future));
  const core::Status status = future.get();
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("not homed"), std::string::npos) << status.error().message;
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Rotary), 0u);
  EXPECT_FALSE(sim.rotaryState().moving);
}

TEST_F(RotaryPlatformTest, CommandsWithoutALinkAreRefused) {
  RotaryPlatform platform(options);  // never connected
  const core::Status status = outcome(platform.enable());
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("not connected"), std::string::npos) << status.error().message;
  EXPECT_EQ(sim.requestCount(SimulatedDevice::Rotary), 0u);
}

TEST_F(RotaryPlatformTest, ConnectingToNothingSaysWhatToCheckAndKeepsRetrying) {
  DeviceSimulator closed;
  ASSERT_TRUE(closed.start().ok());
  const int port = closed.port();
  closed.stop();
  options.connection.tcp.port = port;
  RotaryPlatform platform(options);
  const core::Status status = platform.connect();
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("cannot connect to rotary platform at 127.0.0.1:" + std::to_string(port)),
            std::string::npos)
      << status.error().message;
  EXPECT_EQ(platform.status().link, LinkState::Reconnecting);
}

TEST_F(RotaryPlatformTest, DelayedRepliesAreReportedAsTimeoutsAndTheLinkRecovers) {
  auto platform = connected();
  sim.setReplyDelay(400ms);  // longer than the 150 ms response timeout
  ASSERT_TRUE(eventually([&] { return platform->status().link == LinkState::Reconnecting; }));
  EXPECT_NE(platform->status().lastError.find("did not answer within 150 ms"), std::string::npos)
      << platform->status().lastError;
  EXPECT_NE(platform->status().lastError.find("Modbus id is 1"), std::string::npos);
  sim.setReplyDelay(0ms);
  ASSERT_TRUE(eventually([&] { return platform->status().link == LinkState::Connected; }));
  const auto polls = platform->status().polls;
  EXPECT_TRUE(eventually([&] { return platform->status().polls > polls + 2; }));
}

TEST_F(RotaryPlatformTest, DroppedConnectionDuringAMoveIsReportedAndTheMoveCompletesAfterReconnecting) {
  auto platform = homed();
  ASSERT_TRUE(outcome(platform->moveTo(45.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.rotaryState().moving; }));
  sim.dropConnections(100ms);
  ASSERT_TRUE(eventually([&] { return platform->status().link == LinkState::Reconnecting; }));
  EXPECT_NE(platform->status().lastError.find("rotary platform at 127.0.0.1"), std::string::npos)
      << platform->status().lastError;
  ASSERT_TRUE(eventually([&] { return platform->status().link == LinkState::Connected; }));
  EXPECT_TRUE(eventually([&] { return platform->reached(45.0); }));
}

TEST_F(RotaryPlatformTest, ExceptionReplyIsReportedWithItsCodeAndKeepsTheLink) {
  auto platform = connected();
  sim.setExceptionReply(SimulatedDevice::Rotary, 4);  // server device failure
  const core::Status status = outcome(platform->enable());
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("Modbus exception 4"), std::string::npos) << status.error().message;
  EXPECT_NE(status.error().message.find("fault LED"), std::string::npos) << status.error().message;
  EXPECT_EQ(platform->status().link, LinkState::Connected);
  sim.setExceptionReply(SimulatedDevice::Rotary, 0);
  EXPECT_TRUE(outcome(platform->enable()).ok());
  EXPECT_TRUE(eventually([&] { return platform->status().enabled; }));
}

TEST_F(RotaryPlatformTest, StuckMotorIsDetectedAsAStallAndStopped) {
  auto platform = homed();
  sim.setMotorStuck(true);
  ASSERT_TRUE(outcome(platform->moveTo(30.0)).ok());
  ASSERT_TRUE(eventually([&] { return platform->status().fault == RotaryFault::Stall; }));
  const RotaryStatus status = platform->status();
  EXPECT_TRUE(status.stallDetectedByHost);
  EXPECT_NE(status.lastError.find("did not move for 250 ms while turning to 30.00 degrees"), std::string::npos)
      << status.lastError;
  EXPECT_TRUE(eventually([&] { return !sim.rotaryState().moving; }));  // MultiDir sent stop
  const core::Status refused = outcome(platform->moveTo(10.0));
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("in fault (stall)"), std::string::npos) << refused.error().message;
}

TEST_F(RotaryPlatformTest, EmergencyStopJumpsTheQueueCancelsQueuedMovesAndHaltsTheMotor) {
  options.speedDegreesPerSecond = 20.0;
  auto platform = homed();
  ASSERT_TRUE(outcome(platform->moveTo(60.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.rotaryState().moving; }));
  sim.setReplyDelay(60ms);  // keeps the worker busy so that the next moves wait in the queue
  auto first = platform->moveTo(10.0);
  auto second = platform->moveTo(20.0);
  auto third = platform->moveTo(-20.0);
  auto estop = platform->emergencyStop();
  const core::Status stopped = outcome(std::move(estop));
  EXPECT_TRUE(stopped.ok()) << messageOf(stopped);
  sim.setReplyDelay(0ms);
  const core::Status cancelled = outcome(std::move(third));
  ASSERT_FALSE(cancelled.ok());
  EXPECT_EQ(cancelled.error().code, core::ErrorCode::Cancelled);
  EXPECT_NE(cancelled.error().message.find("cancelled by emergency stop"), std::string::npos);
  outcome(std::move(first));
  outcome(std::move(second));
  const SimulatedRotaryState state = sim.rotaryState();
  EXPECT_FALSE(state.moving);
  EXPECT_EQ(state.faultCode, 5);
  EXPECT_LT(state.angleDegrees, 59.0);
  EXPECT_TRUE(eventually([&] { return platform->status().fault == RotaryFault::EmergencyStop; }));
  EXPECT_FALSE(outcome(platform->moveTo(0.0)).ok());
}

TEST_F(RotaryPlatformTest, SilentHostMakesTheControllerStopOnItsOwn) {
  options.speedDegreesPerSecond = 10.0;
  options.controllerHeartbeatTimeout = 150ms;
  auto platform = homed();
  ASSERT_TRUE(outcome(platform->moveTo(60.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.rotaryState().moving; }));
  platform->disconnect();  // no stop command: only the missing heartbeat can stop it
  ASSERT_TRUE(eventually([&] { return !sim.rotaryState().moving; }));
  const SimulatedRotaryState state = sim.rotaryState();
  EXPECT_EQ(state.faultCode, 2);  // heartbeat lost
  EXPECT_LT(state.angleDegrees, 30.0);
}

TEST_F(RotaryPlatformTest, ControllerThatStopsEchoingTheHeartbeatIsReportedAndMovesAreRefused) {
  auto platform = homed();
  sim.setHeartbeatAnswering(SimulatedDevice::Rotary, false);
  ASSERT_TRUE(eventually([&] { return !platform->status().controllerAlive; }));
  EXPECT_NE(platform->status().lastError.find("stopped echoing the heartbeat"), std::string::npos)
      << platform->status().lastError;
  const auto writes = sim.commandWriteCount(SimulatedDevice::Rotary);
  const core::Status status = outcome(platform->moveTo(10.0));
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Rotary), writes);
}

// Issue 14: a stop asked for while the link was down used to be dropped ("not sent ... reconnecting") and
// the platform finished its move to 60 degrees after the reconnect.
TEST_F(RotaryPlatformTest, StopDuringAShortOutageIsLatchedSentFirstOnReconnectAndThePlatformNeverMovesAfterIt) {
  options.speedDegreesPerSecond = 20.0;  // 10 -> 60 degrees takes 2.5 s
  auto platform = homed();
  ASSERT_TRUE(outcome(platform->moveTo(10.0)).ok());
  ASSERT_TRUE(eventually([&] { return platform->reached(10.0); }));
  ASSERT_TRUE(outcome(platform->moveTo(60.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.rotaryState().moving; }));
  sim.dropConnections(400ms);  // shorter than the controller's 1000 ms heartbeat timeout
  ASSERT_TRUE(eventually([&] { return platform->status().link == LinkState::Reconnecting; }));

  auto stop = platform->stop();
  EXPECT_FALSE(readyAtOnce(stop));  // not "not sent": it waits for the link
  EXPECT_TRUE(platform->status().stop.latched());
  EXPECT_FALSE(platform->status().stop.confirmed);
  const core::Status early = platform->clearStop();
  ASSERT_FALSE(early.ok());
  EXPECT_NE(early.error().message.find("has not confirmed it"), std::string::npos) << early.error().message;

  const core::Status stopped = outcome(std::move(stop));
  ASSERT_TRUE(stopped.ok()) << messageOf(stopped);
  EXPECT_FALSE(sim.rotaryState().moving);
  const double stoppedAt = sim.rotaryState().angleDegrees;
  EXPECT_LT(stoppedAt, 50.0);
  // Twenty polls later it still stands there, and moves are refused until the operator clears the stop.
  const auto polls = platform->status().polls;
  ASSERT_TRUE(eventually([&] { return platform->status().polls > polls + 20; }));
  EXPECT_DOUBLE_EQ(sim.rotaryState().angleDegrees, stoppedAt);
  EXPECT_TRUE(platform->status().stop.confirmed);
  EXPECT_EQ(platform->status().stop.kind, StopKind::Stop);
  auto refused = platform->moveTo(20.0);
  ASSERT_TRUE(readyAtOnce(refused));
  const core::Status refusal = refused.get();
  ASSERT_FALSE(refusal.ok());
  EXPECT_NE(refusal.error().message.find("stop the operator asked for is latched"), std::string::npos)
      << refusal.error().message;
  EXPECT_DOUBLE_EQ(sim.rotaryState().angleDegrees, stoppedAt);

  ASSERT_TRUE(platform->clearStop().ok());
  ASSERT_TRUE(outcome(platform->moveTo(20.0)).ok());
  EXPECT_TRUE(eventually([&] { return platform->reached(20.0); }));
}

TEST_F(RotaryPlatformTest, StopAskedForBeforeConnectingIsWrittenDuringTheConnectBeforeTheFirstPoll) {
  RotaryPlatform platform(options);
  auto stop = platform.stop();
  ASSERT_TRUE(readyAtOnce(stop));
  const core::Status status = stop.get();
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("stays latched and is sent first when you connect"), std::string::npos)
      << status.error().message;
  EXPECT_TRUE(platform.status().stop.latched());
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Rotary), 0u);
  ASSERT_TRUE(platform.connect().ok());  // returns after the first attempt: open, stop, configure, poll
  EXPECT_EQ(platform.status().stop.writes, 1u);
  EXPECT_TRUE(platform.status().stop.confirmed);
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Rotary), 1u);
}

TEST_F(RotaryPlatformTest, LatchedStopIsWrittenAgainAfterEveryReconnect) {
  auto platform = homed();
  ASSERT_TRUE(outcome(platform->stop()).ok());
  ASSERT_EQ(platform->status().stop.writes, 1u);
  sim.dropConnections(50ms);
  ASSERT_TRUE(eventually([&] { return platform->status().stop.writes >= 2; }));
  EXPECT_TRUE(eventually([&] { return platform->status().link == LinkState::Connected; }));
  EXPECT_TRUE(platform->status().stop.confirmed);
}

// Issue 28: a stop answered with a Modbus exception (busy) was never written again: the latch stayed
// unconfirmed with 0 writes and the platform finished its move from 10 to 40 degrees.
TEST_F(RotaryPlatformTest, StopRefusedAsBusyIsWrittenAgainUntilTheControllerTakesItAndThePlatformStops) {
  options.speedDegreesPerSecond = 10.0;  // 10 -> 40 degrees takes 3 s
  auto platform = homed();
  ASSERT_TRUE(outcome(platform->moveTo(10.0)).ok());
  ASSERT_TRUE(eventually([&] { return platform->reached(10.0); }));
  ASSERT_TRUE(outcome(platform->moveTo(40.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.rotaryState().moving; }));
  sim.refuseStops(SimulatedDevice::Rotary, 6, 3);  // busy, three times

  const core::Status first = outcome(platform->stop());  // the device's first answer: busy
  ASSERT_FALSE(first.ok());
  EXPECT_NE(first.error().message.find("Modbus exception 6"), std::string::npos) << first.error().message;
  EXPECT_NE(first.error().message.find("writes it again"), std::string::npos) << first.error().message;
  ASSERT_TRUE(eventually([&] { return platform->status().stop.confirmed; })) << platform->status().stop.problem;
  EXPECT_EQ(platform->status().stop.writes, 1u);
  EXPECT_FALSE(sim.rotaryState().moving);
  const double stoppedAt = sim.rotaryState().angleDegrees;
  EXPECT_LT(stoppedAt, 39.0);
  int stops = 0;
  for (const SimulatedCommandRecord& record : sim.commandLog()) stops += record.command == 5 ? 1 : 0;
  EXPECT_EQ(stops, 4);  // three refused, the fourth taken, and none after the device confirmed it
  const auto polls = platform->status().polls;
  ASSERT_TRUE(eventually([&] { return platform->status().polls > polls + 20; }));
  EXPECT_DOUBLE_EQ(sim.rotaryState().angleDegrees, stoppedAt);
  EXPECT_FALSE(outcome(platform->moveTo(20.0)).ok());  // still latched
}

// Issue 28: the stop MultiDir writes after it detects a stall was written once: refused as busy, it was never
// written again and the controller went on driving the stuck motor. It is latched like the operator's stop now.
TEST_F(RotaryPlatformTest, TheStopAfterAStallRefusedAsBusyIsWrittenAgainUntilTheControllerTakesIt) {
  auto platform = homed();
  sim.refuseStops(SimulatedDevice::Rotary, 6, 3);  // busy, three times
  sim.setMotorStuck(true);
  ASSERT_TRUE(outcome(platform->moveTo(30.0)).ok());
  ASSERT_TRUE(eventually([&] { return platform->status().fault == RotaryFault::Stall; }));

  ASSERT_TRUE(eventually([&] { return !sim.rotaryState().moving; }));  // the controller took a stop
  EXPECT_TRUE(eventually([&] { return platform->status().stop.confirmed; })) << platform->status().stop.problem;
  int stops = 0;
  for (const SimulatedCommandRecord& record : sim.commandLog()) stops += record.command == 5 ? 1 : 0;
  EXPECT_EQ(stops, 4);  // three refused, the fourth taken, and none after the controller confirmed it
}

TEST_F(RotaryPlatformTest, EmergencyStopIsNotDowngradedByALaterStop) {
  auto platform = homed();
  ASSERT_TRUE(outcome(platform->emergencyStop()).ok());
  ASSERT_TRUE(outcome(platform->stop()).ok());
  EXPECT_EQ(platform->status().stop.kind, StopKind::EmergencyStop);
  EXPECT_EQ(sim.rotaryState().faultCode, 5);
}

// Issue 28: nothing gave one run sole control of the platform: a second `multidir run` turned it 40 degrees
// while the first one printed.
TEST_F(RotaryPlatformTest, ASecondDriverIsRefusedControlWhileTheFirstHoldsThePlatformAndNothingMoves) {
  auto first = homed();
  ASSERT_TRUE(first->status().control.held());
  const std::uint16_t holder = first->status().control.session;
  EXPECT_EQ(sim.rotaryState().controlOwner, holder);
  const auto writes = sim.commandWriteCount(SimulatedDevice::Rotary);

  RotaryPlatform second(options);
  const core::Status refused = second.connect();
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("is controlled by another run (" + controlSessionText(holder) + ")"),
            std::string::npos)
      << refused.error().message;
  EXPECT_NE(refused.error().message.find("stop that run first"), std::string::npos) << refused.error().message;
  EXPECT_NE(second.status().link, LinkState::Connected);
  EXPECT_FALSE(outcome(second.moveTo(40.0)).ok());
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Rotary), writes);  // nothing but claims reached the device
  EXPECT_EQ(sim.rotaryState().controlOwner, holder);
  EXPECT_NEAR(sim.rotaryState().angleDegrees, 0.0, 1e-9);

  ASSERT_TRUE(outcome(first->moveTo(20.0)).ok());  // the holder goes on as before
  EXPECT_TRUE(eventually([&] { return first->reached(20.0); }));
}

TEST_F(RotaryPlatformTest, EmergencyStopFromASecondDriverIsHonouredWhileTheFirstHoldsThePlatform) {
  options.speedDegreesPerSecond = 10.0;  // 0 -> 40 degrees takes 4 s
  auto first = homed();
  ASSERT_TRUE(outcome(first->moveTo(40.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.rotaryState().moving; }));
  RotaryPlatform second(options);
  ASSERT_FALSE(second.connect().ok());

  const core::Status stopped = outcome(second.emergencyStop());
  ASSERT_TRUE(stopped.ok()) << messageOf(stopped);
  EXPECT_TRUE(second.status().stop.confirmed);
  const SimulatedRotaryState state = sim.rotaryState();
  EXPECT_FALSE(state.moving);
  EXPECT_EQ(state.faultCode, 5);
  EXPECT_LT(state.angleDegrees, 39.0);
  EXPECT_EQ(state.controlOwner, first->status().control.session);  // stopping takes nobody's control
}

TEST_F(RotaryPlatformTest, DisconnectGivesControlBackSoTheNextDriverGetsIt) {
  auto first = connected();
  first->disconnect();
  EXPECT_EQ(sim.rotaryState().controlOwner, 0);
  RotaryPlatform second(options);
  ASSERT_TRUE(second.connect().ok());
  EXPECT_TRUE(second.status().control.held());
  EXPECT_EQ(sim.rotaryState().controlOwner, second.status().control.session);
}

// A run that died (or lost its link) without giving control back: the lock lapses after the controller's
// timeout, and a driver refused meanwhile takes control on its own next attempt.
TEST_F(RotaryPlatformTest, ControlOfASessionThatFellSilentLapsesAndARefusedDriverThenTakesIt) {
  SimulatorOptions shortLock;
  shortLock.controlTimeout = 300ms;
  DeviceSimulator lapsing(shortLock);
  ASSERT_TRUE(lapsing.start().ok());
  options.connection = fastSettings(lapsing.port(), 1);
  RawClient dead(lapsing.port());  // claims control as session 1234, then writes nothing more
  ASSERT_TRUE(dead.send(mbapFrame(1, 1, writePdu(7, {0x1234}))));  // CLAIM
  ASSERT_TRUE(dead.readFrame().has_value());
  ASSERT_EQ(lapsing.rotaryState().controlOwner, 0x1234);

  RotaryPlatform platform(options);
  const core::Status refused = platform.connect();
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("(session 1234)"), std::string::npos) << refused.error().message;
  ASSERT_TRUE(eventually([&] { return platform.status().link == LinkState::Connected; }, 5000ms))
      << platform.status().lastError;
  EXPECT_TRUE(platform.status().control.held());
  EXPECT_EQ(lapsing.rotaryState().controlOwner, platform.status().control.session);
}

TEST_F(RotaryPlatformTest, BadOptionsAreRefusedWithoutStartingAnything) {
  options.machine.kind = core::MachineKind::TiltRotate;
  RotaryPlatform platform(options);
  const core::Status status = platform.connect();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_EQ(sim.requestCount(SimulatedDevice::Rotary), 0u);
}

}  // namespace
}  // namespace multidir::hardware

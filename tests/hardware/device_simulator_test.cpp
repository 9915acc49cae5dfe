#include "multidir/hardware/device_simulator.h"

#include <gtest/gtest.h>

#include "hardware_test_support.h"
#include "multidir/hardware/print_run.h"
#include "multidir/hardware/rotary_platform.h"
#include "raw_modbus_client.h"

namespace multidir::hardware {
namespace {

using namespace test;

TEST(DeviceSimulator, PortZeroListensOnAFreeLoopbackPortAndReportsIt) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  EXPECT_GT(sim.port(), 0);
  EXPECT_EQ(sim.address(), "127.0.0.1:" + std::to_string(sim.port()));
  EXPECT_TRUE(sim.running());
  sim.stop();
  EXPECT_FALSE(sim.running());
  sim.stop();  // idempotent
}

TEST(DeviceSimulator, PortInUseIsReportedWithWhatToDo) {
  DeviceSimulator first;
  ASSERT_TRUE(first.start().ok());
  SimulatorOptions options;
  options.port = first.port();
  DeviceSimulator second(options);
  const core::Status status = second.start();
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("cannot listen on 127.0.0.1:" + std::to_string(first.port())),
            std::string::npos)
      << status.error().message;
  EXPECT_NE(status.error().message.find("port " + std::to_string(first.port()) + " on 127.0.0.1 is in use"),
            std::string::npos)
      << status.error().message;
  EXPECT_NE(status.error().message.find("stop the other program listening there"), std::string::npos)
      << status.error().message;
  EXPECT_NE(status.error().message.find("choose another port with --port"), std::string::npos)
      << status.error().message;
}

// Issue 14: an address of another machine was reported as "choose another port".
TEST(DeviceSimulator, ListenAddressOfAnotherMachineIsReportedAsNotAnAddressOfThisMachine) {
  SimulatorOptions options;
  options.listenAddress = "192.0.2.1";  // TEST-NET-1 (RFC 5737): never assigned to a machine
  DeviceSimulator sim(options);
  const core::Status status = sim.start();
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("cannot assign requested address: 192.0.2.1 is not an address of this machine"),
            std::string::npos)
      << status.error().message;
  EXPECT_EQ(status.error().message.find("choose another port"), std::string::npos) << status.error().message;
}

TEST(DeviceSimulator, AddressThatIsNotIPv4IsRefused) {
  SimulatorOptions options;
  options.listenAddress = "localhost:1502";
  DeviceSimulator sim(options);
  const core::Status status = sim.start();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, core::ErrorCode::InvalidParameter);
}

TEST(DeviceSimulator, RotaryOnlySimulatorAnswersOtherUnitsWithAGatewayException) {
  SimulatorOptions options;
  options.robot = false;
  DeviceSimulator sim(options);
  ASSERT_TRUE(sim.start().ok());
  RotaryPlatformOptions platformOptions;
  platformOptions.connection = fastSettings(sim.port(), 7);
  platformOptions.machine.kind = core::MachineKind::RotaryPlatform;
  RotaryPlatform platform(platformOptions);
  const core::Status status = platform.connect();
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("Modbus exception 11"), std::string::npos) << status.error().message;
  EXPECT_NE(status.error().message.find("check the unit id"), std::string::npos) << status.error().message;
}

// The sequencer over the real driver and the simulator, in real time.
TEST(DeviceSimulator, PrintRunDrivesTheSimulatedPlatformThroughTwoRegions) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  RotaryPlatformOptions options;
  options.connection = fastSettings(sim.port(), 1);
  options.machine.kind = core::MachineKind::RotaryPlatform;
  options.speedDegreesPerSecond = 120.0;
  RotaryPlatform platform(options);
  ASSERT_TRUE(platform.connect().ok());
  ASSERT_TRUE(outcome(platform.enable()).ok());
  ASSERT_TRUE(eventually([&] { return platform.status().enabled; }));
  ASSERT_TRUE(outcome(platform.home()).ok());
  ASSERT_TRUE(eventually([&] { return platform.status().homed; }));

  auto positioner = makePositioner(platform);
  PrintRunOptions runOptions;
  runOptions.settleTime = 30ms;
  PrintRun run(*positioner,
               {{PlatformOrientation::rotary(-20.0), "region_1.gcode"}, {PlatformOrientation::rotary(40.0), "region_2.gcode"}},
               runOptions);
  std::vector<double> anglesWhenPrinting;
  run.setPrintRequestCallback([&](std::size_t, const PrintStep&) {
    anglesWhenPrinting.push_back(sim.rotaryState().angleDegrees);
  });
  ASSERT_TRUE(run.start().ok());
  for (std::size_t region = 0; region < 2; ++region) {
    ASSERT_TRUE(eventually([&] {
      run.tick();
      return run.state() == PrintRunState::Printing;
    })) << printRunStateName(run.state()) << " " << run.lastProblem();
    ASSERT_TRUE(run.regionDone(region).ok());
  }
  EXPECT_EQ(run.state(), PrintRunState::Completed);
  ASSERT_EQ(anglesWhenPrinting.size(), 2u);
  EXPECT_NEAR(anglesWhenPrinting[0], -20.0, 1e-9);
  EXPECT_NEAR(anglesWhenPrinting[1], 40.0, 1e-9);
}

// Issue 14: a pause during a short outage logged "motion stopped" although the stop was never sent, and the
// platform went on to its target after the reconnect.
TEST(DeviceSimulator, PrintRunPausedDuringAnOutageSaysStoppedOnlyOnceTheDeviceConfirmsAndItNeverMovesAfter) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  RotaryPlatformOptions options;
  options.connection = fastSettings(sim.port(), 1);
  options.machine.kind = core::MachineKind::RotaryPlatform;
  options.speedDegreesPerSecond = 20.0;  // 0 -> 60 degrees takes 3 s (homing runs at the controller's speed)
  RotaryPlatform platform(options);
  ASSERT_TRUE(platform.connect().ok());
  ASSERT_TRUE(outcome(platform.enable()).ok());
  ASSERT_TRUE(eventually([&] { return platform.status().enabled; }));
  ASSERT_TRUE(outcome(platform.home()).ok());
  ASSERT_TRUE(eventually([&] { return platform.status().homed && !platform.status().homing; }));

  auto positioner = makePositioner(platform);
  PrintRun run(*positioner, {{PlatformOrientation::rotary(60.0), "region_1.gcode"}});
  ASSERT_TRUE(run.start().ok()) << run.lastProblem();
  ASSERT_EQ(run.state(), PrintRunState::Moving) << run.lastProblem();
  ASSERT_TRUE(eventually([&] { return sim.rotaryState().moving; }));
  sim.dropConnections(400ms);
  ASSERT_TRUE(eventually([&] { return platform.status().link == LinkState::Reconnecting; }));
  ASSERT_TRUE(run.pause().ok());
  EXPECT_EQ(run.state(), PrintRunState::Paused);
  run.tick();
  EXPECT_EQ(run.log().back().message.find("motion stopped"), std::string::npos) << run.log().back().message;
  EXPECT_TRUE(run.stopUnconfirmed());
  ASSERT_TRUE(eventually([&] {
    run.tick();
    return !run.stopUnconfirmed();
  })) << run.log().back().message;
  EXPECT_NE(run.log().back().message.find("motion stopped"), std::string::npos) << run.log().back().message;
  const double stoppedAt = sim.rotaryState().angleDegrees;
  EXPECT_FALSE(sim.rotaryState().moving);
  EXPECT_LT(stoppedAt, 50.0);
  const auto polls = platform.status().polls;
  ASSERT_TRUE(eventually([&] { return platform.status().polls > polls + 20; }));
  EXPECT_DOUBLE_EQ(sim.rotaryState().angleDegrees, stoppedAt);
}

TEST(DeviceSimulator, PositionerForTheRotaryPlatformRefusesTiltTargets) {
  RotaryPlatformOptions options;
  options.machine.kind = core::MachineKind::RotaryPlatform;
  RotaryPlatform platform(options);
  auto positioner = makePositioner(platform);
  const core::Status status = positioner->startMove(PlatformOrientation::tiltAzimuth(10.0, 0.0));
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("4dof"), std::string::npos);
}

// The reply's PDU: what follows the 7-byte MBAP header.
std::vector<std::uint8_t> replyPdu(RawClient& client) {
  const auto frame = client.readFrame();
  if (!frame) return {};
  return std::vector<std::uint8_t>(frame->begin() + 7, frame->end());
}

// Issue 28: a second master turned the platform while a run controlled it. The controller refuses another
// session's writes (exception 1, nothing written) and takes a stop from anyone.
TEST(DeviceSimulator, RotaryControllerRefusesAnotherSessionsWritesButTakesItsStop) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  RotaryPlatformOptions options;
  options.connection = fastSettings(sim.port(), 1);
  options.machine.kind = core::MachineKind::RotaryPlatform;
  RotaryPlatform holder(options);
  ASSERT_TRUE(holder.connect().ok());
  ASSERT_TRUE(outcome(holder.enable()).ok());
  ASSERT_TRUE(eventually([&] { return holder.status().enabled; }));
  ASSERT_TRUE(outcome(holder.home()).ok());
  ASSERT_TRUE(eventually([&] { return holder.status().homed && !holder.status().homing; }));
  const std::uint16_t session = holder.status().control.session;
  const std::uint16_t other = static_cast<std::uint16_t>(session ^ 0x5555);

  RawClient second(sim.port());
  ASSERT_TRUE(second.connected());
  const std::vector<std::uint16_t> moveTo40 = {0, 4000, 1000, 4};  // TARGET_ANGLE, SPEED, COMMAND move
  ASSERT_TRUE(second.send(mbapFrame(1, 1, writePdu(0, moveTo40))));  // no session
  EXPECT_EQ(replyPdu(second), (std::vector<std::uint8_t>{0x90, 0x01}));
  std::vector<std::uint16_t> withOtherSession = moveTo40;
  withOtherSession.insert(withOtherSession.end(), {77, 1000, other});  // HEARTBEAT, its timeout, SESSION
  ASSERT_TRUE(second.send(mbapFrame(2, 1, writePdu(0, withOtherSession))));
  EXPECT_EQ(replyPdu(second), (std::vector<std::uint8_t>{0x90, 0x01}));
  ASSERT_TRUE(second.send(mbapFrame(3, 1, writePdu(5, {0}))));  // switching the holder's watchdog off
  EXPECT_EQ(replyPdu(second), (std::vector<std::uint8_t>{0x86, 0x01}));
  ASSERT_TRUE(second.send(mbapFrame(4, 1, writePdu(7, {other}))));  // a claim is heard, and not granted
  EXPECT_EQ(replyPdu(second), (std::vector<std::uint8_t>{0x06, 0x00, 0x07, static_cast<std::uint8_t>(other >> 8),
                                                         static_cast<std::uint8_t>(other & 0xFF)}));
  const auto polls = holder.status().polls;
  ASSERT_TRUE(eventually([&] { return holder.status().polls > polls + 5; }));
  SimulatedRotaryState state = sim.rotaryState();
  EXPECT_FALSE(state.moving);
  EXPECT_NEAR(state.angleDegrees, 0.0, 1e-9);
  EXPECT_NEAR(state.targetAngleDegrees, 0.0, 1e-9);
  EXPECT_EQ(state.controlOwner, session);
  EXPECT_EQ(holder.status().link, LinkState::Connected);

  ASSERT_TRUE(outcome(holder.moveTo(60.0)).ok());
  ASSERT_TRUE(eventually([&] { return sim.rotaryState().moving; }));
  ASSERT_TRUE(second.send(mbapFrame(5, 1, writePdu(3, {6}))));  // e-stop: taken from anyone
  EXPECT_EQ(replyPdu(second), (std::vector<std::uint8_t>{0x06, 0x00, 0x03, 0x00, 0x06}));
  state = sim.rotaryState();
  EXPECT_FALSE(state.moving);
  EXPECT_EQ(state.faultCode, 5);
}

// The robot's Modbus server takes every write; the program ignores another session's commands (ACK_SEQUENCE
// does not follow them) and takes its halt. Both masters are bare clients here, so that nothing else writes.
TEST(DeviceSimulator, RobotProgramIgnoresAnotherSessionsMoveButTakesItsHalt) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  RawClient first(sim.port());
  RawClient second(sim.port());
  ASSERT_TRUE(first.send(mbapFrame(1, 255, writePdu(136, {0x1111}))));  // CLAIM
  ASSERT_FALSE(replyPdu(first).empty());
  ASSERT_TRUE(eventually([&] { return sim.robotState().controlOwner == 0x1111; }));
  ASSERT_TRUE(second.send(mbapFrame(1, 255, writePdu(136, {0x2222}))));  // a second claim: not granted
  ASSERT_FALSE(replyPdu(second).empty());

  // tilt 30, azimuth 0, speed 100 %, move, SEQUENCE 1, HOST_HEARTBEAT, HEARTBEAT_TIMEOUT 0, SESSION
  ASSERT_TRUE(second.send(mbapFrame(2, 255, writePdu(128, {3000, 0, 100, 1, 1, 1, 0, 0x2222}))));
  ASSERT_FALSE(replyPdu(second).empty());
  // Three cycles of the program later (its PROGRAM_HEARTBEAT, register 146, counts them):
  std::uint16_t transaction = 10;
  const auto programHeartbeat = [&]() -> int {
    if (!first.send(mbapFrame(++transaction, 255, readPdu(146, 1)))) return -1;
    const std::vector<std::uint8_t> pdu = replyPdu(first);
    return pdu.size() == 4 ? (pdu[2] << 8) | pdu[3] : -1;
  };
  const int cycle = programHeartbeat();
  ASSERT_GE(cycle, 0);
  ASSERT_TRUE(eventually([&] { return programHeartbeat() >= cycle + 3; }));
  SimulatedRobotState state = sim.robotState();
  EXPECT_EQ(state.programState, 1);  // idle
  EXPECT_EQ(state.acknowledgedSequence, 0);
  EXPECT_EQ(state.controlOwner, 0x1111);
  EXPECT_NEAR(state.tiltDegrees, 0.0, 1e-9);

  ASSERT_TRUE(first.send(mbapFrame(3, 255, writePdu(128, {3000, 0, 10, 1, 2, 2, 0, 0x1111}))));  // the holder's
  ASSERT_FALSE(replyPdu(first).empty());
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 2; }));  // moving
  ASSERT_TRUE(second.send(mbapFrame(3, 255, writePdu(131, {3, 3}))));  // halt, SEQUENCE 3: from anyone
  ASSERT_FALSE(replyPdu(second).empty());
  ASSERT_TRUE(eventually([&] { return sim.robotState().programState == 5; }));  // halted
  EXPECT_EQ(sim.robotState().acknowledgedSequence, 3);
  EXPECT_LT(sim.robotState().tiltDegrees, 30.0);
}

}  // namespace
}  // namespace multidir::hardware

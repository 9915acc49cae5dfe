#include "multidir/hardware/device_simulator.h"

#include <gtest/gtest.h>

#include "hardware_test_support.h"
#include "multidir/hardware/print_run.h"
#include "multidir/hardware/rotary_platform.h"

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

}  // namespace
}  // namespace multidir::hardware

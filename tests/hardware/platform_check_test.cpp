// checkPlatformFor against the Modbus device simulator: a job for one platform device run against the other
// is refused with what it needs and what answers, before anything is written to either.
#include "multidir/hardware/platform_check.h"

#include <gtest/gtest.h>

#include "hardware_test_support.h"
#include "multidir/hardware/device_simulator.h"

namespace multidir::hardware {
namespace {

using namespace test;

DeviceSimulator& started(DeviceSimulator& sim) {
  EXPECT_TRUE(sim.start().ok());
  return sim;
}

SimulatorOptions only(bool rotary) {
  SimulatorOptions options;
  options.rotary = rotary;
  options.robot = !rotary;
  return options;
}

TEST(PlatformCheck, ARotaryJobAtARobotArmIsRefusedNamingBothAndNothingIsWritten) {
  DeviceSimulator sim(only(false));
  started(sim);
  const core::Status status = checkPlatformFor(core::MachineKind::RotaryPlatform, fastSettings(sim.port(), 1), 1, 255);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, core::ErrorCode::InvalidParameter);
  const std::string& message = status.error().message;
  EXPECT_NE(message.find("this job needs a 4-DOF rotary platform"), std::string::npos) << message;
  EXPECT_NE(message.find("answers as a robot arm"), std::string::npos) << message;
  EXPECT_NE(message.find("connect the rotary platform's controller"), std::string::npos) << message;
  EXPECT_NE(message.find("--machine 5dof"), std::string::npos) << message;
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Robot), 0u);
}

TEST(PlatformCheck, ARobotJobAtARotaryControllerIsRefusedNamingBothAndNothingIsWritten) {
  DeviceSimulator sim(only(true));
  started(sim);
  const core::Status status = checkPlatformFor(core::MachineKind::TiltRotate, fastSettings(sim.port(), 255), 1, 255);
  ASSERT_FALSE(status.ok());
  const std::string& message = status.error().message;
  EXPECT_NE(message.find("this job needs a 5-DOF robot arm"), std::string::npos) << message;
  EXPECT_NE(message.find("answers as a rotary platform controller"), std::string::npos) << message;
  EXPECT_NE(message.find("connect the robot arm"), std::string::npos) << message;
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Rotary), 0u);
}

TEST(PlatformCheck, EachDeviceOfTheSimulatorPassesTheJobsForIt) {
  DeviceSimulator both;
  started(both);
  EXPECT_TRUE(checkPlatformFor(core::MachineKind::RotaryPlatform, fastSettings(both.port(), 1), 1, 255).ok());
  EXPECT_TRUE(checkPlatformFor(core::MachineKind::TiltRotate, fastSettings(both.port(), 255), 1, 255).ok());
  DeviceSimulator rotary(only(true));
  started(rotary);
  EXPECT_TRUE(checkPlatformFor(core::MachineKind::RotaryPlatform, fastSettings(rotary.port(), 1), 1, 255).ok());
  DeviceSimulator robot(only(false));
  started(robot);
  EXPECT_TRUE(checkPlatformFor(core::MachineKind::TiltRotate, fastSettings(robot.port(), 255), 1, 255).ok());
}

// Nothing answering is the driver's to explain (its connect() names the address and what to check).
TEST(PlatformCheck, NothingListeningIsLeftToTheDriversConnect) {
  DeviceSimulator sim;
  started(sim);
  const int port = sim.port();
  sim.stop();
  EXPECT_TRUE(checkPlatformFor(core::MachineKind::RotaryPlatform, fastSettings(port, 1), 1, 255).ok());
}

}  // namespace
}  // namespace multidir::hardware

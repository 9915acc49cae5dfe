// Runs `multidir simulate` and checks its help, its usage errors and that Ctrl-C (SIGINT) stops it cleanly.
#include <gtest/gtest.h>

#include <string>

#include "multidir/hardware/device_simulator.h"
#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::runCli;

TEST(CliSimulate, HelpNamesTheDevicesAndOptions) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulate.Help");
  const CliRun run = runCli("help simulate", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("--listen ADDRESS"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("registers 128-255"), std::string::npos) << run.out;
}

TEST(CliSimulate, PortOutOfRangeIsAUsageError) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulate.BadPort");
  const CliRun run = runCli("simulate --port 70000", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("--port must be a whole number from 0 to 65535"), std::string::npos) << run.err;
}

// Each firmware's own kind of rotary axis: letters for Marlin (and OctoPrint's Marlin), manual steppers for Klipper.
TEST(CliSimulate, RotaryAxesOfTheOtherFirmwaresKindAreAUsageError) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulate.RotaryAxes");
  const CliRun klipperLetters = runCli("simulate --printer moonraker --port 0 --rotary-axes U,V", dir);
  EXPECT_EQ(klipperLetters.exitCode, 2);
  EXPECT_NE(klipperLetters.err.find("its rotary axes are manual steppers: --manual-stepper"), std::string::npos)
      << klipperLetters.err;
  const CliRun marlinSteppers = runCli("simulate --printer marlin --manual-stepper tilt", dir);
  EXPECT_EQ(marlinSteppers.exitCode, 2);
  EXPECT_NE(marlinSteppers.err.find("Marlin's rotary axes are letters: --rotary-axes U,V"), std::string::npos)
      << marlinSteppers.err;
  const CliRun badLetter = runCli("simulate --printer octoprint --port 0 --rotary-axes Q", dir);
  EXPECT_EQ(badLetter.exitCode, 1);
  EXPECT_NE(badLetter.err.find("'Q' is not a rotary axis letter"), std::string::npos) << badLetter.err;
}

TEST(CliSimulate, ListensOnLoopbackAndStopsCleanlyOnSigint) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulate.Sigint");
  const CliRun run = runCli("simulate --port 0", dir, "timeout --preserve-status -s INT 1");
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("Simulator listening on 127.0.0.1:"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("rotary: disabled, not homed, angle 7.50 deg"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("Simulator stopped."), std::string::npos) << run.out;
}

TEST(CliSimulate, APortInUseFailsAtOnceNamingThePortAndWhatToDo) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulate.PortInUse");
  multidir::hardware::DeviceSimulator first;
  ASSERT_TRUE(first.start().ok());
  const std::string port = std::to_string(first.port());
  const CliRun run = runCli("simulate --port " + port, dir, "timeout --preserve-status -s INT 5");
  EXPECT_EQ(run.exitCode, 1) << run.out << run.err;
  EXPECT_NE(run.err.find("port " + port + " on 127.0.0.1 is in use"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("stop the other program"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--port"), std::string::npos) << run.err;
}

// Issue 14: binding an address of another machine said "choose another port".
TEST(CliSimulate, ListenAddressOfAnotherMachineGivesTheRealReason) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulate.ForeignAddress");
  const CliRun run = runCli("simulate --listen 192.0.2.1 --port 0", dir, "timeout --preserve-status -s INT 5");
  EXPECT_EQ(run.exitCode, 1) << run.err;
  EXPECT_NE(run.err.find("cannot assign requested address: 192.0.2.1 is not an address of this machine"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(run.err.find("choose another port"), std::string::npos) << run.err;
}

}  // namespace

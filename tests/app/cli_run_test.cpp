// `multidir run` against the Modbus device simulator and a printer simulator (Moonraker or OctoPrint on
// 127.0.0.1, Marlin on a pseudo-terminal), all in this test process, and
// `multidir simulate --printer moonraker|octoprint|marlin`.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "multidir/hardware/device_simulator.h"
#include "multidir/hardware/marlin_simulator.h"
#include "multidir/hardware/moonraker_link.h"
#include "multidir/hardware/moonraker_simulator.h"
#include "multidir/hardware/octoprint_simulator.h"
#include "multidir/hardware/rotary_platform.h"
#include "support/cli_runner.h"
#include "support/run_job_writer.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::runCli;
namespace hw = multidir::hardware;

using multidir::test::stepGcode;
using multidir::test::writeJob;

class CliRunTest : public ::testing::Test {
 protected:
  void startSimulators(double printerSpeed, bool robot = false, bool octoPrint = false) {
    hw::SimulatorOptions deviceOptions;
    deviceOptions.robot = robot;
    deviceOptions.rotary = !robot;
    devices = std::make_unique<hw::DeviceSimulator>(deviceOptions);
    ASSERT_TRUE(devices->start().ok());
    hw::OctoPrintSimulatorOptions printerOptions;
    printerOptions.speed = printerSpeed;
    if (octoPrint)
      printer = std::make_unique<hw::OctoPrintSimulator>(printerOptions);
    else
      printer = std::make_unique<hw::MoonrakerSimulator>(printerOptions);
    ASSERT_TRUE(printer->start().ok());
    printerUrl = (octoPrint ? "octoprint://127.0.0.1:" : "http://127.0.0.1:") + std::to_string(printer->port()) +
                 (octoPrint ? std::string(" --api-key ") + hw::kOctoPrintSimulatorApiKey : std::string());
  }
  // `dir`: the folder of the job folder, where writeJob put the platform's machine profile.
  std::string deviceArgs(const std::string& dir) const {
    return "--printer " + printerUrl + " --platform 127.0.0.1:" + std::to_string(devices->port()) +
           " --settle 20 --machine '" + dir + "/platform.json'";
  }
  int printerRequests(const std::string& path) const {
    int n = 0;
    for (const auto& r : printer->requests()) n += r.path == path ? 1 : 0;
    return n;
  }

  std::unique_ptr<hw::DeviceSimulator> devices;
  std::unique_ptr<hw::PrinterSimulator> printer;
  std::string printerUrl;
};

TEST_F(CliRunTest, RunsEveryStepHomingThePlatformAndLogsToAFile) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.Whole");
  writeJob(dir + "/job");
  startSimulators(200.0);
  const CliRun run =
      runCli("run '" + dir + "/job' " + deviceArgs(dir) + " --log '" + dir + "/run.log'", dir, "timeout 60");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("homing rotary platform"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("all 2 regions printed"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("reports step-02.gcode complete"), std::string::npos) << run.out;
  EXPECT_EQ(printerRequests("/printer/print/start"), 2);
  EXPECT_EQ(printerRequests("/server/files/upload"), 2);
  EXPECT_NEAR(devices->rotaryState().angleDegrees, 30.0, 0.05);
  const std::string log = multidir::test::readAll(dir + "/run.log");
  EXPECT_NE(log.find("all 2 regions printed"), std::string::npos) << log;
}

TEST_F(CliRunTest, Runs5DofJobsOnTheRobotArm) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.Robot");
  writeJob(dir + "/job", true, true);
  startSimulators(200.0, true);
  const CliRun run = runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, "timeout 60");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("robot arm"), std::string::npos) << run.out;
  EXPECT_NEAR(devices->robotState().tiltDegrees, 40.0, 0.1);
  EXPECT_NEAR(devices->robotState().azimuthDegrees, 90.0, 0.1);
  EXPECT_EQ(printerRequests("/printer/print/start"), 2);
}

// Issue 24: a job for the other device was refused with the driver's Modbus exception ("illegal data
// address", "gateway target") instead of saying that the wrong device is connected.
TEST_F(CliRunTest, A5DofJobAtARotaryPlatformIsRefusedSayingWhatItNeedsAndNothingMoves) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.RobotJobAtRotary");
  writeJob(dir + "/job", true, true);
  startSimulators(1.0, false);
  const CliRun run = runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, "timeout 60");
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.err.find("this job needs a 5-DOF robot arm"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("answers as a rotary platform controller"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--platform"), std::string::npos) << run.err;
  EXPECT_EQ(devices->commandWriteCount(hw::SimulatedDevice::Rotary), 0u);
  EXPECT_EQ(printerRequests("/server/files/upload"), 0);
}

TEST_F(CliRunTest, A4DofJobAtARobotArmIsRefusedSayingWhatItNeedsAndNothingMoves) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.RotaryJobAtRobot");
  writeJob(dir + "/job");
  startSimulators(1.0, true);
  const CliRun run = runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, "timeout 60");
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.err.find("this job needs a 4-DOF rotary platform"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("answers as a robot arm"), std::string::npos) << run.err;
  EXPECT_EQ(devices->commandWriteCount(hw::SimulatedDevice::Robot), 0u);
  EXPECT_EQ(printerRequests("/server/files/upload"), 0);
}

// Issue 28: nothing gave one run sole control of the platform: a second run turned it 40 degrees while the
// first printed. Here the first run is a driver of this process holding the platform.
TEST_F(CliRunTest, ASecondRunIsRefusedWhileAnotherRunControlsThePlatformAndNothingMoves) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.SecondRun");
  writeJob(dir + "/job");
  startSimulators(200.0);
  hw::RotaryPlatformOptions firstRun;
  firstRun.connection.tcp.port = devices->port();
  firstRun.machine.kind = multidir::core::MachineKind::RotaryPlatform;
  hw::RotaryPlatform holder(firstRun);
  ASSERT_TRUE(holder.connect().ok());
  const std::string session = hw::controlSessionText(holder.status().control.session);
  const auto writes = devices->commandWriteCount(hw::SimulatedDevice::Rotary);

  const CliRun run = runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, "timeout 60");
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.err.find("is controlled by another run (" + session + "); stop that run first"), std::string::npos)
      << run.err;
  EXPECT_EQ(devices->commandWriteCount(hw::SimulatedDevice::Rotary), writes);
  EXPECT_FALSE(devices->rotaryState().homed);
  EXPECT_NEAR(devices->rotaryState().angleDegrees, 7.5, 1e-9);  // where it stood
  EXPECT_EQ(printerRequests("/server/files/upload"), 0);
  EXPECT_TRUE(holder.status().control.held());
}

// Issue 24: the advice was "continue with --from 1", which prints step 1 again from its start over the half
// of it the printer had printed.
TEST_F(CliRunTest, APrinterFaultMidStepSaysTheStepWasPartlyPrintedAndOffersTheNextStepOrARestart) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.Fault");
  writeJob(dir + "/job");
  hw::SimulatorOptions deviceOptions;
  deviceOptions.robot = false;
  devices = std::make_unique<hw::DeviceSimulator>(deviceOptions);
  ASSERT_TRUE(devices->start().ok());
  hw::MoonrakerSimulatorOptions printerOptions;
  printerOptions.speed = 50.0;
  printerOptions.fault = hw::PrinterFault::CancelledOnPrinter;
  printerOptions.faultAtProgress = 0.5;
  printer = std::make_unique<hw::MoonrakerSimulator>(printerOptions);
  ASSERT_TRUE(printer->start().ok());
  printerUrl = "http://127.0.0.1:" + std::to_string(printer->port());
  const CliRun run = runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, "timeout 60");
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.err.find("the run stopped at step 1"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("step-01.gcode was cancelled on the printer"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("step 1 was interrupted while printing (the printer had read"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--from 1 would print the step again from its start, over that part"), std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("continue with the next step: --from 2"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("clear the platform and print the whole job again"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("continue with --from 1"), std::string::npos) << run.err;
  // The log speaks of the command line, not of the studio's buttons.
  EXPECT_EQ(run.out.find("Region done"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("multidir run stops here"), std::string::npos) << run.out;
  EXPECT_EQ(printerRequests("/printer/print/start"), 1);
}

TEST_F(CliRunTest, CtrlCCancelsThePrintersJobAndEnds) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.CtrlC");
  writeJob(dir + "/job");
  startSimulators(1.0);  // the first step prints for about half a minute
  const CliRun run = runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, "timeout --preserve-status -s INT 2");
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.out.find("Ctrl-C: stopping both devices"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("by Ctrl-C"), std::string::npos) << run.err;
  EXPECT_EQ(printerRequests("/printer/print/cancel"), 1);
  EXPECT_EQ(printer->state().jobState, "cancelled");
}

// Issue 24: Ctrl-C while the platform turned between two steps left the heaters on (the run only cancelled a
// job it was printing). Ctrl-C is sent once the first step is complete and the platform turns to 90 degrees.
TEST_F(CliRunTest, CtrlCDuringATurnSwitchesTheHeatersOff) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.CtrlCTurn");
  writeJob(dir + "/job", true, false, true);
  startSimulators(200.0);
  const std::string pidFile = dir + "/pid";
  const std::string prefix = multidir::test::pidRecordingPrefix(pidFile);
  auto cli =
      std::async(std::launch::async, [&] { return runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, prefix); });
  double bedTargetWhenInterrupted = 0.0;
  const bool interrupted = multidir::test::signalCliWhen(pidFile, SIGINT, [&] {
    const hw::SimulatedRotaryState platform = devices->rotaryState();
    bedTargetWhenInterrupted = printer->state().bed.targetC;
    return printer->state().jobState == "complete" && platform.moving && platform.targetAngleDegrees >= 89.0;
  });
  const CliRun run = cli.get();
  ASSERT_TRUE(interrupted) << run.out << run.err;
  EXPECT_GT(bedTargetWhenInterrupted, 59.0);  // the first step left them on
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.out.find("Ctrl-C: stopping both devices"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("switched the heaters off"), std::string::npos) << run.out;
  EXPECT_EQ(printer->state().extruder.targetC, 0.0);
  EXPECT_EQ(printer->state().bed.targetC, 0.0);
  EXPECT_EQ(printerRequests("/printer/print/cancel"), 0);  // nothing was printing
  // Nothing of step 2 was printed: --from 2 is the true way on.
  EXPECT_NE(run.err.find("nothing of step 2 was printed: continue with --from 2"), std::string::npos) << run.err;
}

// A run that ends on its own (here the platform stalls while it turns between two steps) leaves the printer
// unwatched when the command exits: the heaters the first step left on go off.
TEST_F(CliRunTest, APlatformFaultDuringATurnEndsTheRunWithTheHeatersOff) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.FaultTurn");
  writeJob(dir + "/job", true, false, true);
  startSimulators(200.0);
  auto cli = std::async(std::launch::async,
                        [&] { return runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, "timeout 60"); });
  bool stuck = false;
  for (int i = 0; i < 3000 && !stuck; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const hw::SimulatedRotaryState platform = devices->rotaryState();
    if (printer->state().jobState != "complete" || !platform.moving || platform.targetAngleDegrees < 89.0) continue;
    ASSERT_GT(printer->state().bed.targetC, 59.0);  // the first step left them on
    devices->setMotorStuck(true);
    stuck = true;
  }
  const CliRun run = cli.get();
  ASSERT_TRUE(stuck) << run.out << run.err;
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.out.find("switched its heaters off"), std::string::npos) << run.out;
  EXPECT_EQ(printer->state().extruder.targetC, 0.0);
  EXPECT_EQ(printer->state().bed.targetC, 0.0);
}

// Ctrl-C before the first step (here while the platform homes from 170 degrees at 10 degrees/s) stopped
// nothing: the wait for the homing ended, the platform went on homing and the heaters stayed as they were
// (on, from an earlier job).
TEST_F(CliRunTest, CtrlCWhileThePlatformHomesStopsItAndSwitchesTheHeatersOff) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.CtrlCHoming");
  writeJob(dir + "/job");
  hw::SimulatorOptions deviceOptions;
  deviceOptions.robot = false;
  deviceOptions.rotaryInitialAngleDegrees = 170.0;
  deviceOptions.rotaryHomingSpeedDegreesPerSecond = 10.0;
  devices = std::make_unique<hw::DeviceSimulator>(deviceOptions);
  ASSERT_TRUE(devices->start().ok());
  hw::MoonrakerSimulatorOptions printerOptions;
  printerOptions.speed = 200.0;
  printer = std::make_unique<hw::MoonrakerSimulator>(printerOptions);
  ASSERT_TRUE(printer->start().ok());
  printerUrl = "http://127.0.0.1:" + std::to_string(printer->port());
  {  // an earlier job left the heaters on
    hw::MoonrakerSettings settings;
    settings.host = "127.0.0.1";
    settings.port = printer->port();
    auto link = hw::makeMoonrakerLink(settings);
    ASSERT_TRUE(link.ok());
    ASSERT_TRUE((*link)->connect().ok());
    std::ofstream(dir + "/hot.gcode") << stepGcode(1, true);
    ASSERT_TRUE((*link)->upload(dir + "/hot.gcode", "hot.gcode").get().ok());
    ASSERT_TRUE((*link)->startPrint("hot.gcode").get().ok());
    for (int i = 0; i < 500 && printer->state().jobState != "complete"; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_EQ(printer->state().jobState, "complete");
    ASSERT_GT(printer->state().bed.targetC, 59.0);
  }
  const std::string pidFile = dir + "/pid";
  const std::string prefix = multidir::test::pidRecordingPrefix(pidFile);
  auto cli =
      std::async(std::launch::async, [&] { return runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, prefix); });
  const bool interrupted =
      multidir::test::signalCliWhen(pidFile, SIGINT, [&] { return devices->rotaryState().homing; });
  const CliRun run = cli.get();
  ASSERT_TRUE(interrupted) << run.out << run.err;
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.err.find("stopped by Ctrl-C while homing the platform, before the first step: nothing was printed"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.out.find("heaters off: done"), std::string::npos) << run.out;
  EXPECT_EQ(printer->state().extruder.targetC, 0.0);
  EXPECT_EQ(printer->state().bed.targetC, 0.0);
  EXPECT_FALSE(devices->rotaryState().homing);            // the stop reached the platform
  EXPECT_EQ(printerRequests("/server/files/upload"), 1);  // the earlier job's only
}

TEST_F(CliRunTest, CtrlCMidStepCancelsItSwitchesTheHeatersOffAndSaysItWasPartlyPrinted) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.CtrlCMidStep");
  writeJob(dir + "/job", true, false, true);
  startSimulators(1.0);  // the first step prints for about half a minute
  const CliRun run = runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, "timeout --preserve-status -s INT 3");
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_EQ(printerRequests("/printer/print/cancel"), 1);
  EXPECT_EQ(printer->state().extruder.targetC, 0.0);
  EXPECT_EQ(printer->state().bed.targetC, 0.0);
  EXPECT_NE(run.err.find("step 1 was interrupted while printing"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--from 2"), std::string::npos) << run.err;
}

// The log file ends with how the command ended, as stderr says it.
TEST_F(CliRunTest, TheRunLogEndsWithWhyTheRunStoppedAndHowToGoOn) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.LogEnding");
  writeJob(dir + "/job");
  startSimulators(1.0);
  const CliRun run = runCli("run '" + dir + "/job' " + deviceArgs(dir) + " --log '" + dir + "/run.log'", dir,
                            "timeout --preserve-status -s INT 2");
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  const std::string log = multidir::test::readAll(dir + "/run.log");
  ASSERT_FALSE(run.err.empty());
  const std::string ending = run.err.substr(0, run.err.find('\n'));
  EXPECT_NE(ending.find("multidir run: the run stopped at step 1 (aborted"), std::string::npos) << ending;
  EXPECT_NE(log.find("] " + ending + "\n"), std::string::npos) << log;
}

// The log file is read as text: no terminal control sequences, even from names the job brings (here its
// folder's name holds a colour escape).
TEST_F(CliRunTest, TheRunLogHoldsNoTerminalEscapes) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.LogEscapes");
  const std::string job = dir + "/job\x1b[31mred\x1b[0m";
  writeJob(job);
  startSimulators(200.0);
  const CliRun run = runCli("run '" + job + "' " + deviceArgs(dir) + " --log '" + dir + "/run.log'", dir, "timeout 60");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  const std::string log = multidir::test::readAll(dir + "/run.log");
  EXPECT_NE(log.find("all 2 regions printed"), std::string::npos) << log;
  EXPECT_NE(log.find("jobred"), std::string::npos) << log;
  EXPECT_EQ(log.find('\x1b'), std::string::npos) << log;
  EXPECT_EQ(run.out.find('\x1b'), std::string::npos) << run.out;
}

TEST_F(CliRunTest, AJobWithoutGcodeSaysToSliceItFirst) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.NotSliced");
  writeJob(dir + "/job", false);
  const CliRun run = runCli(
      "run '" + dir + "/job' --printer 127.0.0.1:1 --platform 127.0.0.1:1 --machine '" + dir + "/platform.json'", dir);
  EXPECT_EQ(run.exitCode, 1) << run.err;
  EXPECT_NE(run.err.find("has no G-code"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("multidir slice"), std::string::npos) << run.err;
}

TEST_F(CliRunTest, AnUnreachablePrinterIsNamedAndNothingMoves) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.NoPrinter");
  writeJob(dir + "/job");
  startSimulators(1.0);
  const int port = printer->port();
  printer->stop();
  const CliRun run =
      runCli("run '" + dir + "/job' --printer 127.0.0.1:" + std::to_string(port) +
                 " --platform 127.0.0.1:" + std::to_string(devices->port()) + " --machine '" + dir + "/platform.json'",
             dir, "timeout 60");
  EXPECT_EQ(run.exitCode, 4) << run.err;
  EXPECT_NE(run.err.find("Moonraker printer at 127.0.0.1"), std::string::npos) << run.err;
  EXPECT_EQ(devices->commandWriteCount(hw::SimulatedDevice::Rotary), 0u);
}

TEST_F(CliRunTest, RunsEveryStepOnOctoPrint) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.OctoPrint");
  writeJob(dir + "/job");
  startSimulators(200.0, false, true);
  const CliRun run = runCli("run '" + dir + "/job' " + deviceArgs(dir), dir, "timeout 60");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("connected to OctoPrint printer at 127.0.0.1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("reports step-02.gcode complete"), std::string::npos) << run.out;
  EXPECT_EQ(printerRequests("/api/files/local"), 2);
  EXPECT_EQ(printerRequests("/api/files/local/step-01.gcode"), 1);
  EXPECT_EQ(printerRequests("/api/files/local/step-02.gcode"), 1);
  EXPECT_NEAR(devices->rotaryState().angleDegrees, 30.0, 0.05);
}

TEST_F(CliRunTest, AWrongOctoPrintApiKeyIsNamedWithWhereToFindTheKeyAndNothingMoves) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.OctoPrintKey");
  writeJob(dir + "/job");
  startSimulators(1.0, false, true);
  const CliRun run = runCli("run '" + dir + "/job' --printer octoprint://127.0.0.1:" + std::to_string(printer->port()) +
                                " --api-key wrong --platform 127.0.0.1:" + std::to_string(devices->port()) +
                                " --machine '" + dir + "/platform.json'",
                            dir, "timeout 60");
  EXPECT_EQ(run.exitCode, 4) << run.err;
  EXPECT_NE(run.err.find("the API key is wrong"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("Application Keys"), std::string::npos) << run.err;
  EXPECT_EQ(devices->commandWriteCount(hw::SimulatedDevice::Rotary), 0u);
}

// `multidir run ARGS` ends with exit code 2 and says each of `words` on stderr.
void expectRunUsageError(const std::string& args, const std::string& dir, const std::vector<std::string>& words) {
  const CliRun run = runCli("run job " + args, dir);
  EXPECT_EQ(run.exitCode, 2) << args;
  for (const std::string& word : words) EXPECT_NE(run.err.find(word), std::string::npos) << run.err;
}

TEST(CliRun, OctoPrintWithoutAnApiKeyOrAnUnknownSchemeIsAUsageError) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.PrinterUrl");
  expectRunUsageError("--printer octoprint://127.0.0.1:5000 --platform 127.0.0.1:502", dir,
                      {"OctoPrint needs an API key"});
  expectRunUsageError(
      "--printer ftp://127.0.0.1 --platform 127.0.0.1:502", dir,
      {"unknown printer scheme 'ftp://'", "moonraker://HOST:PORT", "octoprint://HOST:PORT", "serial:///dev/ttyACM0"});
}

TEST(CliRun, MissingPrinterOrPlatformIsAUsageError) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.Usage");
  expectRunUsageError("--platform 127.0.0.1:502", dir, {"--printer URL is required"});
  expectRunUsageError("--printer http://127.0.0.1:7125 --platform nowhere", dir, {"--platform must be HOST:PORT"});
}

TEST(CliSimulatePrinter, ServesMoonrakerOnLoopbackAndStopsOnSigint) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulatePrinter.Sigint");
  const CliRun run =
      runCli("simulate --printer moonraker --port 0 --speed 10", dir, "timeout --preserve-status -s INT 1");
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("listening on http://127.0.0.1:"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("printer: ready, job standby"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("Simulator stopped."), std::string::npos) << run.out;
}

TEST(CliSimulatePrinter, ServesOctoPrintOnLoopbackAndPrintsTheApiKeyItExpects) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulatePrinter.OctoPrint");
  const CliRun run =
      runCli("simulate --printer octoprint --port 0 --api-key LAB-KEY", dir, "timeout --preserve-status -s INT 1");
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("Printer simulator (OctoPrint, Marlin) listening on http://127.0.0.1:"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("API key: LAB-KEY"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("--printer octoprint://127.0.0.1:"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("Simulator stopped."), std::string::npos) << run.out;
}

// Issue 24: a second `multidir simulate --printer` on a busy port listened beside the first one (SO_REUSEPORT)
// and the requests were split between the two printers.
TEST(CliSimulatePrinter, APortInUseFailsAtOnceNamingThePortAndWhatToDo) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulatePrinter.PortInUse");
  for (const std::string kind : {"moonraker", "octoprint"}) {
    hw::MoonrakerSimulator first;
    ASSERT_TRUE(first.start().ok());
    const std::string port = std::to_string(first.port());
    const CliRun run =
        runCli("simulate --printer " + kind + " --port " + port, dir, "timeout --preserve-status -s INT 5");
    EXPECT_EQ(run.exitCode, 1) << kind << ": " << run.out << run.err;
    EXPECT_NE(run.err.find("port " + port + " on 127.0.0.1 is in use"), std::string::npos) << kind << ": " << run.err;
    EXPECT_NE(run.err.find("stop the other program"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("--port"), std::string::npos) << run.err;
    EXPECT_EQ(run.out.find("listening on"), std::string::npos) << run.out;
  }
}

TEST(CliSimulatePrinter, UnknownPrinterOrFaultIsAUsageErrorNamingTheChoices) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulatePrinter.Usage");
  const CliRun unknown = runCli("simulate --printer repetier", dir);
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.err.find("simulates 'moonraker' (Klipper), 'octoprint' and 'marlin'"), std::string::npos)
      << unknown.err;
  const CliRun fault = runCli("simulate --printer moonraker --fault fire", dir);
  EXPECT_EQ(fault.exitCode, 2);
  EXPECT_NE(fault.err.find("thermal-runaway"), std::string::npos) << fault.err;
}

TEST(CliSimulatePrinter, ServesMarlinOnAPseudoTerminalAndStopsOnSigint) {
  const std::string dir = multidir::test::scratchDirectory("CliSimulatePrinter.Marlin");
  const CliRun run = runCli("simulate --printer marlin --speed 10", dir, "timeout --preserve-status -s INT 1");
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("Use --printer serial:///dev/pts/"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("printer: running, line 0"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("Simulator stopped."), std::string::npos) << run.out;
}

TEST(CliRunMarlin, StreamsEveryStepToAMarlinPrinterOverSerial) {
  const std::string dir = multidir::test::scratchDirectory("CliRun.Marlin");
  writeJob(dir + "/job");
  hw::SimulatorOptions deviceOptions;
  deviceOptions.robot = false;
  hw::DeviceSimulator devices(deviceOptions);
  ASSERT_TRUE(devices.start().ok());
  hw::MarlinSimulatorOptions printerOptions;
  printerOptions.speed = 200.0;
  hw::MarlinSimulator printer(printerOptions);
  ASSERT_TRUE(printer.start().ok());
  const CliRun run = runCli("run '" + dir + "/job' --printer serial://" + printer.devicePath() +
                                " --platform 127.0.0.1:" + std::to_string(devices.port()) + " --settle 20 --machine '" +
                                dir + "/platform.json'",
                            dir, "timeout 60");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("Marlin printer at " + printer.devicePath()), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("reports step-02.gcode complete"), std::string::npos) << run.out;
  int jobEnds = 0;
  for (const auto& e : printer.executed()) jobEnds += e.command == "M400" ? 1 : 0;
  EXPECT_EQ(jobEnds, 2);
  EXPECT_NEAR(devices.rotaryState().angleDegrees, 30.0, 0.05);
}

}  // namespace

// `multidir run` checks the whole job before anything moves (issue 28): the platform's limits come from the
// machine profile the operator gives (--machine), never only from print-job.json; every step's G-code is
// checked again by the checks `multidir slice` runs; step files that are links or not regular files are
// refused; the job file's mistakes are named by file, field and allowed range. Also: SIGHUP stops the devices
// like Ctrl-C, a log file that cannot be written is reported at once, and the job is read without a temporary
// file. Against the Modbus device simulator and the Moonraker simulator on 127.0.0.1, in this process.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "multidir/hardware/device_simulator.h"
#include "multidir/hardware/moonraker_simulator.h"
#include "support/cli_runner.h"
#include "support/run_job_writer.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::runCli;
namespace hw = multidir::hardware;
namespace fs = std::filesystem;

// print-job.json of the job folder `job`, changed by `change`.
void changeJob(const std::string& job, const std::function<void(nlohmann::json&)>& change) {
  nlohmann::json document = nlohmann::json::parse(multidir::test::readAll(job + "/print-job.json"));
  change(document);
  std::ofstream(job + "/print-job.json") << document.dump(2);
}

// print-job.json's text with `from` replaced by `to` (for tokens JSON cannot hold: 1e999, NaN).
void replaceInJob(const std::string& job, const std::string& from, const std::string& to) {
  std::string text = multidir::test::readAll(job + "/print-job.json");
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, from.size(), to);
  std::ofstream(job + "/print-job.json") << text;
}

class CliRunJobChecks : public ::testing::Test {
 protected:
  void SetUp() override {
    hw::SimulatorOptions deviceOptions;
    deviceOptions.robot = false;
    devices = std::make_unique<hw::DeviceSimulator>(deviceOptions);
    ASSERT_TRUE(devices->start().ok());
  }
  void startPrinter(double speed) {
    hw::MoonrakerSimulatorOptions options;
    options.speed = speed;
    printer = std::make_unique<hw::MoonrakerSimulator>(options);
    ASSERT_TRUE(printer->start().ok());
  }
  // Runs the job folder `dir`/job with the platform profile beside it; `prefix` as runCli's.
  CliRun run(const std::string& dir, const std::string& extra = "", const std::string& prefix = "timeout 60") {
    if (!printer) startPrinter(200.0);
    return runCli("run '" + dir + "/job' --printer http://127.0.0.1:" + std::to_string(printer->port()) +
                      " --platform 127.0.0.1:" + std::to_string(devices->port()) + " --settle 20 --machine '" + dir +
                      "/platform.json' " + extra,
                  dir, prefix);
  }
  int printerRequests(const std::string& path) const {
    int n = 0;
    for (const auto& r : printer->requests()) n += r.path == path ? 1 : 0;
    return n;
  }
  // Refused with exit code 1 before anything was sent to either device, saying each of `words` on stderr.
  void expectRefusedBeforeAnythingMoves(const CliRun& result, const std::vector<std::string>& words) {
    EXPECT_EQ(result.exitCode, 1) << result.out << result.err;
    for (const std::string& word : words) EXPECT_NE(result.err.find(word), std::string::npos) << result.err;
    EXPECT_EQ(devices->commandWriteCount(hw::SimulatedDevice::Rotary), 0u);
    EXPECT_EQ(printerRequests("/server/files/upload"), 0);
  }

  std::unique_ptr<hw::DeviceSimulator> devices;
  std::unique_ptr<hw::MoonrakerSimulator> printer;
};

// Issue 28: the limits came only from print-job.json: widened there to +-180, the platform was turned to 175.
TEST_F(CliRunJobChecks, AnAngleBeyondThePlatformsProfileIsRefusedThoughTheJobWidenedItsOwnLimits) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.Widened");
  multidir::test::writeJob(dir + "/job");
  changeJob(dir + "/job", [](nlohmann::json& job) {
    job["machine"]["minAngleDegrees"] = -180;
    job["machine"]["maxAngleDegrees"] = 180;
    job["steps"][1]["angles"]["rotaryDegrees"] = 175;
  });
  expectRefusedBeforeAnythingMoves(
      run(dir), {"print-job.json: steps[1].angles.rotaryDegrees (step 2)", "175.00", "[-90.00, 90.00]",
                 "--machine " + dir + "/platform.json", "nothing was moved"});
}

// Issue 28: step 1 was homed, turned and printed before the run found that step 2 was out of range.
TEST_F(CliRunJobChecks, AnAngleTheLastStepCannotTakeIsFoundBeforeTheFirstStepIsHomed) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.LastStep");
  multidir::test::writeJob(dir + "/job");  // steps at 0 and 30 degrees
  multidir::test::writeRotaryProfile(dir + "/platform.json", -20.0, 20.0);
  expectRefusedBeforeAnythingMoves(run(dir), {"steps[1].angles.rotaryDegrees (step 2)", "[-20.00, 20.00]"});
  EXPECT_FALSE(devices->rotaryState().homed);
}

TEST_F(CliRunJobChecks, AJobForAnotherKindOfPlatformThanTheProfileIsRefused) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.Kind");
  multidir::test::writeJob(dir + "/job", true, true);  // 5-DOF
  multidir::test::writeRotaryProfile(dir + "/platform.json", -90.0, 90.0);
  expectRefusedBeforeAnythingMoves(run(dir), {"machine.kind is 5dof", "is a 4dof machine"});
}

TEST(CliRunUsage, WithoutThePlatformsMachineProfileIsAUsageError) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.NoMachine");
  multidir::test::writeJob(dir + "/job");
  const CliRun run = runCli("run '" + dir + "/job' --printer http://127.0.0.1:1 --platform 127.0.0.1:1", dir);
  EXPECT_EQ(run.exitCode, 2) << run.err;
  EXPECT_NE(run.err.find("--machine PROFILE.json is required"), std::string::npos) << run.err;
}

// Issue 28: step G-code was not checked again: each of these was uploaded and printed.
class CliRunStepGcode : public CliRunJobChecks,
                        public ::testing::WithParamInterface<std::pair<std::string, std::string>> {};

TEST_P(CliRunStepGcode, AStepFileFailingTheSlicersChecksIsRefusedBeforeAnythingMoves) {
  const std::string dir =
      multidir::test::scratchDirectory("CliRunStepGcode." + std::to_string(std::hash<std::string>{}(GetParam().first)));
  multidir::test::writeJob(dir + "/job");
  std::ofstream(dir + "/job/step-02.gcode", std::ios::app) << GetParam().first << "\n";
  expectRefusedBeforeAnythingMoves(run(dir), {"step-02.gcode: step 2, line 28: " + GetParam().second,
                                              "by the checks 'multidir slice' runs", "nothing was moved"});
}

INSTANTIATE_TEST_SUITE_P(
    Lines, CliRunStepGcode,
    ::testing::Values(std::make_pair(std::string("G1 A30"),
                                     std::string("the platform turns inside a step's own program")),
                      std::make_pair(std::string("MANUAL_STEPPER STEPPER=rotary_a MOVE=30"),
                                     std::string("the platform turns inside a step's own program")),
                      std::make_pair(std::string("G1 Z-5 E3"), std::string("a move to z -5.00 mm, below the bed"))));

// Issue 28: a step file linking outside the job folder was uploaded.
TEST_F(CliRunJobChecks, AStepFileThatIsASymbolicLinkIsRefused) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.Link");
  multidir::test::writeJob(dir + "/job");
  fs::rename(dir + "/job/step-02.gcode", dir + "/outside.gcode");
  fs::create_symlink("../outside.gcode", dir + "/job/step-02.gcode");
  expectRefusedBeforeAnythingMoves(run(dir),
                                   {"step-02.gcode: step 2's G-code (slicing.steps[1].gcode) is a symbolic link",
                                    "regular files inside the job folder"});
}

// Issue 28: a FIFO was reported "missing".
TEST_F(CliRunJobChecks, AStepFileThatIsAFifoIsRefusedAsNotARegularFile) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.Fifo");
  multidir::test::writeJob(dir + "/job");
  fs::remove(dir + "/job/step-02.gcode");
  ASSERT_EQ(::mkfifo((dir + "/job/step-02.gcode").c_str(), 0600), 0);
  expectRefusedBeforeAnythingMoves(run(dir),
                                   {"step-02.gcode: step 2's G-code (slicing.steps[1].gcode) is not a regular "
                                    "file (it is a FIFO)"});
}

TEST_F(CliRunJobChecks, OneGcodeFileForTwoStepsIsRefused) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.SameFile");
  multidir::test::writeJob(dir + "/job");
  changeJob(dir + "/job", [](nlohmann::json& job) { job["slicing"]["steps"][1]["gcode"] = "step-01.gcode"; });
  expectRefusedBeforeAnythingMoves(
      run(dir), {"print-job.json: slicing.steps[1].gcode names 'step-01.gcode', the G-code of an earlier step too"});
}

TEST_F(CliRunJobChecks, AJobVersionBelowOneIsRefusedNamingTheVersionsRead) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.Version");
  multidir::test::writeJob(dir + "/job");
  changeJob(dir + "/job", [](nlohmann::json& job) { job["version"] = -7; });
  expectRefusedBeforeAnythingMoves(run(dir), {"version -7 is not a print-job version (this MultiDir reads 1 to 1)"});
}

// Issue 28: printSeconds 1e308 was shown as "-2562047788015215h".
TEST_F(CliRunJobChecks, APrintTimeBeyondAYearIsRefusedNamingTheFieldAndTheRange) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.PrintSeconds");
  multidir::test::writeJob(dir + "/job");
  changeJob(dir + "/job", [](nlohmann::json& job) { job["slicing"]["steps"][0]["estimate"]["printSeconds"] = 1e308; });
  expectRefusedBeforeAnythingMoves(run(dir), {"slicing.steps[0].estimate.printSeconds is 1e+308, outside the allowed "
                                              "range 0 to 31536000 s"});
}

// Issue 28: an angle of 1e308 was printed as a 31-digit number.
TEST_F(CliRunJobChecks, AHugeAngleIsNamedInShortNotation) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.HugeAngle");
  multidir::test::writeJob(dir + "/job");
  changeJob(dir + "/job", [](nlohmann::json& job) { job["steps"][1]["angles"]["rotaryDegrees"] = 1e308; });
  const CliRun result = run(dir);
  expectRefusedBeforeAnythingMoves(result, {"steps[1].angles.rotaryDegrees (step 2)", "1e+308"});
  EXPECT_EQ(result.err.find("0000000000"), std::string::npos) << result.err;
}

// Issue 28: 1e999 and NaN gave "is not JSON" without the field.
TEST_F(CliRunJobChecks, ANumberNoDoubleHoldsOrNaNIsRefusedNamingItsField) {
  for (const std::string token : {"1e999", "NaN"}) {
    const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.NotFinite" + token);
    multidir::test::writeJob(dir + "/job");
    replaceInJob(dir + "/job", "\"rotaryDegrees\": 30.000000", "\"rotaryDegrees\": " + token);
    expectRefusedBeforeAnythingMoves(run(dir), {"print-job.json", "steps[1].angles.rotaryDegrees", token});
  }
}

// Issue 28: SIGHUP (the terminal closed) killed `run` without stopping anything; SIGTERM (a service manager's
// stop) must do what Ctrl-C does too.
struct StopSignal {
  const char* timeoutName;  // as `timeout -s` takes it
  const char* logName;      // as the run's log names it
};

class CliRunStopSignal : public CliRunJobChecks, public ::testing::WithParamInterface<StopSignal> {};

TEST_P(CliRunStopSignal, CancelsThePrintersJobAndSwitchesTheHeatersOffAsCtrlCDoes) {
  const std::string dir = multidir::test::scratchDirectory(std::string("CliRunJobChecks.") + GetParam().timeoutName);
  multidir::test::writeJob(dir + "/job");
  startPrinter(1.0);  // the first step prints for about half a minute
  const CliRun result = run(dir, "", std::string("timeout --preserve-status -s ") + GetParam().timeoutName + " 2");
  EXPECT_EQ(result.exitCode, 4) << result.out << result.err;
  EXPECT_NE(result.out.find(std::string(GetParam().logName) + ": stopping both devices"), std::string::npos)
      << result.out;
  EXPECT_NE(result.err.find(std::string("by ") + GetParam().logName), std::string::npos) << result.err;
  EXPECT_EQ(printerRequests("/printer/print/cancel"), 1);
  EXPECT_EQ(printer->state().jobState, "cancelled");
  EXPECT_EQ(printer->state().extruder.targetC, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Signals, CliRunStopSignal,
                         ::testing::Values(StopSignal{"HUP", "SIGHUP (the terminal closed)"},
                                           StopSignal{"TERM", "SIGTERM"}),
                         [](const ::testing::TestParamInfo<StopSignal>& info) {
                           return std::string(info.param.timeoutName);
                         });

// SIGHUP while the platform homes before the first step (from 170 degrees at 10 degrees/s): the platform stops.
TEST_F(CliRunJobChecks, SighupWhileThePlatformHomesStopsIt) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.SighupHoming");
  multidir::test::writeJob(dir + "/job");
  hw::SimulatorOptions deviceOptions;
  deviceOptions.robot = false;
  deviceOptions.rotaryInitialAngleDegrees = 170.0;
  deviceOptions.rotaryHomingSpeedDegreesPerSecond = 10.0;
  devices = std::make_unique<hw::DeviceSimulator>(deviceOptions);
  ASSERT_TRUE(devices->start().ok());
  startPrinter(200.0);
  const std::string pidFile = dir + "/pid";
  const std::string prefix = multidir::test::pidRecordingPrefix(pidFile);
  auto cli = std::async(std::launch::async, [&] { return run(dir, "", prefix); });
  const bool hungUp = multidir::test::signalCliWhen(pidFile, SIGHUP, [&] { return devices->rotaryState().homing; });
  const CliRun result = cli.get();
  ASSERT_TRUE(hungUp) << result.out << result.err;
  EXPECT_EQ(result.exitCode, 4) << result.out << result.err;
  EXPECT_NE(result.err.find("stopped by SIGHUP (the terminal closed) while homing the platform"), std::string::npos)
      << result.err;
  EXPECT_FALSE(devices->rotaryState().homing);  // the stop reached the platform
}

// Issue 28: the step files were checked before the first move, but the printer link read step-02.gcode again
// when step 2 came up: a file replaced while step 1 printed was uploaded and printed unchecked.
TEST_F(CliRunJobChecks, AStepFileReplacedAfterTheCheckIsNotUploadedAndTheRunStopsNamingIt) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.Replaced");
  multidir::test::writeJob(dir + "/job");
  startPrinter(10.0);  // step 1 prints for about 3 s: time to replace step 2's file
  auto cli = std::async(std::launch::async, [&] { return run(dir); });
  bool replaced = false;
  for (int i = 0; i < 6000 && !replaced; ++i) {  // at most 60 s
    if (printerRequests("/printer/print/start") >= 1) {
      std::ofstream(dir + "/job/step-02.gcode") << multidir::test::stepGcode(2, true);
      replaced = true;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  const CliRun result = cli.get();
  ASSERT_TRUE(replaced) << result.out << result.err;
  EXPECT_EQ(result.exitCode, 4) << result.out << result.err;
  EXPECT_NE(result.out.find("step-02.gcode changed after it was checked; nothing of it was sent"), std::string::npos)
      << result.out;
  EXPECT_EQ(printerRequests("/server/files/upload"), 1);  // step 1's only
  EXPECT_EQ(printerRequests("/printer/print/start"), 1);
}

// Issue 28: `--log /dev/full` lost the log silently.
TEST_F(CliRunJobChecks, ALogFileThatCannotBeWrittenIsReportedAtOnceAndTheRunGoesOn) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.LogFull");
  multidir::test::writeJob(dir + "/job");
  const CliRun result = run(dir, "--log /dev/full");
  EXPECT_EQ(result.exitCode, 0) << result.out << result.err;
  EXPECT_NE(result.err.find("warning: the log file /dev/full cannot be written (No space left on device): the run "
                            "goes on"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.out.find("all 2 regions printed"), std::string::npos) << result.out;
}

// Issue 28: the job's machine went through a predictable temporary file (/tmp/multidir-run-machine-<pid>.json);
// with TMPDIR naming no folder, a run that needs no temporary file still runs.
TEST_F(CliRunJobChecks, TheJobIsReadWithoutATemporaryFile) {
  const std::string dir = multidir::test::scratchDirectory("CliRunJobChecks.NoTemp");
  multidir::test::writeJob(dir + "/job");
  std::ofstream(dir + "/not-a-folder") << "x";
  const CliRun result = run(dir, "", "env TMPDIR='" + dir + "/not-a-folder' timeout 60");
  EXPECT_EQ(result.exitCode, 0) << result.out << result.err;
}

}  // namespace

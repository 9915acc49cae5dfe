// `multidir run OUT --robot HOST:PORT` and `multidir simulate --ur`: a small hand-written robot job (two steps
// of a few movel each, as `multidir robot-program` writes them) runs to its end on the UR simulator, whose trace
// shows both programs' moves; a protective stop ends the run with the robot's words.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "multidir/hardware/ur_simulator.h"
#include "multidir/robot/cell.h"
#include "multidir/robot/ur_kinematics.h"
#include "support/cli_runner.h"
#include "support/test_models.h"
#include "support/ur_test_support.h"

namespace {

using multidir::test::CliRun;
using multidir::test::runCli;
using multidir::test::urPose;
namespace robot = multidir::robot;
namespace hw = multidir::hardware;

const robot::Joints kStart{0.0, -1.2, 1.5, -1.9, -1.5707963267948966, 0.0};

// The TCP (the platform centre, 50 mm off the flange) at kStart moved by `offset` (mm).
Eigen::Isometry3d tcpAt(const Eigen::Vector3d& offset) { return multidir::test::ur5TcpAt(kStart, offset); }

// Step k: heat a little, move to the start, a square of movel in the TCP's own plane, the last at `last`.
std::string stepProgram(int k, const std::vector<Eigen::Vector3d>& corners) {
  std::string text = "def multidir_step_0" + std::to_string(k) + "():\n";
  text += "  set_tcp(p[0.0, 0.0, 0.05, 0.0, 0.0, 0.0])\n";
  text += "  set_standard_analog_out(1, 0.0900)\n";
  text += "  while get_standard_analog_in(0) < 0.0890:\n    sync()\n  end\n";
  text += "  movej([0.0, -1.2, 1.5, -1.9, -1.5707963267948966, 0.0], a=1.4, v=1.05)\n";
  text += "  textmsg(\"multidir step " + std::to_string(k) + " layer 1\")\n";
  for (const Eigen::Vector3d& c : corners) {
    text += "  set_standard_analog_out(0, 0.2500)\n";
    text += "  movel(" + urPose(tcpAt(c)) + ", a=1.2, v=0.05, r=0.0005)\n";
  }
  text += "  set_standard_analog_out(0, 0.0000)\nend\n";
  return text;
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

// A one-step job of two paths of one layer at one height that cross (docs/robot-cell.md, "Pause and resume"):
// movel 1 to A, 2 from A through C to B (the first path), 3 to D, 4 from D to C (the second path, up to the
// crossing), a sleep of `sleepSeconds` holding the arm at C, 5 on from C to E. `stepFields` follow the step's
// program in robot-job.json. Returns the sleep's line in the program.
int writeCrossingPathsJob(const std::string& dir, double sleepSeconds, const std::string& stepFields) {
  const Eigen::Vector3d a(-10, 0, 0), b(10, 0, 0), c(0, 0, 0), d(0, -10, 0), e(0, 10, 0);
  std::string text = "def multidir_step_01():\n  set_tcp(p[0.0, 0.0, 0.05, 0.0, 0.0, 0.0])\n";
  text += "  set_standard_analog_out(0, 0.0000)\n  write_output_integer_register(24, 0)\n";
  text += "  movej([0.0, -1.2, 1.5, -1.9, -1.5707963267948966, 0.0], a=1.4, v=1.05)\n";
  text += "  textmsg(\"multidir step 1 layer 1\")\n";
  const auto movel = [&](int k, const Eigen::Vector3d& to, double analog) {
    text += "  set_standard_analog_out(0, " + std::to_string(analog) + ")\n";
    text += "  write_output_integer_register(24, " + std::to_string(k) + ")\n";
    text += "  movel(" + urPose(tcpAt(to)) + ", a=1.2, v=0.01, r=0.0)\n";
  };
  movel(1, a, 0.0);
  movel(2, b, 0.25);
  movel(3, d, 0.0);
  movel(4, c, 0.25);
  text += "  sleep(" + std::to_string(sleepSeconds) + ")\n";
  movel(5, e, 0.25);
  text += "  set_standard_analog_out(0, 0.0000)\n  write_output_integer_register(24, 0)\nend\n";
  writeFile(std::filesystem::path(dir) / "step-01.script", text);
  writeFile(std::filesystem::path(dir) / "robot-job.json",
            R"({ "format": "multidir-robot-job", "version": 1, "robot": "ur5", "cell": "cell.json",
  "steps": [ { "step": 1, "program": "step-01.script")" + stepFields + " } ] }");
  writeFile(std::filesystem::path(dir) / "cell.json",
            multidir::test::readAll(std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json"));
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(text.find("sleep(")), '\n'));
}

// A robot job folder of two steps; returns the last corner of each step.
std::vector<Eigen::Vector3d> writeRobotJob(const std::string& dir) {
  const std::vector<Eigen::Vector3d> first{{20, 0, 0}, {20, 20, 0}, {0, 20, 0}};
  const std::vector<Eigen::Vector3d> second{{0, 0, 10}, {-20, 0, 10}, {-20, -20, 10}, {0, -20, 10}};
  writeFile(std::filesystem::path(dir) / "step-01.script", stepProgram(1, first));
  writeFile(std::filesystem::path(dir) / "step-02.script", stepProgram(2, second));
  writeFile(std::filesystem::path(dir) / "robot-job.json",
            R"({ "format": "multidir-robot-job", "version": 1, "robot": "ur5", "cell": "cell.json",
  "steps": [ { "step": 1, "program": "step-01.script", "seconds": 3.5, "filamentMm": 12.0, "moves": 3,
               "reachMarginMm": 40.0, "slowestJoint": 5, "slowdowns": 0 },
             { "step": 2, "program": "step-02.script", "seconds": 4.0, "filamentMm": 14.0, "moves": 4,
               "reachMarginMm": 40.0, "slowestJoint": 5, "slowdowns": 0 } ] })");
  return {first.back(), second.back()};
}

// A UR simulator on four consecutive free ports (tests/support/ur_test_support.h).
std::unique_ptr<hw::UrSimulator> startSimulator(hw::UrSimulatorOptions options) {
  return multidir::test::startUrSimulatorOnFreePorts(options, 41000);
}

TEST(CliRunRobot, ATwoStepRobotJobRunsToItsEndAndTheTraceShowsBothProgramsMoves) {
  const std::string dir = multidir::test::scratchDirectory("CliRunRobot.TwoSteps");
  const std::vector<Eigen::Vector3d> lastCorners = writeRobotJob(dir);
  hw::UrSimulatorOptions options;
  options.speed = 20.0;
  options.keepTrace = true;
  options.initialJoints = {0.0, -1.0, 1.3, -1.9, -1.5707963267948966, 0.0};
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  const CliRun run =
      runCli("run " + dir + " --robot 127.0.0.1:" + std::to_string(simulator->dashboardPort()), dir, "timeout 120");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("powering the arm on"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("robot: textmsg: multidir step 2 layer 1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("done: 2 steps printed"), std::string::npos) << run.out;
  EXPECT_EQ(simulator->state().programsFinished, 2u);
  const auto trace = simulator->trace();
  for (int k = 1; k <= 2; ++k) {
    const std::string name = "multidir_step_0" + std::to_string(k);
    const hw::UrTraceRecord* last = nullptr;
    int moving = 0;
    for (std::size_t i = 1; i < trace.size(); ++i)
      if (trace[i].program == name) {
        last = &trace[i];
        if (trace[i].tcp != trace[i - 1].tcp) ++moving;
      }
    ASSERT_NE(last, nullptr) << name;
    EXPECT_GT(moving, 100) << name;
    const Eigen::Vector3d target = tcpAt(lastCorners[static_cast<std::size_t>(k - 1)]).translation();
    EXPECT_LT((Eigen::Vector3d(last->tcp[0], last->tcp[1], last->tcp[2]) - target).norm(), 0.01) << name;
  }
}

TEST(CliRunRobot, AProtectiveStopEndsTheRunWithTheRobotsWords) {
  const std::string dir = multidir::test::scratchDirectory("CliRunRobot.ProtectiveStop");
  writeRobotJob(dir);
  hw::UrSimulatorOptions options;
  options.speed = 20.0;
  options.fault = hw::UrSimulatorFault::ProtectiveStop;
  options.faultAtLine = 12;  // step 1's second movel
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  const CliRun run =
      runCli("run " + dir + " --robot 127.0.0.1:" + std::to_string(simulator->dashboardPort()), dir, "timeout 120");
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.err.find("the run stopped at step 1: the robot reports: C153: Protective stop: the simulator's "
                         "injected fault"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("safety mode PROTECTIVE_STOP"), std::string::npos) << run.err;
  EXPECT_EQ(simulator->state().programsFinished, 0u);
}

// The paper's cell file with its platform the plan's platform region (docs/robot-cell.md, "The platform").
std::string cellForJob(const std::string& jobDir, const std::string& cellPath) {
  const std::string job = multidir::test::readAll(jobDir + "/print-job.json");
  std::smatch radius;
  if (!std::regex_search(job, radius, std::regex("\"pivot\"[^}]*\"platformRadiusMm\": *([0-9.eE+-]+)"))) return "";
  std::string cell =
      multidir::test::readAll(std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json");
  cell = std::regex_replace(cell, std::regex("\"platformRadiusMm\": *[0-9.]+"),
                            "\"platformRadiusMm\": " + radius[1].str());
  writeFile(cellPath, cell);
  return cellPath;
}

// The TCP target of the last movel in a step's program (mm; the cell's TCP is the platform centre).
Eigen::Vector3d lastMovelTarget(const std::string& script) {
  const std::size_t at = script.rfind("movel(p[");
  std::istringstream numbers(script.substr(at + 8));
  double x = 0, y = 0, z = 0;
  char comma = 0;
  numbers >> x >> comma >> y >> comma >> z;
  return Eigen::Vector3d(x, y, z) * 1000.0;
}

// The kitten (half size, 5-DOF) decomposed, sliced with the cell's profile, converted by 'multidir
// robot-program' and run by 'multidir run --robot' on the simulated UR5 of the paper's cell at 1000 times real
// time, in the scratch folder `scratch`; the simulator (with its trace) stays for the test to read.
struct KittenOnTheCell {
  std::string dir;
  std::string cellPath;
  std::unique_ptr<hw::UrSimulator> simulator;
};

// How many step programs the kitten's converted job has (the plan's region count: the search decides it).
unsigned stepProgramCount(const KittenOnTheCell& kitten) {
  unsigned count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kitten.dir + "/out")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("step-", 0) == 0 && entry.path().extension() == ".script") ++count;
  }
  return count;
}

// Step k's programs in the converted job (robot-job.json's parts: more than one when the step is above the cell's
// maxProgramBytes), in the order they run.
std::vector<std::string> stepPartFiles(const std::string& outDir, int k) {
  const auto job = nlohmann::json::parse(multidir::test::readAll(outDir + "/robot-job.json"));
  std::vector<std::string> files;
  for (const auto& part : job["steps"][static_cast<std::size_t>(k - 1)]["parts"])
    files.push_back(outDir + "/" + part["program"].get<std::string>());
  return files;
}

// Step k's programs' text one after another (the step as the robot runs it).
std::string stepScript(const std::string& outDir, int k) {
  std::string text;
  for (const std::string& file : stepPartFiles(outDir, k)) text += multidir::test::readAll(file);
  return text;
}

// The kitten's job converted for the cell and the simulator started (1000 times real time, its trace kept).
void prepareKittenOnTheCell(const std::string& scratch, KittenOnTheCell& kitten) {
  const std::string dir = multidir::test::scratchDirectory(scratch);
  kitten.dir = dir;
  ASSERT_EQ(runCli("decompose '" + multidir::test::sharedModelPath("kitten.off") +
                       "' --up y --scale 0.5 --machine 5dof -o " + dir + "/plan",
                   dir)
                .exitCode,
            0);
  const CliRun sliced = runCli("slice " + dir + "/plan --printer ur5-cell-0.8 -o " + dir + "/job", dir);
  ASSERT_EQ(sliced.exitCode, 0) << sliced.err;
  kitten.cellPath = cellForJob(dir + "/job", dir + "/cell.json");
  ASSERT_FALSE(kitten.cellPath.empty());
  const CliRun converted =
      runCli("robot-program " + dir + "/job --cell " + kitten.cellPath + " -o " + dir + "/out", dir);
  ASSERT_EQ(converted.exitCode, 0) << converted.err;
  hw::UrSimulatorOptions options;
  options.speed = 1000.0;
  options.keepTrace = true;
  options.cellPath = kitten.cellPath;
  kitten.simulator = startSimulator(options);
  ASSERT_TRUE(kitten.simulator);
}

void runKittenOnTheCell(const std::string& scratch, KittenOnTheCell& kitten) {
  ASSERT_NO_FATAL_FAILURE(prepareKittenOnTheCell(scratch, kitten));
  const std::string& dir = kitten.dir;
  const CliRun run = runCli(
      "run " + dir + "/out --robot 127.0.0.1:" + std::to_string(kitten.simulator->dashboardPort()), dir, "timeout 240");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
}

// The kitten's converted job runs on the cell's arm without a joint beyond its limits or its speed, and each
// step's program ends where its last movel says.
TEST(CliRunRobot, TheKittensConvertedJobRunsOnTheCellsArmWithinItsJointLimits) {
  KittenOnTheCell kitten;
  ASSERT_NO_FATAL_FAILURE(runKittenOnTheCell("CliRunRobot.Kitten", kitten));
  const std::string& dir = kitten.dir;
  const std::string& cellPath = kitten.cellPath;
  const std::unique_ptr<hw::UrSimulator>& simulator = kitten.simulator;
  EXPECT_EQ(simulator->state().programsFinished, stepProgramCount(kitten));
  const robot::ArmModel arm = robot::loadCell(cellPath)->arm;
  const auto trace = simulator->trace();
  for (std::size_t k = 1; k < trace.size(); ++k) {
    const double dt = trace[k].time - trace[k - 1].time;
    if (dt > 0.0081) continue;  // not consecutive ticks (between two programs)
    for (std::size_t j = 0; j < 6; ++j) {
      ASSERT_LE(std::abs(trace[k].joints[j] - trace[k - 1].joints[j]) / dt, arm.limits[j].maxSpeedRadPerS)
          << "joint " << j + 1 << " at " << trace[k].time << " s";
      ASSERT_GE(trace[k].joints[j], arm.limits[j].minRad);
      ASSERT_LE(trace[k].joints[j], arm.limits[j].maxRad);
    }
  }
  const auto job = nlohmann::json::parse(multidir::test::readAll(dir + "/out/robot-job.json"));
  const int steps = static_cast<int>(job["steps"].size());
  ASSERT_GE(steps, 2);
  for (int step = 1; step <= steps; ++step) {
    const std::string name = "multidir_step_0" + std::to_string(step);
    // The step's last program (its parts share the step's name) ends with the joint moves home.
    const std::string script = multidir::test::readAll(stepPartFiles(dir + "/out", step).back());
    // The tick the last movel ends in is the first one traced at the statement after it (the first movej on the
    // way home: to its first via point, or home), which carries the rest of that tick into the movej: at most 8 ms
    // from rest at 1.4 rad/s^2, 45 urad, under 0.05 mm at the platform (the movel's own end is checked to 0.01 mm
    // in UrController's test).
    const std::size_t wayHome = script.find("movej(", script.rfind("movel("));
    const int homeLine =
        1 + static_cast<int>(std::count(script.begin(), script.begin() + static_cast<long>(wayHome), '\n'));
    // Its first tick: the last run of ticks at that line of the step's programs (an earlier part's same line is
    // another statement).
    const hw::UrTraceRecord* ended = nullptr;
    for (std::size_t i = trace.size(); i-- > 0;) {
      const bool atHome = trace[i].program == name && trace[i].line == homeLine;
      if (atHome) ended = &trace[i];
      else if (ended != nullptr) break;
    }
    ASSERT_NE(ended, nullptr) << name << " line " << homeLine;
    const Eigen::Vector3d target = lastMovelTarget(script);
    EXPECT_LT((Eigen::Vector3d(ended->tcp[0], ended->tcp[1], ended->tcp[2]) - target).norm(), 0.05) << name;
  }
}

// The filament the extruder really pushes (its commanded speed over the simulated arm's own time, tick by tick)
// is the G-code's E of each step: the extrusion rate follows the moves as the controller runs them.
TEST(CliRunRobot, TheExtruderPushesEachStepsGcodeFilamentWhileTheArmRunsItsProgram) {
  KittenOnTheCell kitten;
  ASSERT_NO_FATAL_FAILURE(runKittenOnTheCell("CliRunRobot.KittenFilament", kitten));
  const std::string& dir = kitten.dir;
  const std::unique_ptr<hw::UrSimulator>& simulator = kitten.simulator;
  const auto job = nlohmann::json::parse(multidir::test::readAll(dir + "/out/robot-job.json"));
  const auto trace = simulator->trace();
  ASSERT_FALSE(trace.empty());
  ASSERT_TRUE(trace.front().hasCell);
  for (std::size_t step = 0; step < job["steps"].size(); ++step) {
    const std::string name = "multidir_step_0" + std::to_string(step + 1);
    double pushed = 0.0;
    for (std::size_t k = 1; k < trace.size(); ++k)
      if (trace[k].program == name) pushed += trace[k].filamentMmPerS * (trace[k].time - trace[k - 1].time);
    const double gcode = job["steps"][step]["gcodeFilamentMm"].get<double>();
    ASSERT_GT(gcode, 0.0) << name;
    std::cout << "[ measured ] " << name << ": extruder pushed " << pushed << " mm, G-code E " << gcode << " mm\n";
    EXPECT_NEAR(pushed / gcode, 1.0, 0.005) << name;
  }
}

// Ctrl-C while a step's program moves the arm: the run stops the program (the dashboard's stop, latched until
// the robot's state confirms it) and says where it stopped; the arm is at rest and nothing else is sent.
TEST(CliRunRobot, CtrlCStopsTheProgramAndWaitsForTheRobotToConfirmIt) {
  const std::string dir = multidir::test::scratchDirectory("CliRunRobot.CtrlC");
  writeRobotJob(dir);
  hw::UrSimulatorOptions options;
  options.speed = 1.0;  // real time: the signal lands while the arm moves
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  const std::string pidFile = dir + "/pid";
  const std::string prefix = multidir::test::pidRecordingPrefix(pidFile);
  auto cli = std::async(std::launch::async, [&] {
    return runCli("run " + dir + " --robot 127.0.0.1:" + std::to_string(simulator->dashboardPort()), dir, prefix);
  });
  const bool interrupted = multidir::test::signalCliWhen(pidFile, SIGINT, [&] {
    const hw::UrSimulatorState s = simulator->state();
    return s.programName == "multidir_step_01" && s.programState == "PLAYING" && !s.atRest;
  });
  const CliRun run = cli.get();
  ASSERT_TRUE(interrupted) << run.out << run.err;
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.out.find("the robot confirmed the stop"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("the run stopped at step 1: stopped by Ctrl-C"), std::string::npos) << run.err;
  const hw::UrSimulatorState s = simulator->state();
  EXPECT_EQ(s.programState, "STOPPED");
  EXPECT_TRUE(s.atRest);
  EXPECT_EQ(s.programsFinished, 0u);
  EXPECT_EQ(simulator->programsReceived().size(), 1u);  // step 2 never went out
  bool stopSent = false;
  for (const hw::UrDashboardRecord& record : simulator->dashboardLog())
    stopSent = stopSent || (record.command == "stop" && record.reply == "Stopped");
  EXPECT_TRUE(stopSent);
}

// A step's program read as its movel: the nozzle's point in the platform's (the part's) frame at each movel's
// end, and whether the extruder runs during the movel (analog out 0 in effect above 0).
struct NozzleSegment {
  Eigen::Vector3d from, to;
  bool extrudes;
  double tickTravelMm;  // the most the nozzle moves along it in two 8 ms ticks of the controller, plus 0.05 mm
};

std::vector<NozzleSegment> nozzleSegments(const std::string& script, const Eigen::Vector3d& nozzleTipMm) {
  std::vector<NozzleSegment> segments;
  std::istringstream lines(script);
  double analog0 = 0.0;
  bool first = true;
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  for (std::string line; std::getline(lines, line);) {
    if (line.find("set_standard_analog_out(0, ") != std::string::npos)
      analog0 = std::stod(line.substr(line.find("(0, ") + 4));
    const std::size_t at = line.find("movel(p[");
    if (at == std::string::npos) continue;
    std::string numbers = line.substr(at + 8, line.find(']') - at - 8);
    std::replace(numbers.begin(), numbers.end(), ',', ' ');
    std::istringstream in(numbers);
    double v[6];
    for (double& x : v) in >> x;
    const Eigen::Vector3d rv(v[3], v[4], v[5]);
    Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();
    if (rv.norm() > 0.0) tcp.linear() = Eigen::AngleAxisd(rv.norm(), rv.normalized()).toRotationMatrix();
    tcp.translation() = Eigen::Vector3d(v[0], v[1], v[2]) * 1000.0;
    const Eigen::Vector3d nozzle = tcp.inverse() * nozzleTipMm;
    const double speedMmPerS = 1000.0 * std::stod(line.substr(line.find(", v=") + 4));
    if (!first) segments.push_back({previous, nozzle, analog0 > 0.0, speedMmPerS * 0.016 + 0.05});
    first = false;
    previous = nozzle;
  }
  return segments;
}

// Ctrl-Z mid-step: the arm finishes the move under way, the extruder stops and the platform backs off the nozzle,
// and then the arm stays still with the extruder off; Ctrl-Z again: the step goes on from the next move. Every
// tick the simulated extruder ran in step 2 (its program, the pause's, the resumed one) puts the nozzle within
// 0.05 mm of one of the step's extrusion moves, in the program's order and never back along it (no duplicate),
// and every extrusion move is covered from its start to its end with no jump along it longer than two ticks'
// travel (no gap; a tick that ends one statement carries the rest of its time into the next).
TEST(CliRunRobot, PauseMidStepHoldsTheArmWithTheExtruderOffAndResumeLeavesNoGapOrDuplicate) {
  KittenOnTheCell kitten;
  ASSERT_NO_FATAL_FAILURE(prepareKittenOnTheCell("CliRunRobot.PauseResume", kitten));
  hw::UrSimulator& simulator = *kitten.simulator;
  // Step 2 is above the cell's maxProgramBytes: the pause is asked for in its second program, once the first ended.
  const std::vector<std::string> step2Parts = stepPartFiles(kitten.dir + "/out", 2);
  ASSERT_GE(step2Parts.size(), 2u);
  const std::size_t step1Parts = stepPartFiles(kitten.dir + "/out", 1).size();
  const std::string script = stepScript(kitten.dir + "/out", 2);
  const std::string part2 = multidir::test::readAll(step2Parts[1]);
  const int firstMovelLine =
      1 + static_cast<int>(std::count(part2.begin(), part2.begin() + static_cast<long>(part2.find("movel(")), '\n'));
  const std::string pidFile = kitten.dir + "/pid";
  const std::string prefix = multidir::test::pidRecordingPrefix(pidFile, 240);
  auto cli = std::async(std::launch::async, [&] {
    return runCli("run " + kitten.dir + "/out --robot 127.0.0.1:" + std::to_string(simulator.dashboardPort()),
                  kitten.dir, prefix);
  });
  const bool pauseSent = multidir::test::signalCliWhen(pidFile, SIGTSTP, [&] {
    const hw::UrSimulatorState s = simulator.state();
    return s.programName == "multidir_step_02" && s.programState == "PLAYING" && s.programsFinished == step1Parts + 1 &&
           s.line > firstMovelLine + 200;
  });
  ASSERT_TRUE(pauseSent);
  bool pausedStill = false;
  for (int wait = 0; wait < 3000 && !pausedStill; ++wait) {
    const hw::UrSimulatorState s = simulator.state();
    pausedStill = s.programName == "multidir_pause" && s.programState == "STOPPED" && s.atRest;
    if (!pausedStill) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(pausedStill);
  const hw::UrSimulatorState paused = simulator.state();
  EXPECT_EQ(paused.analogOut[0], 0.0);  // the extruder off
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // 300 s of the simulated cell
  const hw::UrSimulatorState later = simulator.state();
  EXPECT_GT(later.time, paused.time + 100.0);
  EXPECT_EQ(later.joints, paused.joints);  // the arm still
  EXPECT_TRUE(later.atRest);
  EXPECT_EQ(later.analogOut[0], 0.0);
  EXPECT_EQ(later.programState, "STOPPED");
  EXPECT_TRUE(multidir::test::signalCliWhen(pidFile, SIGTSTP, [] { return true; }));
  const CliRun run = cli.get();
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("paused at a safe point: step 2 after movel "), std::string::npos) << run.out;
  // Asked for in the step's second program; at 1000 times real time a program lasts tens of milliseconds, so
  // the pause lands in that one or one soon after it: never in the first.
  std::smatch inProgram;
  ASSERT_TRUE(std::regex_search(run.out, inProgram, std::regex("after movel [0-9]+ of [0-9]+ in program ([0-9]+) of " +
                                                                   std::to_string(step2Parts.size()))))
      << run.out;
  EXPECT_GE(std::stoi(inProgram[1].str()), 2) << run.out;
  EXPECT_NE(run.out.find("resuming step 2 after movel "), std::string::npos) << run.out;
  // Every program but the paused one whole, the pause, and the paused program's resumed rest.
  EXPECT_EQ(simulator.state().programsFinished, stepProgramCount(kitten) + 1) << run.out;
  // Where the pause landed: movel k of the program is segment k - 2 (the first movel comes from the approach).
  const std::size_t landed = run.out.find("paused at a safe point: step 2 after movel ");
  const int pausedMovel = landed == std::string::npos ? 0 : std::atoi(run.out.c_str() + landed + 43);

  const Eigen::Vector3d tip = robot::loadCell(kitten.cellPath)->nozzleTipMm;
  const std::vector<NozzleSegment> segments = nozzleSegments(script, tip);
  std::vector<double> reachedFrom(segments.size(), 1e9), reachedTo(segments.size(), -1e9);
  std::size_t at = 0;
  double along = 0.0;
  int extruding = 0;
  const auto trace = simulator.trace();
  for (std::size_t k = 1; k < trace.size(); ++k) {
    const hw::UrTraceRecord& r = trace[k];
    if (r.filamentMmPerS <= 0.0) continue;
    if (r.program != "multidir_step_02" && r.program != "multidir_pause") continue;
    const Eigen::Vector3d p(r.nozzleInPlatform[0], r.nozzleInPlatform[1], r.nozzleInPlatform[2]);
    ++extruding;
    bool placed = false;
    for (std::size_t i = at; i < segments.size() && !placed; ++i) {
      if (!segments[i].extrudes) continue;
      const Eigen::Vector3d d = segments[i].to - segments[i].from;
      const double length = d.norm();
      const double t = length > 0.0 ? std::clamp((p - segments[i].from).dot(d) / (length * length), 0.0, 1.0) : 0.0;
      if ((segments[i].from + t * d - p).norm() > 0.05) continue;
      if (i == at && t * length < along - 0.05) continue;  // back along the move: a duplicate
      placed = true;
      if (i == at && reachedTo[i] > -1.0) {
        EXPECT_LE(t * length - along, segments[i].tickTravelMm)
            << "a gap along extrusion move " << i + 1 << " at " << r.time << " s (" << r.program << " line " << r.line
            << ")";
      }
      at = i;
      along = t * length;
      reachedFrom[i] = std::min(reachedFrom[i], along);
      reachedTo[i] = std::max(reachedTo[i], along);
    }
    ASSERT_TRUE(placed) << "tick at " << r.time << " s (" << r.program << " line " << r.line << "): the nozzle at ("
                        << p.transpose() << ") on no extrusion move at or after move " << at + 1;
  }
  EXPECT_GT(extruding, 1000);
  ASSERT_GE(pausedMovel, 2);
  const NozzleSegment& pausedIn = segments[static_cast<std::size_t>(pausedMovel - 2)];
  std::cout << "[ measured ] paused in movel " << pausedMovel << " of step 2, "
            << (pausedIn.extrudes ? "an extrusion" : "a travel") << " of " << (pausedIn.to - pausedIn.from).norm()
            << " mm\n";
  // Each extrusion move reached from near its start to near its end: within two ticks' travel at its speed. A
  // move shorter than that can begin and end between two ticks.
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (!segments[i].extrudes) continue;
    const double length = (segments[i].to - segments[i].from).norm();
    const double tick = segments[i].tickTravelMm;
    if (length < tick) continue;
    EXPECT_LE(reachedFrom[i], tick) << "extrusion move " << i + 1 << " of " << segments.size();
    EXPECT_GE(reachedTo[i], length - tick) << "extrusion move " << i + 1 << " of " << segments.size();
  }
}

// The kitten's job, its steps split into programs the controller accepts (the cell's maxProgramBytes), runs to its
// end with every tick the simulated extruder runs putting the nozzle within 0.05 mm of one of its step's extrusion
// moves (the programs' movels, which KittenRobotProgram checks against the G-code), in order: a part boundary
// neither skips nor repeats a move; and every extrusion move is reached from near its start to near its end.
TEST(CliRunRobot, TheKittensSplitStepsPrintTheirExtrusionMovesAcrossPartBoundaries) {
  KittenOnTheCell kitten;
  ASSERT_NO_FATAL_FAILURE(runKittenOnTheCell("CliRunRobot.KittenSplitPath", kitten));
  const std::string out = kitten.dir + "/out";
  const auto job = nlohmann::json::parse(multidir::test::readAll(out + "/robot-job.json"));
  const Eigen::Vector3d tip = robot::loadCell(kitten.cellPath)->nozzleTipMm;
  const auto trace = kitten.simulator->trace();
  std::size_t splitSteps = 0;
  for (std::size_t k = 1; k <= job["steps"].size(); ++k) {
    const int step = static_cast<int>(k);
    splitSteps += stepPartFiles(out, step).size() > 1 ? 1 : 0;
    std::cout << "[ measured ] step " << step << ": " << stepPartFiles(out, step).size() << " program(s)\n";
    const std::vector<NozzleSegment> segments = nozzleSegments(stepScript(out, step), tip);
    const std::string name = "multidir_step_0" + std::to_string(step);
    std::vector<double> reachedFrom(segments.size(), 1e9), reachedTo(segments.size(), -1e9);
    std::size_t at = 0;
    double along = 0.0;
    for (const hw::UrTraceRecord& r : trace) {
      if (r.filamentMmPerS <= 0.0 || r.program != name) continue;
      const Eigen::Vector3d p(r.nozzleInPlatform[0], r.nozzleInPlatform[1], r.nozzleInPlatform[2]);
      bool placed = false;
      for (std::size_t i = at; i < segments.size() && !placed; ++i) {
        if (!segments[i].extrudes) continue;
        const Eigen::Vector3d d = segments[i].to - segments[i].from;
        const double length = d.norm();
        const double t = length > 0.0 ? std::clamp((p - segments[i].from).dot(d) / (length * length), 0.0, 1.0) : 0.0;
        if ((segments[i].from + t * d - p).norm() > 0.05) continue;
        // Back along the move it is on: the next move turning back over it (infill's zigzag).
        if (i == at && t * length < along - 0.05) continue;
        placed = true;
        at = i;
        along = t * length;
        reachedFrom[i] = std::min(reachedFrom[i], t * length);
        reachedTo[i] = std::max(reachedTo[i], t * length);
      }
      ASSERT_TRUE(placed) << name << " tick at " << r.time << " s (line " << r.line << "): the nozzle at ("
                          << p.transpose() << ") on no extrusion move at or after move " << at + 1;
    }
    for (std::size_t i = 0; i < segments.size(); ++i) {
      if (!segments[i].extrudes) continue;
      const double length = (segments[i].to - segments[i].from).norm();
      if (length < segments[i].tickTravelMm) continue;
      EXPECT_LE(reachedFrom[i], segments[i].tickTravelMm) << name << " extrusion move " << i + 1;
      EXPECT_GE(reachedTo[i], length - segments[i].tickTravelMm) << name << " extrusion move " << i + 1;
    }
  }
  EXPECT_GE(splitSteps, 1u);
  EXPECT_EQ(kitten.simulator->state().programsFinished, stepProgramCount(kitten));
}

// A program above what the controller compiles (the simulator's bound set below a step's second program): the
// controller refuses it with a compile error, and the run stops saying so in the robot's words with the step and
// the program of the step it sent.
TEST(CliRunRobot, AProgramAboveTheControllersBoundEndsTheRunNamingTheStepAndItsProgram) {
  const std::string dir = multidir::test::scratchDirectory("CliRunRobot.ProgramTooLarge");
  std::string first = stepProgram(1, {{20, 0, 0}, {20, 20, 0}});
  std::string second = "def multidir_step_01():\n  set_tcp(p[0.0, 0.0, 0.05, 0.0, 0.0, 0.0])\n";
  for (int i = 0; i < 60; ++i) second += "  # a line that makes the program larger than the controller takes\n";
  second += "  set_standard_analog_out(0, 0.2500)\n  movel(" + urPose(tcpAt({0, 20, 0})) + ", a=1.2, v=0.05, r=0.0)\n";
  second += "  set_standard_analog_out(0, 0.0000)\nend\n";
  writeFile(std::filesystem::path(dir) / "step-01-part-001.script", first);
  writeFile(std::filesystem::path(dir) / "step-01-part-002.script", second);
  writeFile(std::filesystem::path(dir) / "robot-job.json",
            R"({ "format": "multidir-robot-job", "version": 2, "robot": "ur5", "cell": "cell.json",
  "steps": [ { "step": 1, "program": "step-01-part-001.script", "seconds": 5.0,
               "parts": [ { "program": "step-01-part-001.script" }, { "program": "step-01-part-002.script" } ] } ] })");
  ASSERT_LT(first.size(), 2500u);
  ASSERT_GT(second.size(), 2500u);
  hw::UrSimulatorOptions options;
  options.speed = 20.0;
  options.maxProgramBytes = 2500;
  options.initialJoints = {0.0, -1.0, 1.3, -1.9, -1.5707963267948966, 0.0};
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  const CliRun run =
      runCli("run " + dir + " --robot 127.0.0.1:" + std::to_string(simulator->dashboardPort()), dir, "timeout 120");
  EXPECT_NE(run.exitCode, 0) << run.out << run.err;
  EXPECT_NE(run.err.find("the run stopped at step 1: the robot reports: "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("Compile error: the program is " + std::to_string(second.size()) + " bytes, above the 2500"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("(in step-01-part-002.script, program 2 of 2 of the step)"), std::string::npos) << run.err;
  EXPECT_EQ(simulator->state().programsFinished, 1u);  // the first program ran; the second never started
}

// A protective stop in a step's second program: the first ran to its end, the second was sent after it, and the
// run stops with the robot's words naming that program of the step.
TEST(CliRunRobot, AProtectiveStopInAStepsSecondProgramEndsTheRunNamingThatProgram) {
  const std::string dir = multidir::test::scratchDirectory("CliRunRobot.ProtectiveStopInPart2");
  const std::string first = stepProgram(1, {{20, 0, 0}});  // 12 lines
  std::string second = "def multidir_step_01():\n  set_tcp(p[0.0, 0.0, 0.05, 0.0, 0.0, 0.0])\n";
  for (int i = 0; i < 10; ++i)
    second += "  set_standard_analog_out(0, 0.2500)\n  movel(" + urPose(tcpAt({20.0 - 2.0 * i, 2.0 * i, 0})) +
              ", a=1.2, v=0.05, r=0.0)\n";
  second += "  set_standard_analog_out(0, 0.0000)\nend\n";
  writeFile(std::filesystem::path(dir) / "step-01-part-001.script", first);
  writeFile(std::filesystem::path(dir) / "step-01-part-002.script", second);
  writeFile(std::filesystem::path(dir) / "robot-job.json",
            R"({ "format": "multidir-robot-job", "version": 2, "robot": "ur5", "cell": "cell.json",
  "steps": [ { "step": 1, "program": "step-01-part-001.script", "seconds": 5.0,
               "parts": [ { "program": "step-01-part-001.script" }, { "program": "step-01-part-002.script" } ] } ] })");
  hw::UrSimulatorOptions options;
  options.speed = 20.0;
  options.fault = hw::UrSimulatorFault::ProtectiveStop;
  options.faultAtLine = 16;  // the second program's seventh movel; the first has 12 lines
  options.initialJoints = {0.0, -1.0, 1.3, -1.9, -1.5707963267948966, 0.0};
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  const CliRun run =
      runCli("run " + dir + " --robot 127.0.0.1:" + std::to_string(simulator->dashboardPort()), dir, "timeout 120");
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.err.find("the run stopped at step 1: the robot reports: C153: Protective stop"), std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("(in step-01-part-002.script, program 2 of 2 of the step)"), std::string::npos) << run.err;
  EXPECT_EQ(simulator->state().programsFinished, 1u);
  EXPECT_EQ(simulator->programsReceived().size(), 2u);
}

// Ctrl-C while paused: the run ends with the stop latched until the robot confirms it, and nothing more is sent
// (the step's program and the pause's only).
TEST(CliRunRobot, CtrlCWhilePausedStopsTheRunOnceTheRobotConfirmsTheStop) {
  const std::string dir = multidir::test::scratchDirectory("CliRunRobot.CtrlCWhilePaused");
  writeRobotJob(dir);
  writeFile(std::filesystem::path(dir) / "cell.json",
            multidir::test::readAll(std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json"));
  hw::UrSimulatorOptions options;
  options.speed = 1.0;  // real time: the pause lands while the arm moves
  options.initialJoints = {0.0, -1.0, 1.3, -1.9, -1.5707963267948966, 0.0};
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  const std::string pidFile = dir + "/pid";
  const std::string prefix = multidir::test::pidRecordingPrefix(pidFile);
  auto cli = std::async(std::launch::async, [&] {
    return runCli("run " + dir + " --robot 127.0.0.1:" + std::to_string(simulator->dashboardPort()), dir, prefix);
  });
  const bool pauseSent = multidir::test::signalCliWhen(pidFile, SIGTSTP, [&] {
    const hw::UrSimulatorState s = simulator->state();
    return s.programName == "multidir_step_01" && s.programState == "PLAYING" && s.line >= 11 && !s.atRest;
  });
  const bool stopSent = multidir::test::signalCliWhen(pidFile, SIGINT, [&] {
    const hw::UrSimulatorState s = simulator->state();
    return s.programName == "multidir_pause" && s.programState == "STOPPED" && s.atRest;
  });
  const CliRun run = cli.get();
  ASSERT_TRUE(pauseSent) << run.out << run.err;
  ASSERT_TRUE(stopSent) << run.out << run.err;
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.out.find("paused at a safe point: step 1 after movel "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("the robot confirmed the stop"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("the run stopped at step 1: stopped by Ctrl-C while paused"), std::string::npos) << run.err;
  EXPECT_EQ(simulator->programsReceived().size(), 2u);
  EXPECT_TRUE(simulator->state().atRest);
  EXPECT_EQ(simulator->state().analogOut[0], 0.0);
}

// Two paths of one layer at one height that cross, the pause landing on the second right where it crosses the
// first (the arm holds there in a sleep of the program, so the pause lands there every run): the pause names the
// move the robot says it runs (its movel register), not the first move of the layer that passes there. Naming
// the first, the resumed program printed everything between the two again (docs/robot-cell.md, "Pause and
// resume").
TEST(CliRunRobot, APauseWhereTwoPathsOfALayerCrossNamesTheMoveTheRobotRunsNotTheFirstThatPassesThere) {
  const std::string dir = multidir::test::scratchDirectory("CliRunRobot.PauseOnCrossingPaths");
  const int sleepLine = writeCrossingPathsJob(dir, 60.0,
                                              R"(, "seconds": 70.0, "filamentMm": 12.0, "moves": 5, )"
                                              R"("reachMarginMm": 40.0, "slowestJoint": 5, "slowdowns": 0)");
  const Eigen::Vector3d d(0, -10, 0), e(0, 10, 0);
  hw::UrSimulatorOptions options;
  options.speed = 10.0;
  options.initialJoints = {0.0, -1.2, 1.5, -1.9, -1.5707963267948966, 0.0};
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  const std::string pidFile = dir + "/pid";
  const std::string prefix = multidir::test::pidRecordingPrefix(pidFile, 120);
  auto cli = std::async(std::launch::async, [&] {
    return runCli("run " + dir + " --robot 127.0.0.1:" + std::to_string(simulator->dashboardPort()), dir, prefix);
  });
  // Held at C on the second path, the first passing 0 mm away.
  const bool pauseSent = multidir::test::signalCliWhen(pidFile, SIGTSTP, [&] {
    const hw::UrSimulatorState s = simulator->state();
    return s.programName == "multidir_step_01" && s.programState == "PLAYING" && s.line == sleepLine && s.atRest;
  });
  const bool resumeSent = multidir::test::signalCliWhen(pidFile, SIGTSTP, [&] {
    const hw::UrSimulatorState s = simulator->state();
    return s.programName == "multidir_pause" && s.programState == "STOPPED" && s.atRest;
  });
  const CliRun run = cli.get();
  ASSERT_TRUE(pauseSent) << run.out << run.err;
  ASSERT_TRUE(resumeSent) << run.out << run.err;
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("paused at a safe point: step 1 after movel 4 of 5"), std::string::npos) << run.out;
  // The resumed program goes on with the sleep and movel 5; movel 3 (to D, after the first path) is not run again.
  const std::vector<std::string> programs = simulator->programsReceived();
  ASSERT_EQ(programs.size(), 3u);
  EXPECT_EQ(programs[2].find(urPose(tcpAt(d))), std::string::npos) << programs[2];
  EXPECT_NE(programs[2].find(urPose(tcpAt(e))), std::string::npos) << programs[2];
}

// The same crossing paths run through, the arm held at the crossing: the progress names the movel the robot says
// it runs (its register), 4, while it is held there, never the first path's movel 2 that passes there too; the
// movels the progress names only go forward.
TEST(CliRunRobot, TheProgressAtCrossingPathsNamesTheMoveTheRobotRuns) {
  const std::string dir = multidir::test::scratchDirectory("CliRunRobot.ProgressOnCrossingPaths");
  writeCrossingPathsJob(dir, 40.0, R"(, "seconds": 50.0)");
  hw::UrSimulatorOptions options;
  options.speed = 10.0;
  options.initialJoints = {0.0, -1.2, 1.5, -1.9, -1.5707963267948966, 0.0};
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  const CliRun run =
      runCli("run " + dir + " --robot 127.0.0.1:" + std::to_string(simulator->dashboardPort()), dir, "timeout 120");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  std::vector<int> named;
  const std::regex progress("progress: step 1/1 [A-Z]+ [0-9]+ %, movel ([0-9]+) of 5");
  for (std::sregex_iterator i(run.out.begin(), run.out.end(), progress), end; i != end; ++i)
    named.push_back(std::stoi((*i)[1].str()));
  EXPECT_NE(std::find(named.begin(), named.end(), 4), named.end()) << run.out;
  EXPECT_TRUE(std::is_sorted(named.begin(), named.end())) << run.out;
}

TEST(CliRunRobot, AnUnknownArmModelIsAUsageErrorNamingTheKnownOnes) {
  const std::string dir = multidir::test::scratchDirectory("CliRunRobot.UnknownModel");
  const CliRun run = runCli("simulate --ur ur7 --port 0", dir, "timeout -s INT 5");
  EXPECT_EQ(run.exitCode, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("ur5"), std::string::npos) << run.err;
}

TEST(CliRunRobot, SimulateUrPrintsItsThreePortsAndStopsOnSigint) {
  const std::string dir = multidir::test::scratchDirectory("CliRunRobot.SimulatePorts");
  const CliRun run = runCli("simulate --ur ur5e --port 0", dir, "timeout --preserve-status -s INT 1");
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("UR controller simulator (ur5e) on 127.0.0.1: dashboard "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("robot: POWER_OFF, safety NORMAL, program STOPPED"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("Simulator stopped."), std::string::npos) << run.out;
}

}  // namespace

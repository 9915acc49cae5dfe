// The Hardware dock's robot cell section (issue 25, item 5; docs/hardware.md, "The robot cell section")
// against the UR simulator on 127.0.0.1: a small robot job (two steps of movel, as `multidir
// robot-program` writes them, with the paper's cell as its cell.json) run from the dock as an operator would,
// outcomes read from the section's labels, the job timeline and the simulator's own record.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTest>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "multidir/hardware/robot_run.h"
#include "multidir/hardware/ur_simulator.h"
#include "multidir/robot/cell.h"
#include "multidir/robot/cell_file.h"
#include "multidir/robot/ur_kinematics.h"
#include "support/test_models.h"
#include "support/ur_test_support.h"
#include "ui/device/hardware_panel.h"
#include "ui/device/job_timeline.h"
#include "ui/device/robot_cell_section.h"
#include "ui/document/studio_document.h"
#include "ui/main_window.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

namespace fs = std::filesystem;
namespace hw = hardware;
using multidir::test::urPose;

constexpr int kRunMs = 120000;  // a guard against a hang under a busy ctest, not a limit checked

const robot::Joints kStart{0.0, -1.2, 1.5, -1.9, -1.5707963267948966, 0.0};
const fs::path kCellFile = fs::path(MULTIDIR_SOURCE_DIR) / "resources" / "cells" / "ur5-fixed-extruder.json";

// The TCP (the platform centre, 50 mm off the flange) at kStart moved by `offset` (mm).
Eigen::Isometry3d tcpAt(const Eigen::Vector3d& offset) { return multidir::test::ur5TcpAt(kStart, offset); }

// Step k: to the start by a joint move, then extrusions along `corners` at `speed` (m/s), as robot-program
// writes them (a layer message first, the extruder's rate before each movel).
std::string stepProgram(int k, const std::vector<Eigen::Vector3d>& corners, double speed) {
  std::string text = "def multidir_step_0" + std::to_string(k) + "():\n";
  text += "  set_tcp(p[0.0, 0.0, 0.05, 0.0, 0.0, 0.0])\n";
  text += "  movej([0.0, -1.2, 1.5, -1.9, -1.5707963267948966, 0.0], a=1.4, v=1.05)\n";
  text += "  textmsg(\"multidir step " + std::to_string(k) + " layer 1\")\n";
  for (const Eigen::Vector3d& c : corners) {
    text += "  set_standard_analog_out(0, 0.2500)\n";
    char params[64];
    std::snprintf(params, sizeof params, ", a=1.2, v=%.6f, r=0.0000)\n", speed);
    text += "  movel(" + urPose(tcpAt(c)) + params;
  }
  text += "  set_standard_analog_out(0, 0.0000)\nend\n";
  return text;
}

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

// A robot job folder of two steps with `cell` as its cell.json; `speed` the movels' (m/s).
std::string writeRobotJob(const std::string& name, double speed, const fs::path& cell = kCellFile) {
  const std::string dir = test::scratchDirectory(name);
  const std::vector<Eigen::Vector3d> first{{20, 0, 0}, {20, 20, 0}, {0, 20, 0}, {0, 0, 0}};
  const std::vector<Eigen::Vector3d> second{{0, 0, 10}, {-20, 0, 10}, {-20, -20, 10}, {0, -20, 10}};
  writeFile(fs::path(dir) / "step-01.script", stepProgram(1, first, speed));
  writeFile(fs::path(dir) / "step-02.script", stepProgram(2, second, speed));
  fs::copy_file(cell, fs::path(dir) / "cell.json", fs::copy_options::overwrite_existing);
  writeFile(fs::path(dir) / "robot-job.json",
            R"({ "format": "multidir-robot-job", "version": 1, "robot": "ur5", "cell": "cell.json",
  "steps": [ { "step": 1, "program": "step-01.script", "seconds": 3.5 },
             { "step": 2, "program": "step-02.script", "seconds": 4.0 } ] })");
  return dir;
}

// A UR simulator on four consecutive free ports (tests/support/ur_test_support.h).
std::unique_ptr<hw::UrSimulator> startSimulator(hw::UrSimulatorOptions options) {
  options.keepTrace = true;
  options.initialJoints = {0.0, -1.0, 1.3, -1.9, -1.5707963267948966, 0.0};
  return multidir::test::startUrSimulatorOnFreePorts(options, 43000);
}

// The extruding part of a run as the simulator recorded it: the TCP (mm) of every tick that drives the extruder.
std::vector<Eigen::Vector3d> extrudingPath(const std::vector<hw::UrTraceRecord>& trace) {
  std::vector<Eigen::Vector3d> path;
  for (const hw::UrTraceRecord& r : trace)
    if (r.analogOut0 > 0.0 && !r.program.empty()) path.emplace_back(r.tcp[0], r.tcp[1], r.tcp[2]);
  return path;
}

double distanceToPolyline(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& line) {
  double least = 1e300;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Eigen::Vector3d ab = line[i] - line[i - 1];
    const double t = ab.squaredNorm() > 0.0 ? std::clamp((p - line[i - 1]).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    least = std::min(least, (line[i - 1] + t * ab - p).norm());
  }
  return least;
}

// Filament pushed (the extruder's speed fraction integrated over the simulated time).
double extruded(const std::vector<hw::UrTraceRecord>& trace) {
  double sum = 0.0;
  for (std::size_t i = 1; i < trace.size(); ++i) sum += trace[i - 1].analogOut0 * (trace[i].time - trace[i - 1].time);
  return sum;
}

class RobotCellDock : public ::testing::Test {
 protected:
  void SetUp() override {
    auto cell = robot::parseCell(kCellFile);
    ASSERT_TRUE(cell.ok());
    document.setCell(*cell);
    // The machine is the robot cell, so the Hardware dock's device is the cell and its section shows.
    core::MachineSpec fiveDof;
    fiveDof.kind = core::MachineKind::TiltRotate;
    document.setMachine(fiveDof);
    document.setMachineIsRobotCell(true);
    core::Decomposition plan;
    plan.regions.resize(2);
    SearchRun run;
    run.plan = std::make_shared<const core::Decomposition>(std::move(plan));
    document.setPlan(run);
    section = panel.robotCellSection();
    ASSERT_NE(section, nullptr);
    panel.resize(520, 1400);
    panel.show();
  }

  QPushButton* buttonNamed(const char* name) {
    auto* found = panel.findChild<QPushButton*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << name;
    return found;
  }
  void press(const char* name) {
    QPushButton* target = buttonNamed(name);
    ASSERT_NE(target, nullptr);
    ASSERT_TRUE(target->isEnabled()) << name << " is disabled; message: " << section->messageText().toStdString();
    QTest::mouseClick(target, Qt::LeftButton);
  }
  // Until the arm moves along step 1's movels (past the program's first lines), or the run guard's time.
  static bool waitUntilMovingInStepOne(const hw::UrSimulator& simulator) {
    return QTest::qWaitFor(
        [&] {
          const hw::UrSimulatorState s = simulator.state();
          return s.programName == "multidir_step_01" && s.programState == "PLAYING" && !s.atRest && s.line > 6;
        },
        kRunMs);
  }
  void connectTo(const hw::UrSimulator& simulator) {
    section->setAddress(QStringLiteral("127.0.0.1:%1").arg(simulator.dashboardPort()));
    press("robotConnect");
    ASSERT_TRUE(QTest::qWaitFor([&] { return section->isConnected(); }, 10000)) << section->messageText().toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] { return section->stateText().contains(QStringLiteral("robot mode")); }, 5000));
  }
  void startJob(const std::string& dir) {
    section->setJobFolder(QString::fromStdString(dir));
    press("robotStart");
    ASSERT_TRUE(section->isRunUnderWay()) << section->messageText().toStdString();
  }
  bool waitForRunEnd() {
    return QTest::qWaitFor([&] { return !section->isRunUnderWay(); }, kRunMs);
  }

  StudioDocument document;
  HardwarePanel panel{&document};
  RobotCellSection* section = nullptr;
};

TEST_F(RobotCellDock, ConnectShowsTheRobotsModesAndJoints) {
  hw::UrSimulatorOptions options;
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  ASSERT_NO_FATAL_FAILURE(connectTo(*simulator));
  EXPECT_TRUE(
      section->stateText().contains(QStringLiteral("robot mode POWER_OFF, safety mode NORMAL, program STOPPED")))
      << section->stateText().toStdString();
  // The simulator's initial joints, in degrees: {0, -1.0, 1.3, ...} rad.
  auto* joints = panel.findChild<QLabel*>(QStringLiteral("robotJoints"));
  ASSERT_NE(joints, nullptr);
  EXPECT_TRUE(joints->text().startsWith(QStringLiteral("0.00, -57.30, 74.48"))) << joints->text().toStdString();
}

TEST_F(RobotCellDock, TheDockRunsTheJobToItsEndAlongThePathTheCliRunGives) {
  const std::string dir = writeRobotJob("RobotCellDock.ToItsEnd", 0.05);
  // The CLI's run: hardware's robot run, as `multidir run OUT --robot` calls it, on a simulator of its own.
  hw::UrSimulatorOptions options;
  options.speed = 20.0;
  auto cliSimulator = startSimulator(options);
  ASSERT_TRUE(cliSimulator);
  {
    auto job = hw::readRobotJob(dir);
    ASSERT_TRUE(job.ok());
    hw::UrLinkSettings settings;
    settings.dashboardPort = cliSimulator->dashboardPort();
    settings.secondaryPort = cliSimulator->dashboardPort() + 1;
    settings.realtimePort = cliSimulator->dashboardPort() + 2;
    settings.rtdePort = cliSimulator->dashboardPort() + 3;
    hw::UrLink link(settings);
    ASSERT_TRUE(link.connect().ok());
    hw::RobotRunRequests requests;
    hw::RobotRunListener silent;
    const hw::RobotRunEnd end = hw::runRobotJob(link, *job, 1, requests, silent);
    ASSERT_EQ(end.kind, hw::RobotRunEnd::Kind::Done) << end.why;
  }
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  ASSERT_NO_FATAL_FAILURE(connectTo(*simulator));
  ASSERT_NO_FATAL_FAILURE(startJob(dir));
  EXPECT_TRUE(document.isSessionJobPinned());
  ASSERT_TRUE(waitForRunEnd());
  EXPECT_FALSE(section->messageIsError()) << section->messageText().toStdString();
  EXPECT_EQ(section->messageText().toStdString(), "The robot job is done: 2 steps printed.");
  EXPECT_FALSE(document.isSessionJobPinned());
  EXPECT_EQ(simulator->state().programsFinished, 2u);
  const std::vector<TimelineRow>& rows = panel.jobTimeline()->rows();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].region.toStdString(), "step-01.script");
  EXPECT_EQ(rows[0].phase, StepPhase::Done);
  EXPECT_EQ(rows[1].phase, StepPhase::Done);
  // The same nozzle path and the same filament as the CLI's run.
  const std::vector<Eigen::Vector3d> cliPath = extrudingPath(cliSimulator->trace());
  const std::vector<Eigen::Vector3d> dockPath = extrudingPath(simulator->trace());
  ASSERT_GT(dockPath.size(), 100u);
  double worst = 0.0;
  for (const Eigen::Vector3d& p : dockPath) worst = std::max(worst, distanceToPolyline(p, cliPath));
  EXPECT_LT(worst, 0.05);
  EXPECT_LT((dockPath.back() - cliPath.back()).norm(), 0.01);
  const double cliFilament = extruded(cliSimulator->trace());
  EXPECT_NEAR(extruded(simulator->trace()), cliFilament, 0.005 * cliFilament);
}

TEST_F(RobotCellDock, EstopMidStepReachesTheRobotAndNothingMovesAfter) {
  const std::string dir = writeRobotJob("RobotCellDock.Estop", 0.01);
  hw::UrSimulatorOptions options;
  options.speed = 1.0;
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  ASSERT_NO_FATAL_FAILURE(connectTo(*simulator));
  ASSERT_NO_FATAL_FAILURE(startJob(dir));
  ASSERT_TRUE(waitUntilMovingInStepOne(*simulator));
  press("robotEstop");
  ASSERT_TRUE(waitForRunEnd());
  EXPECT_TRUE(section->messageText().contains(QStringLiteral("The run stopped in step 1: stopped by the operator")))
      << section->messageText().toStdString();
  EXPECT_TRUE(
      QTest::qWaitFor([&] { return panel.stopsText().contains(QStringLiteral("Robot: E-STOP confirmed")); }, 5000))
      << panel.stopsText().toStdString();
  const hw::UrSimulatorState stopped = simulator->state();
  EXPECT_EQ(stopped.programState, "STOPPED");
  EXPECT_EQ(stopped.robotMode, "POWER_OFF");
  bool poweredOff = false;
  for (const hw::UrDashboardRecord& r : simulator->dashboardLog()) poweredOff = poweredOff || r.command == "power off";
  EXPECT_TRUE(poweredOff);
  // Nothing moves after the stop: the record's last second has one pose.
  const std::size_t before = simulator->trace().size();
  QTest::qWait(1000);
  const std::vector<hw::UrTraceRecord> trace = simulator->trace();
  for (std::size_t i = before; i < trace.size(); ++i) EXPECT_EQ(trace[i].joints, stopped.joints) << "tick " << i;
  EXPECT_EQ(simulator->state().programsFinished, 0u);
}

TEST_F(RobotCellDock, AProtectiveStopShowsTheRobotsWordsAndHoldsTheRun) {
  const std::string dir = writeRobotJob("RobotCellDock.ProtectiveStop", 0.05);
  hw::UrSimulatorOptions options;
  options.speed = 20.0;
  options.fault = hw::UrSimulatorFault::ProtectiveStop;
  options.faultAtLine = 8;  // step 1's second movel
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  ASSERT_NO_FATAL_FAILURE(connectTo(*simulator));
  ASSERT_NO_FATAL_FAILURE(startJob(dir));
  ASSERT_TRUE(waitForRunEnd());
  EXPECT_TRUE(section->messageIsError());
  EXPECT_TRUE(section->messageText().contains(QStringLiteral(
      "The run stopped in step 1: the robot reports: C153: Protective stop: the simulator's injected fault")))
      << section->messageText().toStdString();
  const std::vector<TimelineRow>& rows = panel.jobTimeline()->rows();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].phase, StepPhase::Failed);
  EXPECT_TRUE(rows[0].reason.contains(QStringLiteral("C153"))) << rows[0].reason.toStdString();
  EXPECT_EQ(rows[1].phase, StepPhase::Waiting);
  // Held: the second step was never sent.
  EXPECT_EQ(simulator->programsReceived().size(), 1u);
}

TEST_F(RobotCellDock, ALostLinkShowsInTheBannerAndEndsTheRunInItsStep) {
  const std::string dir = writeRobotJob("RobotCellDock.LinkDrop", 0.01);
  hw::UrSimulatorOptions options;
  options.speed = 1.0;
  options.fault = hw::UrSimulatorFault::LinkDrop;
  options.faultAtLine = 8;  // step 1's second movel
  options.linkDropSeconds = 3.0;
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  ASSERT_NO_FATAL_FAILURE(connectTo(*simulator));
  ASSERT_NO_FATAL_FAILURE(startJob(dir));
  ASSERT_TRUE(QTest::qWaitFor(
      [&] { return panel.bannerText().contains(QStringLiteral("The link to the robot at 127.0.0.1:")); }, kRunMs))
      << section->messageText().toStdString();
  ASSERT_TRUE(waitForRunEnd());
  EXPECT_TRUE(
      section->messageText().contains(QStringLiteral("The run stopped in step 1: the link to the robot is lost")))
      << section->messageText().toStdString();
  EXPECT_EQ(panel.jobTimeline()->rows()[0].phase, StepPhase::Failed);
  // Back after the drop: the banner goes, the robot's values again.
  EXPECT_TRUE(QTest::qWaitFor([&] { return panel.bannerText().isEmpty(); }, 15000)) << panel.bannerText().toStdString();
  EXPECT_TRUE(section->stateText().startsWith(QStringLiteral("robot mode "))) << section->stateText().toStdString();
}

TEST_F(RobotCellDock, PauseHoldsTheArmOffTheNozzleAndResumeFinishesTheJob) {
  const std::string dir = writeRobotJob("RobotCellDock.Pause", 0.01);
  hw::UrSimulatorOptions options;
  options.speed = 1.0;
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  ASSERT_NO_FATAL_FAILURE(connectTo(*simulator));
  ASSERT_NO_FATAL_FAILURE(startJob(dir));
  ASSERT_TRUE(waitUntilMovingInStepOne(*simulator));
  press("robotPause");
  ASSERT_TRUE(QTest::qWaitFor([&] { return section->isRunPaused(); }, kRunMs)) << section->messageText().toStdString();
  const hw::UrSimulatorState held = simulator->state();
  EXPECT_EQ(held.programName, "multidir_pause");
  EXPECT_EQ(held.analogOut[0], 0.0);  // the extruder stopped
  EXPECT_EQ(panel.jobTimeline()->rows()[0].phase, StepPhase::Paused);
  EXPECT_TRUE(section->runStepText().contains(QStringLiteral("mm off the nozzle")))
      << section->runStepText().toStdString();
  press("robotResume");
  ASSERT_TRUE(waitForRunEnd());
  EXPECT_EQ(section->messageText().toStdString(), "The robot job is done: 2 steps printed.");
  // What the robot was sent: step 1, the pause program, step 1's rest (under its own name), step 2.
  const std::vector<std::string> programs = simulator->programsReceived();
  ASSERT_EQ(programs.size(), 4u);
  EXPECT_EQ(programs[1].rfind("def multidir_pause():", 0), 0u) << programs[1];
  EXPECT_NE(programs[2].find("# MultiDir: resumed after movel "), std::string::npos) << programs[2];
  EXPECT_EQ(programs[3].rfind("def multidir_step_02():", 0), 0u) << programs[3];
}

TEST_F(RobotCellDock, AJobForAnotherCellIsRefusedSayingWhich) {
  auto cell = robot::parseCell(kCellFile);
  ASSERT_TRUE(cell.ok());
  cell->nozzleTipMm.x() += 5.0;
  const fs::path other = fs::path(test::scratchDirectory("RobotCellDock.OtherCell")) / "moved-nozzle.json";
  ASSERT_TRUE(robot::writeCell(*cell, other).ok());
  const std::string dir = writeRobotJob("RobotCellDock.OtherCellJob", 0.05, other);
  hw::UrSimulatorOptions options;
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  ASSERT_NO_FATAL_FAILURE(connectTo(*simulator));
  section->setJobFolder(QString::fromStdString(dir));
  press("robotStart");
  EXPECT_FALSE(section->isRunUnderWay());
  EXPECT_TRUE(section->messageText().startsWith(QStringLiteral("Start refused: the job's cell (")))
      << section->messageText().toStdString();
  EXPECT_TRUE(section->messageText().contains(QStringLiteral("is not the cell on the Machine tab")));
  EXPECT_FALSE(document.isSessionJobPinned());
  EXPECT_EQ(simulator->programsReceived().size(), 0u);
}

TEST_F(RobotCellDock, AJobOfAnotherPlanIsRefusedSayingWhich) {
  core::Decomposition plan;
  plan.regions.resize(3);
  SearchRun run;
  run.plan = std::make_shared<const core::Decomposition>(std::move(plan));
  document.setPlan(run);
  const std::string dir = writeRobotJob("RobotCellDock.OtherPlan", 0.05);
  hw::UrSimulatorOptions options;
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  ASSERT_NO_FATAL_FAILURE(connectTo(*simulator));
  section->setJobFolder(QString::fromStdString(dir));
  press("robotStart");
  EXPECT_FALSE(section->isRunUnderWay());
  EXPECT_EQ(section->messageText().toStdString(),
            "Start refused: the job has 2 steps but the plan shown has 3 regions: it was made from another plan.");
  EXPECT_EQ(simulator->programsReceived().size(), 0u);
}

// Quitting the studio while the dock runs a robot job asks about the run first (as for a print run); Stop the
// Devices and Quit stops the robot's program and waits for it before the window goes.
TEST(RobotCellDockQuit, QuittingDuringARobotRunAsksAndStopsTheRobotFirst) {
  test::resetStudioSettings();
  auto window = std::make_unique<MainWindow>();
  auto cell = robot::parseCell(kCellFile);
  ASSERT_TRUE(cell.ok());
  window->document()->setCell(*cell);
  core::Decomposition plan;
  plan.regions.resize(2);
  SearchRun run;
  run.plan = std::make_shared<const core::Decomposition>(std::move(plan));
  window->document()->setPlan(run);
  window->resize(1400, 900);
  window->show();
  const std::string dir = writeRobotJob("RobotCellDockQuit.Quit", 0.01);
  hw::UrSimulatorOptions options;
  options.speed = 1.0;
  auto simulator = startSimulator(options);
  ASSERT_TRUE(simulator);
  RobotCellSection* section = window->hardwarePanel()->robotCellSection();
  section->setAddress(QStringLiteral("127.0.0.1:%1").arg(simulator->dashboardPort()));
  section->connectRobot();
  ASSERT_TRUE(QTest::qWaitFor([&] { return section->isConnected(); }, 10000)) << section->messageText().toStdString();
  section->setJobFolder(QString::fromStdString(dir));
  section->startRun();
  ASSERT_TRUE(section->isRunUnderWay()) << section->messageText().toStdString();
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        const hw::UrSimulatorState s = simulator->state();
        return s.programName == "multidir_step_01" && s.programState == "PLAYING" && !s.atRest;
      },
      kRunMs));

  window->close();
  QMessageBox* box = test::waitForMessageBox(*window, QStringLiteral("printRunQuitBox"));
  ASSERT_NE(box, nullptr) << "quitting during a robot run should ask about the run";
  EXPECT_TRUE(window->isVisible());
  auto* stop = box->findChild<QPushButton*>(QStringLiteral("stopDevicesAndQuit"));
  ASSERT_NE(stop, nullptr);
  stop->click();
  EXPECT_TRUE(QTest::qWaitFor([&] { return !window->isVisible(); }, 20000));
  EXPECT_FALSE(section->isRunUnderWay());
  const hw::UrSimulatorState s = simulator->state();
  EXPECT_EQ(s.programState, "STOPPED");
  EXPECT_TRUE(s.atRest);
  EXPECT_EQ(s.programsFinished, 0u);
}

}  // namespace
}  // namespace multidir::ui

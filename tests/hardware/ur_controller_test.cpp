// The simulated UR controller's physics, stepped tick by tick (no sockets, no clock): moves reach their targets
// within the joint limits, a limit is a protective stop in UR's words, an emergency stop brakes the arm at once,
// the nozzle follows its set point.
#include "sim/ur_controller.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "multidir/robot/arm_links.h"
#include "multidir/robot/cell.h"
#include "multidir/robot/ur_kinematics.h"

namespace {

using multidir::hardware::sim::kUrTickSeconds;
using multidir::hardware::sim::UrController;
using multidir::hardware::sim::UrTraceSample;
using multidir::hardware::ur::UrProgramState;
using multidir::hardware::ur::UrRobotMode;
using multidir::hardware::ur::UrSafetyMode;
namespace robot = multidir::robot;

const robot::Joints kStart{0.0, -1.2, 1.5, -1.9, -1.5707963267948966, 0.0};

robot::ArmModel ur5() { return *robot::armModel("ur5"); }

// A controller powered on with its brakes released, the arm at kStart.
UrController readyController(const robot::ArmModel& arm = ur5()) {
  UrController c(arm, kStart);
  bool quit = false;
  EXPECT_EQ(c.dashboard("power on", quit), "Powering on");
  for (int i = 0; i < 100; ++i) c.tick();
  EXPECT_EQ(c.dashboard("brake release", quit), "Brake releasing");
  EXPECT_EQ(c.robotMode(), UrRobotMode::Running);
  return c;
}

std::string pose(const Eigen::Isometry3d& p) {
  const Eigen::AngleAxisd aa(p.linear());
  const Eigen::Vector3d r = aa.axis() * aa.angle();
  const Eigen::Vector3d t = p.translation() / 1000.0;
  char text[200];
  std::snprintf(text, sizeof text, "p[%.9f, %.9f, %.9f, %.12f, %.12f, %.12f]", t.x(), t.y(), t.z(), r.x(), r.y(),
                r.z());
  return text;
}

// Ticks until the program stopped and the arm is at rest (at most `seconds`); returns the traced ticks.
std::vector<UrTraceSample> runToEnd(UrController& c, double seconds = 60.0) {
  std::vector<UrTraceSample> trace;
  for (int i = 0; i < static_cast<int>(seconds / kUrTickSeconds); ++i) {
    c.tick();
    for (UrTraceSample& s : c.takeTrace()) trace.push_back(std::move(s));
    if (c.programState() == UrProgramState::Stopped && c.atRest()) break;
  }
  return trace;
}

TEST(UrController, MovelReachesItsTargetWithin0_01MmAndNoJointExceedsItsSpeedLimit) {
  const robot::ArmModel arm = ur5();
  UrController c = readyController(arm);
  Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();
  tcp.translation() = Eigen::Vector3d(0.0, 0.0, 50.0);
  const Eigen::Isometry3d start = robot::forwardKinematics(arm, kStart) * tcp;
  Eigen::Isometry3d target = start;
  target.translation() += Eigen::Vector3d(120.0, -80.0, 60.0);
  target.linear() = target.linear() * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  c.receiveProgram("def step():\n  set_tcp(p[0, 0, 0.05, 0, 0, 0])\n  movel(" + pose(target) +
                   ", a=1.2, v=0.25)\nend\n");
  ASSERT_EQ(c.programState(), UrProgramState::Playing) << c.lastFault();
  const std::vector<UrTraceSample> trace = runToEnd(c);
  ASSERT_EQ(c.programsFinished(), 1u) << c.lastFault();
  ASSERT_EQ(c.safetyMode(), UrSafetyMode::Normal) << c.lastFault();
  const Eigen::Isometry3d reached = robot::forwardKinematics(arm, c.joints()) * tcp;
  EXPECT_LT((reached.translation() - target.translation()).norm(), 0.01);
  EXPECT_LT(Eigen::AngleAxisd(reached.linear().transpose() * target.linear()).angle(), 1e-6);
  // Every tick's joint speeds within the arm's limits, and the TCP's along the line no faster than v.
  ASSERT_GT(trace.size(), 10u);
  double fastestTcp = 0.0;
  for (std::size_t k = 1; k < trace.size(); ++k) {
    const double dt = trace[k].time - trace[k - 1].time;
    for (std::size_t j = 0; j < 6; ++j)
      EXPECT_LE(std::abs(trace[k].q[j] - trace[k - 1].q[j]) / dt, arm.limits[j].maxSpeedRadPerS)
          << "joint " << j + 1 << " at " << trace[k].time << " s";
    const Eigen::Vector3d a(trace[k - 1].tcp[0], trace[k - 1].tcp[1], trace[k - 1].tcp[2]);
    const Eigen::Vector3d b(trace[k].tcp[0], trace[k].tcp[1], trace[k].tcp[2]);
    fastestTcp = std::max(fastestTcp, (b - a).norm() / dt);
  }
  EXPECT_LE(fastestTcp, 250.0 * (1.0 + 1e-6));
  EXPECT_GT(fastestTcp, 240.0);  // it did cruise at v
}

TEST(UrController, AMovejBeyondAJointLimitIsAProtectiveStopNamingTheJoint) {
  robot::ArmModel arm = ur5();
  arm.limits[2].maxRad = 2.0;  // the cell narrows the elbow
  UrController c = readyController(arm);
  c.receiveProgram("def step():\n  movej([0, -1.2, 2.5, -1.9, -1.57, 0], a=1.4, v=1.05)\n  sleep(1)\nend\n");
  runToEnd(c);
  EXPECT_EQ(c.safetyMode(), UrSafetyMode::ProtectiveStop);
  EXPECT_EQ(c.programState(), UrProgramState::Stopped);
  EXPECT_NE(c.lastFault().find("Protective stop: Joint Position Limit violated: joint 3 (elbow)"), std::string::npos)
      << c.lastFault();
  EXPECT_EQ(c.programsFinished(), 0u);
  bool quit = false;
  EXPECT_EQ(c.dashboard("safetystatus", quit), "Safetystatus: PROTECTIVE_STOP");
  EXPECT_EQ(c.dashboard("unlock protective stop", quit),
            "Cannot unlock protective stop until 5s after occurrence. Always inspect cause of protective stop before "
            "unlocking");
  for (int i = 0; i < 700; ++i) c.tick();
  EXPECT_EQ(c.dashboard("unlock protective stop", quit), "Protective stop releasing");
  EXPECT_EQ(c.safetyMode(), UrSafetyMode::Normal);
}

TEST(UrController, AMovejFasterThanAJointsSpeedLimitIsAProtectiveStopAndTheArmStops) {
  UrController c = readyController();
  // UR5's base turns at most 180 deg/s (3.14 rad/s).
  c.receiveProgram("def step():\n  movej([2.5, -1.2, 1.5, -1.9, -1.57, 0], a=40, v=4.0)\nend\n");
  runToEnd(c);
  EXPECT_EQ(c.safetyMode(), UrSafetyMode::ProtectiveStop);
  EXPECT_NE(c.lastFault().find("Joint Speed Limit violated: joint 1 (base)"), std::string::npos) << c.lastFault();
  EXPECT_TRUE(c.atRest());
  EXPECT_LT(c.joints()[0], 2.5);
}

// The cell's bodies are physical to the simulated arm (simulate --cell): a program whose movej drives the forearm
// through a strut of the extruder's mount is stopped there with a protective stop naming the link and the body,
// and the arm does not reach the move's end.
TEST(UrController, AMovejDrivingTheForearmIntoACellBodyIsAProtectiveStopNamingTheLinkAndTheBody) {
  robot::Cell cell = *robot::loadCell(std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json");
  cell.boxes.clear();  // only the strut: nothing else in the arm's way
  cell.cylinders.clear();
  const robot::Joints to{kStart[0] + 0.6, kStart[1] + 0.3, kStart[2] - 0.3, kStart[3], kStart[4], kStart[5]};
  robot::Joints middle{};
  for (std::size_t j = 0; j < 6; ++j) middle[j] = 0.5 * (kStart[j] + to[j]);
  const robot::ArmLinkSolid forearm = robot::armLinkSolids(cell.arm, middle)[1];
  robot::CollisionBox strut;
  strut.name = "mount strut";
  strut.pose.translation() = 0.5 * (forearm.fromMm + forearm.toMm);
  strut.sizeMm = Eigen::Vector3d(30.0, 30.0, 30.0);
  cell.boxes.push_back(strut);
  ASSERT_GT(robot::armClearance(cell, kStart).mm, 0.0);
  ASSERT_GT(robot::armClearance(cell, to).mm, 0.0);
  UrController c = readyController(cell.arm);
  c.watchCollisions(cell);
  char program[200];
  std::snprintf(program, sizeof program, "def step():\n  movej([%.9f, %.9f, %.9f, %.9f, %.9f, %.9f], a=1.4, v=1.05)\nend\n",
                to[0], to[1], to[2], to[3], to[4], to[5]);
  c.receiveProgram(program);
  runToEnd(c);
  EXPECT_EQ(c.safetyMode(), UrSafetyMode::ProtectiveStop);
  EXPECT_NE(c.lastFault().find("Protective stop: collision: the arm's forearm touches the cell's body \"mount strut\""),
            std::string::npos)
      << c.lastFault();
  EXPECT_EQ(c.programsFinished(), 0u);
  EXPECT_TRUE(c.atRest());
  EXPECT_LT(c.joints()[0], to[0] - 0.1);
}

TEST(UrController, AnEmergencyStopBringsTheArmToRestWithin200MsAndNothingMovesAfter) {
  const robot::ArmModel arm = ur5();
  UrController c = readyController(arm);
  c.receiveProgram("def step():\n  movej([1.5, -1.0, 1.2, -1.7, -1.2, 0.5], a=3.0, v=3.0)\nend\n");
  for (int i = 0; i < 50; ++i) c.tick();  // 0.4 s: the base turns at 1.2 rad/s
  c.takeTrace();
  const double pressedAt = c.time();
  ASSERT_GT(std::abs(c.realtime().qdActual[0]), 1.0);
  c.pressEmergencyStop();
  std::vector<UrTraceSample> trace;
  for (int i = 0; i < 250; ++i) {  // 2 s
    c.tick();
    for (UrTraceSample& s : c.takeTrace()) trace.push_back(std::move(s));
  }
  const robot::Joints stoppedAt = c.joints();
  double lastMove = pressedAt;
  robot::Joints previous{};
  bool first = true;
  for (const UrTraceSample& s : trace) {
    if (!first && s.q != previous) lastMove = s.time;
    previous = s.q;
    first = false;
  }
  EXPECT_LE(lastMove - pressedAt, 0.2 + 1e-9);
  for (int i = 0; i < 125; ++i) c.tick();
  EXPECT_EQ(c.joints(), stoppedAt);
  EXPECT_EQ(c.safetyMode(), UrSafetyMode::RobotEmergencyStop);
  EXPECT_EQ(c.robotMode(), UrRobotMode::PowerOff);
  EXPECT_EQ(c.programState(), UrProgramState::Stopped);
}

TEST(UrController, TheNozzleHeatsAtItsDocumentedRateAndTheHeatWaitHoldsTheProgram) {
  UrController c = readyController();
  // 0.5 of 300 C = 150 C: from 25 C at 3 C/s that is 41.7 s.
  c.receiveProgram(
      "def heat():\n  set_standard_analog_out(1, 0.5)\n  while get_standard_analog_in(0) < 0.5:\n    sync()\n  "
      "end\n  textmsg(\"hot\")\nend\n");
  const double started = c.time();
  runToEnd(c, 120.0);
  EXPECT_EQ(c.programsFinished(), 1u);
  EXPECT_NEAR(c.time() - started, (150.0 - 25.0) / 3.0, 0.05);
  EXPECT_NEAR(c.nozzleC(), 150.0, 1e-6);
  const auto messages = c.takeMessages();
  ASSERT_FALSE(messages.empty());
  EXPECT_EQ(messages.back().text, "hot");
}

TEST(UrController, AProgramOutsideTheSubsetIsRefusedWithARuntimeExceptionNamingTheLine) {
  UrController c = readyController();
  c.receiveProgram("def step():\n  sleep(0.1)\n  popup(\"hello\")\nend\n");
  EXPECT_EQ(c.programState(), UrProgramState::Stopped);
  const auto messages = c.takeMessages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].kind, multidir::hardware::ur::UrRobotMessage::Kind::RuntimeException);
  EXPECT_EQ(messages[0].line, 3);
  EXPECT_NE(messages[0].text.find("'popup' is not in the URScript subset"), std::string::npos) << messages[0].text;
}

// A program above the controller's bound (the cell's maxProgramBytes) is refused before it runs, with a compile
// error giving its size and the bound; one at the bound runs.
TEST(UrController, AProgramAboveTheControllersBoundIsRefusedWithACompileErrorGivingItsSize) {
  UrController c = readyController();
  c.setMaxProgramBytes(4096);
  std::string text = "def step():\n";
  while (text.size() < 4096 - 16) text += "  sleep(0.001)\n";
  text.resize(4096 - 4, ' ');
  text += "\nend\n";
  ASSERT_EQ(text.size(), 4097u);
  c.receiveProgram(text);
  EXPECT_EQ(c.programState(), UrProgramState::Stopped);
  const auto messages = c.takeMessages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].kind, multidir::hardware::ur::UrRobotMessage::Kind::RuntimeException);
  EXPECT_EQ(messages[0].text, "Compile error: the program is 4097 bytes, above the 4096 bytes this controller compiles");
  text.erase(text.size() - 6, 1);  // one byte less: at the bound
  c.receiveProgram(text);
  EXPECT_EQ(c.programState(), UrProgramState::Playing);
  EXPECT_TRUE(c.takeMessages().empty());
}

// A program writes a movel's number to the register just before the movel: the register names the move the arm
// makes while it makes it (docs/robot-cell.md, "Pause and resume"), and keeps it at the move's end until the
// next write.
TEST(UrController, TheMovelRegisterNamesTheMoveTheArmIsMaking) {
  const robot::ArmModel arm = ur5();
  UrController c = readyController(arm);
  Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();
  tcp.translation() = Eigen::Vector3d(0.0, 0.0, 50.0);
  const Eigen::Isometry3d start = robot::forwardKinematics(arm, kStart) * tcp;
  Eigen::Isometry3d first = start, second = start;
  first.translation() += Eigen::Vector3d(20.0, 0.0, 0.0);
  second.translation() += Eigen::Vector3d(20.0, 20.0, 0.0);
  c.receiveProgram("def step():\n  set_tcp(p[0, 0, 0.05, 0, 0, 0])\n  write_output_integer_register(24, 0)\n"
                   "  write_output_integer_register(24, 1)\n  movel(" + pose(first) + ", a=1.2, v=0.02)\n"
                   "  write_output_integer_register(24, 2)\n  movel(" + pose(second) + ", a=1.2, v=0.02)\n"
                   "  write_output_integer_register(24, 0)\nend\n");
  ASSERT_EQ(c.programState(), UrProgramState::Playing) << c.lastFault();
  // Every tick: the register's move is the one whose line the TCP is on (0.01 mm), in order 1 then 2, then 0.
  std::vector<int> seen;
  for (int i = 0; i < static_cast<int>(10.0 / kUrTickSeconds) && c.programState() == UrProgramState::Playing; ++i) {
    c.tick();
    const int k = c.outputIntRegister(24);
    if (seen.empty() || seen.back() != k) seen.push_back(k);
    const Eigen::Vector3d at = (robot::forwardKinematics(arm, c.joints()) * tcp).translation();
    const Eigen::Vector3d from = k == 2 ? Eigen::Vector3d(first.translation()) : Eigen::Vector3d(start.translation());
    const Eigen::Vector3d to = k == 2 ? Eigen::Vector3d(second.translation()) : Eigen::Vector3d(first.translation());
    if (k == 0) continue;
    const Eigen::Vector3d d = to - from;
    const double t = std::clamp((at - from).dot(d) / d.squaredNorm(), 0.0, 1.0);
    EXPECT_LT((from + t * d - at).norm(), 0.01) << "register " << k << " at " << c.time() << " s";
  }
  EXPECT_EQ(c.programsFinished(), 1u);
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 0}));
  EXPECT_EQ(c.outputIntRegister(25), 0);  // only the written register changed
}

}  // namespace

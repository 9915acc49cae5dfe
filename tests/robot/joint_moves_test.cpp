// The programs' joint moves between home and a step (docs/robot-cell.md, "Joint moves"): checked like every other
// move, given via points where the straight joint path is blocked, refused naming the step and the move when none
// is found, and the same program for the same input. The programs are replayed with an independent check
// (support/joint_sweep_check.h: forward kinematics sampled every 0.1 degree, point-to-solid distances of its own).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "multidir/robot/arm_links.h"
#include "multidir/robot/cell.h"
#include "joint_path_planner.h"
#include "step_converter.h"
#include "support/joint_sweep_check.h"
#include "support/square_steps.h"

namespace multidir::robot::detail {
namespace {

// The platform's rim as the test's step carries it (stepOf: 72 points 30 mm about the centre).
std::vector<Eigen::Vector3d> platformRim(const StepInput& input) {
  std::vector<Eigen::Vector3d> rim;
  for (const CarriedPoint& p : input.carried) rim.push_back(p.platformMm);
  return rim;
}

// On the paper's cell as shipped (home [-90, -90, -90, 0, 90, 0]) the straight joint move from home to a flat
// step's first point takes the wrist through the extruder: the replay of that one straight move meets a body.
TEST(JointMoves, OnTheShippedCellTheStraightMoveFromHomeToAFlatStepMeetsTheExtruder) {
  const Cell cell = shippedCell();
  const StepInput input = stepOf(squares(2), 30.0);
  const StepOutput out = convertStep(input, cell, fixedRotation(), core::JobContext());
  ASSERT_TRUE(out.refusals.empty()) << out.refusals.front();
  // The program's joint moves up to its first movel: home to home, then the way to the step's first point.
  const std::vector<test::ScriptJointMove> moves = test::scriptJointMoves(cell, cell.home, out.script);
  const std::string beforeMovel = out.script.substr(0, out.script.find("movel("));
  std::size_t movejs = 0;
  for (std::size_t at = beforeMovel.find("movej("); at != std::string::npos; at = beforeMovel.find("movej(", at + 1))
    ++movejs;
  ASSERT_GE(movejs, 2u);
  const Joints approach = moves[movejs - 1].to;
  char straight[200];
  std::snprintf(straight, sizeof straight, "movej([%.9f, %.9f, %.9f, %.9f, %.9f, %.9f])", approach[0], approach[1],
                approach[2], approach[3], approach[4], approach[5]);
  std::string what;
  EXPECT_LE(test::leastJointMoveClearance(cell, cell.home, straight, platformRim(input), what), 0.0) << what;
}

// The same step's program goes round the extruder: via points on the way from home, and its replay (every joint
// move from home to the step and back, sampled every 0.1 degree) keeps the links and the platform clear of every
// body and the table.
TEST(JointMoves, ABlockedMoveFromHomeGetsViaPointsAndTheReplayedJointPathsStayClear) {
  const Cell cell = shippedCell();
  const StepInput input = stepOf(squares(2), 30.0);
  const StepOutput out = convertStep(input, cell, fixedRotation(), core::JobContext());
  ASSERT_TRUE(out.refusals.empty()) << out.refusals.front();
  EXPECT_GE(out.summary.viaPointsFromHome, 1);
  EXPECT_LE(out.summary.viaPointsFromHome, 3);
  EXPECT_NE(out.script.find("via point"), std::string::npos);
  std::string what;
  const double least = test::leastJointMoveClearance(cell, cell.home, out.script, platformRim(input), what);
  EXPECT_GT(least, 0.0) << what;
}

// With via points off the blocked move is refused before anything is written, naming the step, the move, what
// hits what and the clearance.
TEST(JointMoves, WithViaPointsOffABlockedMoveFromHomeIsRefusedNamingTheStepAndTheMove) {
  RobotProgramOptions options = fixedRotation();
  options.viaPoints = false;
  const StepOutput out = convertStep(stepOf(squares(2), 30.0), shippedCell(), options, core::JobContext());
  ASSERT_FALSE(out.refusals.empty());
  const std::string refusal = out.refusals.front();
  EXPECT_NE(refusal.find("step 1 (step-01.gcode): the move from home to step 1's first point, 30 mm off the nozzle "
                         "(a joint move) is not clear: the arm's "),
            std::string::npos)
      << refusal;
  EXPECT_NE(refusal.find("would hit the extruder's body \""), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("(the links' least clearance along the move: -"), std::string::npos) << refusal;
  EXPECT_TRUE(out.script.empty());
}

// A body the arm touches at home (a cable tray mounted where the wrist parks): no joint path leaves home clear,
// straight or by any via point, and the step is refused naming the move and the straight move's first contact
// (at home), after the search gave up.
TEST(JointMoves, WhenNoViaPathExistsTheMoveFromHomeIsRefusedNamingTheStepAndTheMove) {
  Cell cell = shippedCell();
  const ArmLinkSolid wrist2 = armLinkSolids(cell.arm, cell.home)[3];
  ASSERT_STREQ(wrist2.name, "wrist 2");
  CollisionBox tray;
  tray.name = "cable tray";
  tray.pose.translation() = 0.5 * (wrist2.fromMm + wrist2.toMm);
  tray.sizeMm = Eigen::Vector3d(20.0, 20.0, 20.0);
  cell.boxes.push_back(tray);
  const StepOutput out = convertStep(stepOf(squares(2), 30.0), cell, fixedRotation(), core::JobContext());
  ASSERT_FALSE(out.refusals.empty());
  const std::string& refusal = out.refusals.front();
  EXPECT_NE(refusal.find("step 1 (step-01.gcode): the move from home to step 1's first point, 30 mm off the nozzle "
                         "(a joint move) is not clear: the arm's wrist 2 would hit the extruder's body \"cable tray\""),
            std::string::npos)
      << refusal;
  EXPECT_NE(refusal.find("no via points found either"), std::string::npos) << refusal;
  EXPECT_TRUE(out.script.empty());
}

// Two poses on either side of a pillar (a tall cylinder from the table up, standing where the flange passes half
// way between them), the joints differing only at the base: every natural candidate swings the arm through the
// pillar at the same distance from the base (the wrists or the big joints first are the straight move here; backing
// off along the vertical nozzle axis keeps that distance), so the search finds the way round; its path, replayed
// independently, stays clear, and it is the same path every time.
TEST(JointMoves, WhenNoNaturalCandidateIsClearTheSeededSearchFindsAWayRoundThePillar) {
  Cell cell = shippedCell();
  cell.boxes.clear();
  cell.cylinders.clear();
  const Joints from{-135.0 * kPi / 180, -70.0 * kPi / 180, 100.0 * kPi / 180, -120.0 * kPi / 180, -90.0 * kPi / 180, 0.0};
  Joints to = from;
  to[0] = -45.0 * kPi / 180;
  Joints middle = from;
  middle[0] = -90.0 * kPi / 180;
  const Eigen::Vector3d flange = forwardKinematics(cell.arm, middle).translation();
  CollisionCylinder pillar;
  pillar.name = "pillar";
  pillar.baseMm = Eigen::Vector3d(flange.x(), flange.y(), cell.tableZMm);
  pillar.axis = Eigen::Vector3d::UnitZ();
  pillar.radiusMm = 60.0;
  pillar.lengthMm = 1500.0;
  cell.cylinders.push_back(pillar);
  const StepInput input = stepOf(squares(1), 30.0);
  const JointMoveScene scene{&cell, &input.carried, Eigen::Isometry3d::Identity(), 0.0};
  const JointPathPlan plan = planJointPath(scene, from, to, true);
  ASSERT_TRUE(plan.found) << plan.straightHit;
  EXPECT_EQ(plan.method, "search");
  EXPECT_FALSE(plan.straightHit.empty());
  EXPECT_GE(plan.vias.size(), 1u);
  EXPECT_LE(plan.vias.size(), 6u);
  std::string script;  // the path's joint moves from `from`
  std::vector<Joints> targets = plan.vias;
  targets.push_back(to);
  for (const Joints& q : targets) {
    char line[200];
    std::snprintf(line, sizeof line, "movej([%.9f, %.9f, %.9f, %.9f, %.9f, %.9f])\n", q[0], q[1], q[2], q[3], q[4], q[5]);
    script += line;
  }
  std::string what;
  EXPECT_GT(test::leastJointMoveClearance(cell, from, script, platformRim(input), what), 0.0) << what;
  const JointPathPlan again = planJointPath(scene, from, to, true);
  EXPECT_EQ(again.vias, plan.vias);
}

// The same step converted twice (via points included) writes the same program byte for byte.
TEST(JointMoves, ConvertingTheSameStepTwiceWritesTheSameProgram) {
  const Cell cell = shippedCell();
  const StepOutput a = convertStep(stepOf(squares(2), 30.0), cell, fixedRotation(), core::JobContext());
  const StepOutput b = convertStep(stepOf(squares(2), 30.0), cell, fixedRotation(), core::JobContext());
  ASSERT_TRUE(a.refusals.empty()) << a.refusals.front();
  EXPECT_EQ(a.script, b.script);
}

}  // namespace
}  // namespace multidir::robot::detail

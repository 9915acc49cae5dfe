// A step that no single rotation about the nozzle axis can print is split into runs re-oriented at travel moves
// (docs/robot-cell.md, "Re-orientation within a step"); one that no split can save is refused naming the line.
// The cell and step: tests/support/reorientation_step.h.
#include <gtest/gtest.h>

#include "multidir/robot/cell.h"
#include "multidir/robot/robot_program.h"
#include "step_converter.h"
#include "support/reorientation_step.h"

namespace multidir::robot::detail {
namespace {

StepInput stepOf(const test::IslandsProgram& program) {
  StepInput input;
  input.gcodeFile = "step-01.gcode";
  input.gcode = program.text();
  input.recordMotion = true;
  for (int i = 0; i < 72; ++i) {
    const double a = 2 * test::kReorientPi * i / 72;
    input.carried.push_back({Eigen::Vector3d(30.0 * std::cos(a), 30.0 * std::sin(a), 0.0), CarriedPoint::Kind::Platform});
  }
  return input;
}

TEST(StepReorientation, WithWrist3FreeTheThreeSquaresPrintOnOneRotation) {
  Cell cell = test::narrowWrist3Cell();
  cell.arm.limits[5].minRad = -2 * test::kReorientPi;
  cell.arm.limits[5].maxRad = 2 * test::kReorientPi;
  const StepOutput out = convertStep(stepOf(test::threeIslands(true)), cell, test::everyDegree(), core::JobContext());
  ASSERT_TRUE(out.refusals.empty()) << out.refusals.front();
  EXPECT_TRUE(out.summary.reorientations.empty());
}

TEST(StepReorientation, AStepOneRotationCannotReachIsReorientedOnceAtATravelMove) {
  const test::IslandsProgram program = test::threeIslands(true);
  const StepOutput out =
      convertStep(stepOf(program), test::narrowWrist3Cell(), test::everyDegree(), core::JobContext());
  ASSERT_TRUE(out.refusals.empty()) << out.refusals.front();
  ASSERT_EQ(out.summary.reorientations.size(), 1u);
  const RobotReorientation& r = out.summary.reorientations.front();
  // At the travel to the third square, to another rotation.
  EXPECT_EQ(r.line, program.marks.at("travel to square 2"));
  EXPECT_NE(r.rotationDegrees, out.summary.rotationDegrees);
  // The program lifts, turns in joint space, comes down: one movej between the approach and the way home.
  std::size_t movejs = 0;
  for (std::size_t at = out.script.find("movej("); at != std::string::npos; at = out.script.find("movej(", at + 1))
    ++movejs;
  EXPECT_EQ(movejs, 4u);  // home, the approach, the turn, home
  EXPECT_NE(out.script.find("# re-orientation 1 before G-code line " + std::to_string(r.line)), std::string::npos);
  // The studio's motion follows: two rotations, and every sample's pose puts the nozzle tip on its point.
  ASSERT_EQ(out.platformRotations.size(), 2u);
  int lastRun = 0;
  for (const MotionSample& s : out.motion) {
    EXPECT_GE(s.run, lastRun);
    lastRun = s.run;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = out.platformRotations[static_cast<std::size_t>(s.run)];
    pose.translation() = s.platformMm;
    const Eigen::Vector3d tipOnPart = pose.inverse() * test::narrowWrist3Cell().nozzleTipMm;
    EXPECT_LT((tipOnPart - s.nozzleFileMm).norm(), 1e-6) << "line " << s.line;
    EXPECT_TRUE(platformPose(test::narrowWrist3Cell(), s.joints).isApprox(pose, 1e-6)) << "line " << s.line;
  }
  EXPECT_EQ(lastRun, 1);
}

// summary.txt says how many times each step was re-oriented and where.
TEST(StepReorientation, TheSummaryListsEachReorientationWithItsGcodeLine) {
  const test::IslandsProgram program = test::threeIslands(true);
  const StepOutput out =
      convertStep(stepOf(program), test::narrowWrist3Cell(), test::everyDegree(), core::JobContext());
  ASSERT_TRUE(out.refusals.empty()) << out.refusals.front();
  RobotJob job;
  job.robot = "ur5";
  job.steps.push_back(out.summary);
  job.scripts.push_back(out.script);
  const std::string summary = robotJobSummary(job);
  EXPECT_NE(summary.find("re-orientations"), std::string::npos) << summary;
  EXPECT_NE(summary.find("step 1 re-oriented before G-code line " +
                         std::to_string(program.marks.at("travel to square 2")) + ": rotation about the nozzle axis"),
            std::string::npos)
      << summary;
}

// The squares joined by extrusions: the only travels come before the first square, so no run can turn between
// them. Refused as without re-orientation (the step's own rotation, naming its line and reason), saying so.
TEST(StepReorientation, AStepWithNoTravelToTurnAtIsRefusedNamingTheLine) {
  const test::IslandsProgram program = test::threeIslands(false);
  const StepOutput out =
      convertStep(stepOf(program), test::narrowWrist3Cell(), test::everyDegree(), core::JobContext());
  ASSERT_EQ(out.refusals.size(), 1u);
  const std::string& refusal = out.refusals.front();
  ASSERT_GT(out.refusalLine, 0);
  EXPECT_EQ(refusal.find("step 1, line " + std::to_string(out.refusalLine) + " (step-01.gcode): "), 0u) << refusal;
  EXPECT_NE(refusal.find("joint limits (jointLimitsDegrees)"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("re-orienting the part at a travel move does not help"), std::string::npos) << refusal;
}

}  // namespace
}  // namespace multidir::robot::detail

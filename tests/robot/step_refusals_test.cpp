// One step's program refused before anything is written, naming the step, the G-code line and the reason:
// unreachable, a wrist flip, a collision with the extruder's body, a collision with the table. Small
// hand-made G-code and cells that force each (the rotation about the nozzle axis fixed at 0 so the geometry is
// the one written here).
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <sstream>

#include "multidir/robot/arm_links.h"
#include "multidir/robot/cell.h"
#include "step_converter.h"
#include "support/square_steps.h"

namespace multidir::robot::detail {
namespace {

TEST(StepRefusals, SquaresUnderTheShippedCellConvert) {
  const StepOutput out = convertStep(stepOf(squares(3), 30.0), shippedCell(), fixedRotation(), core::JobContext());
  EXPECT_TRUE(out.refusals.empty()) << out.refusals.front();
  // Every move that goes somewhere (the first layer's lift, travel and four sides; later layers' lift and four
  // sides: the travel back to the corner stays put), then the retreat.
  EXPECT_EQ(out.summary.moves, 6 + 5 + 5 + 1);
}

TEST(StepRefusals, AMoveOutOfReachIsRefusedWithItsLine) {
  Program p = squares(2);
  p.add("G1 X900 Y0 F6000", "far");
  const StepOutput out = convertStep(stepOf(p, 30.0), shippedCell(), fixedRotation(), core::JobContext());
  const std::string refusal = onlyRefusal(out);
  EXPECT_NE(refusal.find("step 1, line " + std::to_string(p.marks["far"]) + " (step-01.gcode): "), std::string::npos)
      << refusal;
  EXPECT_NE(refusal.find("reach"), std::string::npos) << refusal;
}

// The platform stands on the flange turned a quarter turn (its normal along the flange's x), under the vertical
// nozzle: the flange points along the base's -x. On the shoulder branch with q1 = 90 deg (the only one the
// narrowed base limits allow) the wrist is singular where the wrist centre's x equals d4, which the first layer's
// first side crosses at the part's x = 5: q4 and q6 turn half a turn there. The wrist margin is set to 0 so the
// joint-jump check is the one that catches it.
TEST(StepRefusals, AWristFlipIsRefusedWithItsLine) {
  Cell cell = shippedCell();
  cell.boxes.clear();
  cell.cylinders.clear();
  cell.flangeToPlatform.linear() = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const double d4 = cell.arm.d[3], d6 = cell.arm.d[5];
  const double flangeToTcp = cell.flangeToPlatform.translation().z();
  cell.nozzleTipMm = Eigen::Vector3d(d4 - d6 - flangeToTcp + 5.0, -400.0, 300.0);
  cell.arm.limits[0].minRad = 30.0 * kPi / 180;
  cell.arm.limits[0].maxRad = 150.0 * kPi / 180;
  cell.home = {kPi / 2, -kPi / 2, kPi / 2, 0.0, kPi / 2, 0.0};
  cell.margins.minWristDegrees = 0.0;
  const Program p = squares(2);
  const StepOutput out = convertStep(stepOf(p, 30.0), cell, fixedRotation(), core::JobContext());
  const std::string refusal = onlyRefusal(out);
  EXPECT_NE(refusal.find("step 1, line " + std::to_string(p.marks.at("first extrusion of layer0")) +
                         " (step-01.gcode): joint "),
            std::string::npos)
      << refusal;
  EXPECT_NE(refusal.find("a wrist flip"), std::string::npos) << refusal;
}

// A fan duct hangs beside the nozzle, 65 to 75 mm along x: the platform's rim (30 mm) reaches it when the nozzle
// travels to x -40 on the part.
TEST(StepRefusals, ThePlatformHittingTheExtrudersBodyIsRefusedWithItsLine) {
  Cell cell = shippedCell();
  CollisionBox duct;
  duct.name = "fan duct";
  duct.pose.translation() = cell.nozzleTipMm + Eigen::Vector3d(70.0, 0.0, -2.0);
  duct.sizeMm = Eigen::Vector3d(10.0, 10.0, 6.0);
  cell.boxes.push_back(duct);
  Program p = squares(2);
  p.add("G1 X-40 Y0 F6000", "towards duct");
  const StepOutput out = convertStep(stepOf(p, 30.0), cell, fixedRotation(), core::JobContext());
  const std::string refusal = onlyRefusal(out);
  EXPECT_NE(refusal.find("step 1, line " + std::to_string(p.marks["towards duct"]) +
                         " (step-01.gcode): the platform would hit the extruder's body \"fan duct\""),
            std::string::npos)
      << refusal;
}

// Nozzle axis along x again, far from the singularity: the platform (80 mm radius) stands on its edge and its rim
// dips as the nozzle moves along the part's y. The table 100 mm below the tip: the rim comes within 5 mm of it
// past y 15, before the wrist's housing (50 mm about the flange, level with the platform centre) past y 45.
TEST(StepRefusals, ThePlatformComingDownOnTheTableIsRefusedWithItsLine) {
  Cell cell = shippedCell();
  cell.boxes.clear();
  cell.cylinders.clear();
  cell.nozzleAxis = Eigen::Vector3d::UnitX();
  cell.nozzleTipMm = Eigen::Vector3d(400.0, -300.0, 300.0);
  cell.tableZMm = 200.0;
  Program p = squares(1);
  p.add("G1 X0 Y30 F6000", "down");
  const StepOutput out = convertStep(stepOf(p, 80.0), cell, fixedRotation(), core::JobContext());
  const std::string refusal = onlyRefusal(out);
  EXPECT_NE(refusal.find("step 1, line " + std::to_string(p.marks["down"]) +
                         " (step-01.gcode): the platform would come within 5.0 mm of the table"),
            std::string::npos)
      << refusal;
}

// The nozzle 60 mm above the table: the flange hangs 50 mm under the platform, so every configuration brings the
// arm's wrist housings down on the table at the first move (an elbow under the table is refused the same way).
TEST(StepRefusals, TheArmComingDownOnTheTableIsRefusedWithItsLine) {
  Cell cell = shippedCell();
  cell.nozzleTipMm = Eigen::Vector3d(0.0, -500.0, 60.0);
  cell.boxes.clear();
  cell.cylinders.clear();
  const Program p = squares(1);
  const StepOutput out = convertStep(stepOf(p, 30.0), cell, fixedRotation(), core::JobContext());
  const std::string refusal = onlyRefusal(out);
  EXPECT_NE(refusal.find("step 1, line 4 (step-01.gcode): the arm's "), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("of the table (its housing about 50 mm"), std::string::npos) << refusal;
}

// An extruder mount strut put where the arm's forearm passes while the squares print: the joints kept within a
// quarter turn of the configuration the step uses without it (so no other configuration can dodge it), a 30 mm
// cube about the forearm's middle at the first layer. The platform and the part stay clear of it; the forearm
// does not.
TEST(StepRefusals, AnExtruderMountWhereTheForearmPassesIsRefusedNamingTheLink) {
  Cell cell = shippedCell();
  const Program p = squares(2);
  const StepOutput clear = convertStep(stepOf(p, 30.0), cell, fixedRotation(), core::JobContext());
  ASSERT_TRUE(clear.refusals.empty()) << clear.refusals.front();
  const Eigen::Isometry3d flange =
      platformPoseFor(cell, Eigen::Isometry3d::Identity(), 0.0, Eigen::Vector3d(-10.0, -10.0, 0.4)) *
      cell.flangeToPlatform.inverse();
  std::optional<Joints> q;
  for (const IkSolution& s : inverseKinematics(cell.arm, flange))
    if (s.branch == clear.summary.branch) q = nearestWithinLimits(cell.arm, {s}, cell.home);
  ASSERT_TRUE(q.has_value());
  for (std::size_t j = 0; j < 6; ++j) {
    cell.arm.limits[j].minRad = (*q)[j] - kPi / 2;
    cell.arm.limits[j].maxRad = (*q)[j] + kPi / 2;
  }
  const ArmLinkSolid forearm = armLinkSolids(cell.arm, *q)[1];
  ASSERT_STREQ(forearm.name, "forearm");
  CollisionBox strut;
  strut.name = "mount strut";
  strut.pose.translation() = 0.5 * (forearm.fromMm + forearm.toMm);
  strut.sizeMm = Eigen::Vector3d(30.0, 30.0, 30.0);
  cell.boxes.push_back(strut);
  const StepOutput out = convertStep(stepOf(p, 30.0), cell, fixedRotation(), core::JobContext());
  const std::string refusal = onlyRefusal(out);
  EXPECT_NE(refusal.find("step 1, line " + std::to_string(p.marks.at("layer0")) +
                         " (step-01.gcode): the arm's forearm would hit the extruder's body \"mount strut\""),
            std::string::npos)
      << refusal;
}

// The links are checked between the samples too: one 60 mm extrusion checked only at its ends (--sample-mm 500),
// and a 4 mm block 1 mm inside the forearm's surface where the forearm stands half way, out of its reach at either
// end. The move is refused naming the forearm: the clearances at the ends do not cover how far the forearm can
// move between them, so the path is split until the block is met. The elbow is kept bent the one way (its joint
// limits), so no configuration with the other elbow (which the step, or a re-orientation at the travel before,
// could take) dodges the block.
TEST(StepRefusals, TheForearmMeetingABodyBetweenTwoSamplesIsRefused) {
  Cell cell = shippedCell();
  Program p;
  p.add("G90");
  p.add("M82");
  p.add("G92 E0");
  p.add("G1 X-30 Y0 F6000");
  p.add("G1 Z0.4 F600");
  p.add("G1 X30 Y0 E2 F1200", "long line");
  RobotProgramOptions options = fixedRotation();
  options.sampleMm = 500.0;
  const StepOutput clear = convertStep(stepOf(p, 30.0), cell, options, core::JobContext());
  ASSERT_TRUE(clear.refusals.empty()) << clear.refusals.front();
  auto jointsAt = [&](double x) {
    const Eigen::Isometry3d flange =
        platformPoseFor(cell, Eigen::Isometry3d::Identity(), 0.0, Eigen::Vector3d(x, 0.0, 0.4)) *
        cell.flangeToPlatform.inverse();
    std::optional<Joints> q;
    for (const IkSolution& s : inverseKinematics(cell.arm, flange))
      if (s.branch == clear.summary.branch) q = nearestWithinLimits(cell.arm, {s}, cell.home);
    EXPECT_TRUE(q.has_value());
    return q.value_or(Joints{});
  };
  cell.arm.limits[2].minRad = -kPi;
  cell.arm.limits[2].maxRad = -1e-3;
  const ArmLinkSolid start = armLinkSolids(cell.arm, jointsAt(-30.0))[1];
  const ArmLinkSolid middle = armLinkSolids(cell.arm, jointsAt(0.0))[1];
  const ArmLinkSolid end = armLinkSolids(cell.arm, jointsAt(30.0))[1];
  // Out from the forearm's axis, across the way it moves.
  const Eigen::Vector3d axis = (middle.toMm - middle.fromMm).normalized();
  const Eigen::Vector3d travel = (end.fromMm + end.toMm - start.fromMm - start.toMm).normalized();
  const Eigen::Vector3d out = axis.cross(travel).normalized();
  CollisionBox block;
  block.name = "cable clamp";
  block.pose.translation() = 0.5 * (middle.fromMm + middle.toMm) + (middle.radiusMm + 1.0) * out;
  block.sizeMm = Eigen::Vector3d(4.0, 4.0, 4.0);
  block.pose.linear().col(0) = out;
  block.pose.linear().col(1) = axis;
  block.pose.linear().col(2) = out.cross(axis);
  cell.boxes.push_back(block);
  ASSERT_GT(armClearance(cell, jointsAt(-30.0)).mm, 0.0);
  ASSERT_GT(armClearance(cell, jointsAt(30.0)).mm, 0.0);
  ASSERT_LT(armClearance(cell, jointsAt(0.0)).mm, 0.0);
  const StepOutput refused = convertStep(stepOf(p, 30.0), cell, options, core::JobContext());
  const std::string refusal = onlyRefusal(refused);
  EXPECT_NE(refusal.find("step 1, line " + std::to_string(p.marks.at("long line")) +
                         " (step-01.gcode): the arm's forearm would hit the extruder's body \"cable clamp\""),
            std::string::npos)
      << refusal;
}

}  // namespace
}  // namespace multidir::robot::detail

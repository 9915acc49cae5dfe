// One step's program refused before anything is written, naming the step, the G-code line and the reason:
// unreachable, a wrist flip, a collision with the extruder's body, a collision with the table. Small
// hand-made G-code and cells that force each (the rotation about the nozzle axis fixed at 0 so the geometry is
// the one written here).
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "multidir/robot/cell.h"
#include "step_converter.h"

namespace multidir::robot::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
const std::string kShippedCell = std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json";

Cell shippedCell() {
  auto cell = loadCell(kShippedCell);
  EXPECT_TRUE(cell.ok()) << cell.error().describe();
  return cell.value();
}

// A G-code program written line by line, remembering lines by name.
struct Program {
  std::vector<std::string> lines;
  std::map<std::string, int> marks;
  void add(const std::string& line, const std::string& mark = "") {
    lines.push_back(line);
    if (!mark.empty()) marks[mark] = static_cast<int>(lines.size());
  }
  std::string text() const {
    std::string t;
    for (const auto& l : lines) t += l + "\n";
    return t;
  }
};

// `layers` square perimeters of 20 mm about the platform centre, 2 mm apart from z 0.4.
Program squares(int layers) {
  Program p;
  p.add("G90");
  p.add("M82");
  p.add("G92 E0");
  double e = 0.0;
  for (int k = 0; k < layers; ++k) {
    const double z = 0.4 + 2.0 * k;
    std::ostringstream zMove;
    zMove << "G1 Z" << z << " F600";
    p.add(zMove.str(), "layer" + std::to_string(k));
    p.add("G1 X-10 Y-10 F6000");
    for (const char* corner : {"X10 Y-10", "X10 Y10", "X-10 Y10", "X-10 Y-10"}) {
      e += 1.0;
      std::ostringstream m;
      m << "G1 " << corner << " E" << e << " F1200";
      p.add(m.str(), corner == std::string("X10 Y-10") ? "first extrusion of layer" + std::to_string(k) : "");
    }
  }
  return p;
}

StepInput stepOf(const Program& program, double platformRadiusMm) {
  StepInput input;
  input.gcodeFile = "step-01.gcode";
  input.gcode = program.text();
  for (int i = 0; i < 72; ++i) {
    const double a = 2 * kPi * i / 72;
    input.carried.push_back({Eigen::Vector3d(platformRadiusMm * std::cos(a), platformRadiusMm * std::sin(a), 0.0),
                             CarriedPoint::Kind::Platform});
  }
  return input;
}

RobotProgramOptions fixedRotation() {
  RobotProgramOptions options;
  options.rotationStepDegrees = 360.0;
  return options;
}

std::string onlyRefusal(const StepOutput& out) {
  EXPECT_EQ(out.refusals.size(), 1u);
  return out.refusals.empty() ? std::string() : out.refusals.front();
}

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

}  // namespace
}  // namespace multidir::robot::detail

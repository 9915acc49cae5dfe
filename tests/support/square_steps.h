#pragma once
// Small hand-made steps for the conversion's tests (robot/src/step_converter.h): square perimeters about the
// platform centre under the paper's cell, the rotation about the nozzle axis fixed at 0 so the geometry is the one
// written here.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "multidir/robot/cell.h"
#include "step_converter.h"

namespace multidir::robot::detail {

constexpr double kPi = 3.14159265358979323846;
inline const std::string kShippedCell = std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json";

inline Cell shippedCell() {
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
inline Program squares(int layers) {
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

inline StepInput stepOf(const Program& program, double platformRadiusMm) {
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

inline RobotProgramOptions fixedRotation() {
  RobotProgramOptions options;
  options.rotationStepDegrees = 360.0;
  return options;
}

inline std::string onlyRefusal(const StepOutput& out) {
  EXPECT_EQ(out.refusals.size(), 1u);
  return out.refusals.empty() ? std::string() : out.refusals.front();
}

}  // namespace multidir::robot::detail

#pragma once
// A step no single rotation about the nozzle axis can print on a cell whose wrist 3 turns only 8 degrees, and
// that two can (docs/robot-cell.md, "Re-orientation within a step"). With the platform facing up under the
// vertical nozzle, q6 = phi - q1 + 90 deg on the arm's configuration 1 (phi the rotation about the nozzle axis):
// within one rotation wrist 3 follows the base joint, which turns over the part by its angular extent seen from
// the base axis, while phi sets where that range lies. Three 20 mm squares on a triangle of 60 mm circumradius
// about the platform centre, 500 mm from the base axis, and wrist 3 kept within 26..34 deg: no rotation keeps all
// three squares within it; one does the first two and another the third (found by sampling every rotation at the
// squares' corners: the window 8 deg wide works centred anywhere from 8 to 52 deg).
#include <Eigen/Geometry>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "multidir/robot/cell.h"
#include "multidir/robot/robot_program.h"

namespace multidir::test {

constexpr double kReorientPi = 3.14159265358979323846;

// The paper's cell with wrist 3 kept within 26..34 deg, its home there (30).
inline robot::Cell narrowWrist3Cell() {
  auto cell = robot::loadCell(std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json");
  if (!cell) throw std::runtime_error(cell.error().describe());
  robot::Cell c = cell.value();
  c.arm.limits[5].minRad = 26.0 * kReorientPi / 180.0;
  c.arm.limits[5].maxRad = 34.0 * kReorientPi / 180.0;
  c.home[5] = 30.0 * kReorientPi / 180.0;
  return c;
}

// The rotation about the nozzle axis sampled every degree (the 8-degree window needs finer than the default 10).
inline robot::RobotProgramOptions everyDegree() {
  robot::RobotProgramOptions options;
  options.rotationStepDegrees = 1.0;
  return options;
}

// A G-code program remembering lines by name.
struct IslandsProgram {
  std::vector<std::string> lines;
  std::map<std::string, int> marks;
  void add(const std::string& line, const std::string& mark = "") {
    lines.push_back(line);
    if (!mark.empty()) marks[mark] = static_cast<int>(lines.size());
  }
  [[nodiscard]] std::string text() const {
    std::string t;
    for (const auto& l : lines) t += l + "\n";
    return t;
  }
};

// The three squares' centres (mm, platform frame), in printing order.
inline std::vector<Eigen::Vector2d> islandCentres() {
  std::vector<Eigen::Vector2d> centres;
  for (int k = 0; k < 3; ++k) {
    const double a = (90.0 + 120.0 * k) * kReorientPi / 180.0;
    centres.emplace_back(60.0 * std::cos(a), 60.0 * std::sin(a));
  }
  return centres;
}

// One layer at z 0.4: each square's perimeter extruded, a travel between squares ("travel to square k") when
// `travelBetween`, else one extrusion from square to square (nowhere to turn).
inline IslandsProgram threeIslands(bool travelBetween) {
  IslandsProgram p;
  p.add("G90");
  p.add("M82");
  p.add("G92 E0");
  p.add("G1 Z0.4 F600");
  double e = 0.0;
  const std::vector<Eigen::Vector2d> centres = islandCentres();
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const Eigen::Vector2d c = centres[k];
    std::ostringstream to;
    to.precision(6);
    to << std::fixed;
    if (k == 0 || travelBetween) {
      to << "G1 X" << c.x() - 10 << " Y" << c.y() - 10 << " F6000";
      p.add(to.str(), "travel to square " + std::to_string(k));
    } else {
      e += 4.0;
      to << "G1 X" << c.x() - 10 << " Y" << c.y() - 10 << " E" << e << " F1200";
      p.add(to.str(), "extrusion to square " + std::to_string(k));
    }
    const double corners[4][2] = {{10, -10}, {10, 10}, {-10, 10}, {-10, -10}};
    for (const auto& corner : corners) {
      e += 1.0;
      std::ostringstream m;
      m.precision(6);
      m << std::fixed << "G1 X" << c.x() + corner[0] << " Y" << c.y() + corner[1] << " E" << e << " F1200";
      p.add(m.str());
    }
  }
  return p;
}

}  // namespace multidir::test

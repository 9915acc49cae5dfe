// The cell file written: every key of parseCell (cell.cpp), in the order docs/robot-cell.md lists them.
#include "multidir/robot/cell_file.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "multidir/core/common/atomic_file.h"

namespace multidir::robot {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// Rounded to 1e-9 so values typed as decimals read back as typed (no 0.30000000000000004 in the file).
double tidy(double v) {
  const double r = std::round(v * 1e9) / 1e9;
  return r == 0.0 ? 0.0 : r;
}

Json vector3(const Eigen::Vector3d& v) { return Json::array({tidy(v.x()), tidy(v.y()), tidy(v.z())}); }

Json rotationVectorDegrees(const Eigen::Matrix3d& rotation) {
  const Eigen::AngleAxisd turn(rotation);
  return vector3(turn.axis() * (turn.angle() / kDeg));
}

}  // namespace

std::string cellJson(const Cell& cell) {
  Json j;
  j["format"] = "multidir-robot-cell";
  j["version"] = 1;
  j["name"] = cell.name;
  j["robot"] = cell.arm.name;
  Json limits = Json::array(), speeds = Json::array(), accels = Json::array();
  for (const JointLimits& l : cell.arm.limits) {
    limits.push_back(Json::array({tidy(l.minRad / kDeg), tidy(l.maxRad / kDeg)}));
    speeds.push_back(tidy(l.maxSpeedRadPerS / kDeg));
    accels.push_back(tidy(l.maxAccelRadPerS2 / kDeg));
  }
  j["jointLimitsDegrees"] = limits;
  j["jointMaxSpeedDegreesPerS"] = speeds;
  j["jointMaxAccelDegreesPerS2"] = accels;
  j["nozzleTipMm"] = vector3(cell.nozzleTipMm);
  j["nozzleAxis"] = vector3(cell.nozzleAxis);
  j["nozzleZone"] = {{"radiusMm", tidy(cell.nozzleZoneRadiusMm)}, {"heightMm", tidy(cell.nozzleZoneHeightMm)}};
  j["flangeToPlatform"] = {{"translationMm", vector3(cell.flangeToPlatform.translation())},
                           {"rotationVectorDegrees", rotationVectorDegrees(cell.flangeToPlatform.linear())}};
  j["platformRadiusMm"] = tidy(cell.platformRadiusMm);
  j["platformThicknessMm"] = tidy(cell.platformThicknessMm);
  j["maxFilamentMmPerS"] = tidy(cell.maxFilamentMmPerS);
  j["maxProgramBytes"] = cell.maxProgramBytes;
  Json bodies = Json::array();
  for (const CollisionBox& b : cell.boxes) {
    Json box;
    box["name"] = b.name;
    box["type"] = "box";
    box["centerMm"] = vector3(b.pose.translation());
    box["rotationVectorDegrees"] = rotationVectorDegrees(b.pose.linear());
    box["sizeMm"] = vector3(b.sizeMm);
    bodies.push_back(box);
  }
  for (const CollisionCylinder& c : cell.cylinders) {
    Json cylinder;
    cylinder["name"] = c.name;
    cylinder["type"] = "cylinder";
    cylinder["baseMm"] = vector3(c.baseMm);
    cylinder["axis"] = vector3(c.axis);
    cylinder["radiusMm"] = tidy(c.radiusMm);
    cylinder["lengthMm"] = tidy(c.lengthMm);
    bodies.push_back(cylinder);
  }
  j["bodies"] = bodies;
  j["tableZMm"] = tidy(cell.tableZMm);
  Json home = Json::array();
  for (double q : cell.home) home.push_back(tidy(q / kDeg));
  j["homeDegrees"] = home;
  j["margins"] = {{"minReachMm", tidy(cell.margins.minReachMm)},
                  {"minWristDegrees", tidy(cell.margins.minWristDegrees)},
                  {"maxJointStepDegrees", tidy(cell.margins.maxJointStepDegrees)},
                  {"tableClearanceMm", tidy(cell.margins.tableClearanceMm)}};
  j["motion"] = {{"travelSpeedMmPerS", tidy(cell.motion.travelSpeedMmPerS)},
                 {"toolAccelMmPerS2", tidy(cell.motion.toolAccelMmPerS2)},
                 {"blendRadiusMm", tidy(cell.motion.blendRadiusMm)},
                 {"jointSpeedDegreesPerS", tidy(cell.motion.jointSpeedDegreesPerS)},
                 {"jointAccelDegreesPerS2", tidy(cell.motion.jointAccelDegreesPerS2)}};
  return j.dump(2) + "\n";
}

core::Status writeCell(const Cell& cell, const std::filesystem::path& path) {
  return core::writeTextFileAtomically(path.string(), cellJson(cell));
}

}  // namespace multidir::robot

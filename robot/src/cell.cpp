// The cell file: read (parseCell), judged (checkCell), both (loadCell). docs/robot-cell.md, "The cell file".
#include "multidir/robot/cell.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace multidir::robot {
namespace {

using Json = nlohmann::json;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr const char* kFormat = "multidir-robot-cell";

// A key of the wrong type or shape; caught in parseCell and turned into an Error naming the key.
struct KeyError {
  std::string key;
  std::string message;
};

double number(const Json& j, const std::string& key) {
  if (!j.is_number()) throw KeyError{key, "must be a number"};
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw KeyError{key, "must be a finite number"};
  return v;
}

Eigen::Vector3d vector3(const Json& j, const std::string& key) {
  if (!j.is_array() || j.size() != 3) throw KeyError{key, "must be an array of three numbers [x, y, z]"};
  return {number(j[0], key + "[0]"), number(j[1], key + "[1]"), number(j[2], key + "[2]")};
}

std::string text(const Json& j, const std::string& key) {
  if (!j.is_string()) throw KeyError{key, "must be a string"};
  return j.get<std::string>();
}

const Json& required(const Json& object, const std::string& name, const std::string& prefix = "") {
  if (!object.contains(name)) throw KeyError{prefix + name, "is missing; see docs/robot-cell.md for the keys"};
  return object.at(name);
}

// A rotation vector in degrees (axis times angle), as the cell file writes rotations.
Eigen::Matrix3d rotationFromVectorDegrees(const Eigen::Vector3d& v) {
  const double angle = v.norm() * kDeg;
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, v.normalized()).toRotationMatrix();
}

Eigen::Isometry3d transform(const Json& j, const std::string& key) {
  if (!j.is_object()) throw KeyError{key, "must be an object {\"translationMm\": [..], \"rotationVectorDegrees\": [..]}"};
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = vector3(required(j, "translationMm", key + "."), key + ".translationMm");
  if (j.contains("rotationVectorDegrees"))
    t.linear() = rotationFromVectorDegrees(vector3(j.at("rotationVectorDegrees"), key + ".rotationVectorDegrees"));
  return t;
}

void readLimits(const Json& cell, ArmModel& arm) {
  if (cell.contains("jointLimitsDegrees")) {
    const Json& limits = cell.at("jointLimitsDegrees");
    if (!limits.is_array() || limits.size() != 6)
      throw KeyError{"jointLimitsDegrees", "must be six [min, max] pairs, base to wrist 3"};
    for (std::size_t i = 0; i < 6; ++i) {
      const std::string key = "jointLimitsDegrees[" + std::to_string(i) + "]";
      if (!limits[i].is_array() || limits[i].size() != 2) throw KeyError{key, "must be a pair [min, max]"};
      arm.limits[i].minRad = number(limits[i][0], key + "[0]") * kDeg;
      arm.limits[i].maxRad = number(limits[i][1], key + "[1]") * kDeg;
    }
  }
  if (cell.contains("jointMaxSpeedDegreesPerS")) {
    const Json& speeds = cell.at("jointMaxSpeedDegreesPerS");
    if (!speeds.is_array() || speeds.size() != 6)
      throw KeyError{"jointMaxSpeedDegreesPerS", "must be six numbers, base to wrist 3"};
    for (std::size_t i = 0; i < 6; ++i)
      arm.limits[i].maxSpeedRadPerS = number(speeds[i], "jointMaxSpeedDegreesPerS[" + std::to_string(i) + "]") * kDeg;
  }
  if (cell.contains("jointMaxAccelDegreesPerS2")) {
    const Json& accels = cell.at("jointMaxAccelDegreesPerS2");
    if (!accels.is_array() || accels.size() != 6)
      throw KeyError{"jointMaxAccelDegreesPerS2", "must be six numbers, base to wrist 3"};
    for (std::size_t i = 0; i < 6; ++i)
      arm.limits[i].maxAccelRadPerS2 = number(accels[i], "jointMaxAccelDegreesPerS2[" + std::to_string(i) + "]") * kDeg;
  }
}

void readBodies(const Json& cell, Cell& out) {
  if (!cell.contains("bodies")) return;
  const Json& bodies = cell.at("bodies");
  if (!bodies.is_array()) throw KeyError{"bodies", "must be an array of boxes and cylinders"};
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const std::string key = "bodies[" + std::to_string(i) + "]";
    const Json& b = bodies[i];
    if (!b.is_object()) throw KeyError{key, "must be an object with \"type\": \"box\" or \"cylinder\""};
    const std::string type = text(required(b, "type", key + "."), key + ".type");
    const std::string name = b.contains("name") ? text(b.at("name"), key + ".name") : key;
    if (type == "box") {
      CollisionBox box;
      box.name = name;
      box.pose.translation() = vector3(required(b, "centerMm", key + "."), key + ".centerMm");
      if (b.contains("rotationVectorDegrees"))
        box.pose.linear() = rotationFromVectorDegrees(vector3(b.at("rotationVectorDegrees"), key + ".rotationVectorDegrees"));
      box.sizeMm = vector3(required(b, "sizeMm", key + "."), key + ".sizeMm");
      out.boxes.push_back(box);
    } else if (type == "cylinder") {
      CollisionCylinder c;
      c.name = name;
      c.baseMm = vector3(required(b, "baseMm", key + "."), key + ".baseMm");
      c.axis = vector3(required(b, "axis", key + "."), key + ".axis");
      c.radiusMm = number(required(b, "radiusMm", key + "."), key + ".radiusMm");
      c.lengthMm = number(required(b, "lengthMm", key + "."), key + ".lengthMm");
      out.cylinders.push_back(c);
    } else {
      throw KeyError{key + ".type", "is \"" + type + "\"; a body is a \"box\" or a \"cylinder\""};
    }
  }
}

void readMargins(const Json& cell, CellMargins& m) {
  if (!cell.contains("margins")) return;
  const Json& j = cell.at("margins");
  if (!j.is_object()) throw KeyError{"margins", "must be an object"};
  if (j.contains("minReachMm")) m.minReachMm = number(j.at("minReachMm"), "margins.minReachMm");
  if (j.contains("minWristDegrees")) m.minWristDegrees = number(j.at("minWristDegrees"), "margins.minWristDegrees");
  if (j.contains("maxJointStepDegrees"))
    m.maxJointStepDegrees = number(j.at("maxJointStepDegrees"), "margins.maxJointStepDegrees");
  if (j.contains("tableClearanceMm")) m.tableClearanceMm = number(j.at("tableClearanceMm"), "margins.tableClearanceMm");
}

void readMotion(const Json& cell, CellMotion& m) {
  if (!cell.contains("motion")) return;
  const Json& j = cell.at("motion");
  if (!j.is_object()) throw KeyError{"motion", "must be an object"};
  if (j.contains("travelSpeedMmPerS")) m.travelSpeedMmPerS = number(j.at("travelSpeedMmPerS"), "motion.travelSpeedMmPerS");
  if (j.contains("toolAccelMmPerS2")) m.toolAccelMmPerS2 = number(j.at("toolAccelMmPerS2"), "motion.toolAccelMmPerS2");
  if (j.contains("blendRadiusMm")) m.blendRadiusMm = number(j.at("blendRadiusMm"), "motion.blendRadiusMm");
  if (j.contains("jointSpeedDegreesPerS"))
    m.jointSpeedDegreesPerS = number(j.at("jointSpeedDegreesPerS"), "motion.jointSpeedDegreesPerS");
  if (j.contains("jointAccelDegreesPerS2"))
    m.jointAccelDegreesPerS2 = number(j.at("jointAccelDegreesPerS2"), "motion.jointAccelDegreesPerS2");
}

Cell readCell(const Json& j) {
  if (!j.is_object()) throw KeyError{"(top level)", "must be a JSON object"};
  if (text(required(j, "format"), "format") != kFormat)
    throw KeyError{"format", std::string("must be \"") + kFormat + "\""};
  const double version = number(required(j, "version"), "version");
  if (version != 1.0) throw KeyError{"version", "is " + std::to_string(version) + "; this MultiDir reads version 1"};
  Cell cell;
  cell.name = j.contains("name") ? text(j.at("name"), "name") : std::string();
  const std::string model = text(required(j, "robot"), "robot");
  auto arm = armModel(model);
  if (!arm.ok()) throw KeyError{"robot", arm.error().message};
  cell.arm = arm.value();
  readLimits(j, cell.arm);
  cell.nozzleTipMm = vector3(required(j, "nozzleTipMm"), "nozzleTipMm");
  cell.nozzleAxis = vector3(required(j, "nozzleAxis"), "nozzleAxis");
  if (j.contains("nozzleZone")) {
    const Json& zone = j.at("nozzleZone");
    if (!zone.is_object()) throw KeyError{"nozzleZone", "must be an object {\"radiusMm\", \"heightMm\"}"};
    cell.nozzleZoneRadiusMm = number(required(zone, "radiusMm", "nozzleZone."), "nozzleZone.radiusMm");
    cell.nozzleZoneHeightMm = number(required(zone, "heightMm", "nozzleZone."), "nozzleZone.heightMm");
  }
  cell.flangeToPlatform = transform(required(j, "flangeToPlatform"), "flangeToPlatform");
  if (j.contains("platformRadiusMm")) cell.platformRadiusMm = number(j.at("platformRadiusMm"), "platformRadiusMm");
  if (j.contains("platformThicknessMm"))
    cell.platformThicknessMm = number(j.at("platformThicknessMm"), "platformThicknessMm");
  cell.maxFilamentMmPerS = number(required(j, "maxFilamentMmPerS"), "maxFilamentMmPerS");
  if (j.contains("maxProgramBytes")) {
    const Json& bytes = j.at("maxProgramBytes");
    if (!bytes.is_number_unsigned()) throw KeyError{"maxProgramBytes", "must be a whole number of bytes"};
    cell.maxProgramBytes = bytes.get<std::size_t>();
  }
  readBodies(j, cell);
  cell.tableZMm = number(required(j, "tableZMm"), "tableZMm");
  const Json& home = required(j, "homeDegrees");
  if (!home.is_array() || home.size() != 6) throw KeyError{"homeDegrees", "must be six joint angles, base to wrist 3"};
  for (std::size_t i = 0; i < 6; ++i) cell.home[i] = number(home[i], "homeDegrees[" + std::to_string(i) + "]") * kDeg;
  readMargins(j, cell.margins);
  readMotion(j, cell.motion);
  return cell;
}

std::string fixed1(double v) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(1);
  s << v;
  return s.str();
}

}  // namespace

core::Result<Cell> parseCell(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    return core::Error{core::ErrorCode::FileNotFound, "cannot open the cell file; check the path",
                       path.string()};
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const Json j = Json::parse(buffer.str(), nullptr, false);
  if (j.is_discarded()) {
    return core::Error{core::ErrorCode::MalformedFile, "the cell file is not valid JSON", path.string()};
  }
  try {
    return readCell(j);
  } catch (const KeyError& e) {
    const bool unknownModel = e.key == "robot" && e.message.rfind("unknown robot model", 0) == 0;
    return core::Error{unknownModel ? core::ErrorCode::InvalidParameter : core::ErrorCode::MalformedFile,
                       e.key + " " + e.message, path.string()};
  }
}

std::vector<CellProblem> checkCell(const Cell& cell) {
  std::vector<CellProblem> problems;
  auto add = [&](std::string key, std::string message) { problems.push_back({std::move(key), std::move(message)}); };

  const double axisLength = cell.nozzleAxis.norm();
  if (std::abs(axisLength - 1.0) > 1e-6) {
    add("nozzleAxis", "has length " + std::to_string(axisLength) +
                          "; give a unit vector from the nozzle tip up into the extruder, e.g. [0, 0, 1]");
  }
  for (int j = 0; j < 6; ++j) {
    const JointLimits& l = cell.arm.limits[static_cast<std::size_t>(j)];
    const std::string key = "jointLimitsDegrees[" + std::to_string(j) + "]";
    if (!(l.minRad < l.maxRad)) add(key, "min must be below max");
    if (l.minRad < -2 * kPi - 1e-9 || l.maxRad > 2 * kPi + 1e-9)
      add(key, "reaches past the arm's own +-360 deg; narrow it to within [-360, 360]");
    if (!(l.maxSpeedRadPerS > 0.0))
      add("jointMaxSpeedDegreesPerS[" + std::to_string(j) + "]", "must be above 0");
    if (!(l.maxAccelRadPerS2 > 0.0))
      add("jointMaxAccelDegreesPerS2[" + std::to_string(j) + "]", "must be above 0");
    const double h = cell.home[static_cast<std::size_t>(j)];
    if (h < l.minRad || h > l.maxRad) {
      add("homeDegrees[" + std::to_string(j) + "]",
          "is " + fixed1(h / kDeg) + " deg, outside the joint's limits [" + fixed1(l.minRad / kDeg) + ", " +
              fixed1(l.maxRad / kDeg) + "]; move home within them or widen jointLimitsDegrees");
    }
  }
  const double flangeOffset = cell.flangeToPlatform.translation().norm();
  if (flangeOffset > 500.0) {
    add("flangeToPlatform.translationMm", "puts the platform centre " + fixed1(flangeOffset) +
                                              " mm from the flange; measure it again (a platform mount is well under 500 mm)");
  }
  if (!(cell.platformRadiusMm > 0.0)) add("platformRadiusMm", "must be above 0: the platform disc's radius");
  if (!(cell.platformThicknessMm >= 0.0)) add("platformThicknessMm", "must be 0 or more");
  if (!(cell.maxFilamentMmPerS > 0.0)) add("maxFilamentMmPerS", "must be above 0: the filament speed at analog out 0 = 1");
  if (cell.maxProgramBytes < kMinProgramBytes)
    add("maxProgramBytes", "must be at least " + std::to_string(kMinProgramBytes) +
                               " bytes: a program part holds its preamble, the step's closing lines and some moves (the "
                               "default, " + std::to_string(kDefaultMaxProgramBytes) + ", is what UR controllers are "
                               "reported to accept)");
  if (!(cell.nozzleZoneRadiusMm >= 0.0) || !(cell.nozzleZoneHeightMm >= 0.0))
    add("nozzleZone", "radiusMm and heightMm must be 0 or more");
  for (std::size_t i = 0; i < cell.boxes.size(); ++i) {
    const CollisionBox& b = cell.boxes[i];
    if (!(b.sizeMm.minCoeff() > 0.0))
      add("bodies \"" + b.name + "\".sizeMm", "every edge must be above 0 mm");
  }
  for (const CollisionCylinder& c : cell.cylinders) {
    if (std::abs(c.axis.norm() - 1.0) > 1e-6) add("bodies \"" + c.name + "\".axis", "must be a unit vector");
    if (!(c.radiusMm > 0.0) || !(c.lengthMm > 0.0))
      add("bodies \"" + c.name + "\"", "radiusMm and lengthMm must be above 0");
  }
  if (!(cell.tableZMm < cell.nozzleTipMm.z())) {
    add("tableZMm", "is " + fixed1(cell.tableZMm) + " mm, not below the nozzle tip (z " + fixed1(cell.nozzleTipMm.z()) +
                        " mm); the table plane is under the nozzle, measure both in the robot base frame");
  }
  const CellMargins& m = cell.margins;
  if (!(m.minReachMm >= 0.0)) add("margins.minReachMm", "must be 0 or more");
  if (!(m.minWristDegrees >= 0.0 && m.minWristDegrees < 90.0)) add("margins.minWristDegrees", "must be in [0, 90)");
  if (!(m.maxJointStepDegrees > 0.0)) add("margins.maxJointStepDegrees", "must be above 0");
  if (!(m.tableClearanceMm >= 0.0)) add("margins.tableClearanceMm", "must be 0 or more");
  const CellMotion& mo = cell.motion;
  if (!(mo.travelSpeedMmPerS > 0.0)) add("motion.travelSpeedMmPerS", "must be above 0");
  if (!(mo.toolAccelMmPerS2 > 0.0)) add("motion.toolAccelMmPerS2", "must be above 0");
  if (!(mo.blendRadiusMm >= 0.0)) add("motion.blendRadiusMm", "must be 0 or more");
  if (!(mo.jointSpeedDegreesPerS > 0.0)) add("motion.jointSpeedDegreesPerS", "must be above 0");
  if (!(mo.jointAccelDegreesPerS2 > 0.0)) add("motion.jointAccelDegreesPerS2", "must be above 0");

  // Home: reachable (its own pose solved again within the limits) and the platform clear of the table.
  const Eigen::Isometry3d homeFlange = forwardKinematics(cell.arm, cell.home);
  std::array<IkSolution, 8> solutions{};
  const int count = inverseKinematics(cell.arm, homeFlange, solutions);
  if (!nearestWithinLimits(cell.arm, solutions.data(), count, cell.home).has_value()) {
    add("homeDegrees", "is not reachable within the joint limits (a singular pose?); choose a home away from "
                       "the shoulder, elbow and wrist singularities");
  }
  const Eigen::Isometry3d homePlatform = homeFlange * cell.flangeToPlatform;
  const double lowest = homePlatform.translation().z() -
                        cell.platformRadiusMm * std::sqrt(std::max(0.0, 1.0 - std::pow(homePlatform.linear()(2, 2), 2))) -
                        cell.platformThicknessMm * std::abs(homePlatform.linear()(2, 2));
  if (lowest < cell.tableZMm + m.tableClearanceMm) {
    add("homeDegrees", "puts the platform's lowest point at z " + fixed1(lowest) + " mm, not " +
                           fixed1(m.tableClearanceMm) + " mm above the table (tableZMm " + fixed1(cell.tableZMm) +
                           "); choose a home that holds the platform higher");
  }
  return problems;
}

core::Result<Cell> loadCell(const std::filesystem::path& path) {
  auto cell = parseCell(path);
  if (!cell.ok()) return cell;
  const auto problems = checkCell(cell.value());
  if (problems.empty()) return cell;
  std::string message = "the cell has " + std::to_string(problems.size()) + " problem(s):";
  for (const auto& p : problems) message += "\n  " + p.key + ": " + p.message;
  message += "\n(multidir cell check lists them too)";
  return core::Error{core::ErrorCode::InvalidParameter, message, path.string()};
}

Eigen::Isometry3d platformPose(const Cell& cell, const Joints& joints) {
  return forwardKinematics(cell.arm, joints) * cell.flangeToPlatform;
}

}  // namespace multidir::robot

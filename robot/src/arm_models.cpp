// The arm models: UR's published DH tables and joint speeds.
//
// DH tables (theta offsets all 0, a and d in metres there, here in mm): Universal Robots, "DH Parameters for
// calculations of kinematics and dynamics" (support article, universal-robots.com/articles/ur/
// application-installation/dh-parameters-for-calculations-of-kinematics-and-dynamics/; CB3 software 3.7, e-Series
// 5.1). The CB3 rows (ur3, ur5, ur10) are that article's "UR3", "UR5", "UR10" (the latest CB3 series; older CB2
// manuals list slightly different UR5 tables, "serie 1/2").
//
// Max joint speeds: the arms' user manuals, technical specifications ("joint ranges / speed"): base and shoulder
// 180 deg/s on UR3, UR5, UR3e, UR5e, 120 deg/s on UR10, UR10e, UR16e; elbow 180 deg/s on all; wrists 360 deg/s on
// UR3 and UR3e, 180 deg/s on the others. Joint ranges are +-360 deg on every joint (the cell may narrow them).
// UR publishes no joint acceleration limit: the default is URScript's default movej acceleration, 1.4 rad/s^2
// (URScript manual, movej), which the controller accepts on every model; a cell file may set its own.
#include <algorithm>
#include <cmath>

#include "multidir/robot/ur_kinematics.h"

namespace multidir::robot {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kDefaultAccelRadPerS2 = 1.4;

struct PublishedTable {
  const char* name;
  double d1, a2, a3, d4, d5, d6;       // metres, as published
  std::array<double, 6> speedDegPerS;  // max joint speeds
};

constexpr PublishedTable kTables[] = {
    {"ur3", 0.1519, -0.24365, -0.21325, 0.11235, 0.08535, 0.0819, {180, 180, 180, 360, 360, 360}},
    {"ur5", 0.089159, -0.425, -0.39225, 0.10915, 0.09465, 0.0823, {180, 180, 180, 180, 180, 180}},
    {"ur10", 0.1273, -0.612, -0.5723, 0.163941, 0.1157, 0.0922, {120, 120, 180, 180, 180, 180}},
    {"ur3e", 0.15185, -0.24355, -0.2132, 0.13105, 0.08535, 0.0921, {180, 180, 180, 360, 360, 360}},
    {"ur5e", 0.1625, -0.425, -0.3922, 0.1333, 0.0997, 0.0996, {180, 180, 180, 180, 180, 180}},
    {"ur10e", 0.1807, -0.6127, -0.57155, 0.17415, 0.11985, 0.11655, {120, 120, 180, 180, 180, 180}},
    {"ur16e", 0.1807, -0.4784, -0.36, 0.17415, 0.11985, 0.11655, {120, 120, 180, 180, 180, 180}},
};

ArmModel fromTable(const PublishedTable& t) {
  ArmModel m;
  m.name = t.name;
  m.d = {t.d1 * 1000.0, 0.0, 0.0, t.d4 * 1000.0, t.d5 * 1000.0, t.d6 * 1000.0};
  m.a = {0.0, t.a2 * 1000.0, t.a3 * 1000.0, 0.0, 0.0, 0.0};
  m.alpha = {kPi / 2, 0.0, 0.0, kPi / 2, -kPi / 2, 0.0};
  for (int j = 0; j < 6; ++j) {
    m.limits[j] = {-360.0 * kDeg, 360.0 * kDeg, t.speedDegPerS[j] * kDeg, kDefaultAccelRadPerS2};
  }
  return m;
}

}  // namespace

std::vector<std::string> armModelNames() {
  std::vector<std::string> names;
  for (const auto& t : kTables) names.emplace_back(t.name);
  return names;
}

core::Result<ArmModel> armModel(std::string_view name) {
  for (const auto& t : kTables) {
    if (name == t.name) return fromTable(t);
  }
  std::string known;
  for (const auto& t : kTables) known += std::string(known.empty() ? "" : ", ") + t.name;
  return core::Error{core::ErrorCode::InvalidParameter,
                     "unknown robot model \"" + std::string(name) + "\"; the known models are " + known,
                     "robot model"};
}

}  // namespace multidir::robot

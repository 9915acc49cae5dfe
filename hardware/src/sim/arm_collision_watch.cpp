#include "sim/arm_collision_watch.h"

#include <algorithm>
#include <cmath>

#include "multidir/robot/arm_links.h"

namespace multidir::hardware::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRimPoints = 72;

bool insideBox(const robot::CollisionBox& b, const Eigen::Vector3d& x) {
  const Eigen::Vector3d local = b.pose.inverse() * x;
  return (local.cwiseAbs().array() <= (b.sizeMm / 2).array()).all();
}

bool insideCylinder(const robot::CollisionCylinder& c, const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = x - c.baseMm;
  const double h = d.dot(c.axis);
  return h >= 0.0 && h <= c.lengthMm && (d - h * c.axis).norm() <= c.radiusMm;
}

}  // namespace

ArmCollisionWatch::ArmCollisionWatch(robot::Cell cell) : m_cell(std::move(cell)) {
  // Contact, not the planner's margin: the table plane itself.
  m_cell.margins.tableClearanceMm = 0.0;
  for (int i = 0; i < kRimPoints; ++i) {
    const double a = 2.0 * kPi * i / kRimPoints;
    const Eigen::Vector3d rim(m_cell.platformRadiusMm * std::cos(a), m_cell.platformRadiusMm * std::sin(a), 0.0);
    m_platform.push_back(rim);
    m_platform.push_back(rim - Eigen::Vector3d(0.0, 0.0, m_cell.platformThicknessMm));
  }
}

std::string ArmCollisionWatch::contactAt(const robot::Joints& q) const {
  const robot::ArmClearance links = robot::armClearance(m_cell, q);
  if (links.mm <= 0.0) {
    const std::string link = robot::armLinkSolids(m_cell.arm, q)[static_cast<std::size_t>(links.link)].name;
    return "the arm's " + link + (links.body == "the table" ? " touches the table" : " touches the cell's body \"" + links.body + "\"");
  }
  const Eigen::Isometry3d platform = robot::forwardKinematics(m_cell.arm, q) * m_cell.flangeToPlatform;
  for (const Eigen::Vector3d& p : m_platform) {
    const Eigen::Vector3d x = platform * p;
    // The nozzle's own zone: where the part meets the nozzle by design.
    const Eigen::Vector3d d = x - m_cell.nozzleTipMm;
    const double h = d.dot(m_cell.nozzleAxis);
    if (h <= m_cell.nozzleZoneHeightMm && (d - h * m_cell.nozzleAxis).norm() <= m_cell.nozzleZoneRadiusMm) continue;
    for (const robot::CollisionBox& b : m_cell.boxes)
      if (insideBox(b, x)) return "the platform touches the cell's body \"" + b.name + "\"";
    for (const robot::CollisionCylinder& c : m_cell.cylinders)
      if (insideCylinder(c, x)) return "the platform touches the cell's body \"" + c.name + "\"";
    if (x.z() <= m_cell.tableZMm) return "the platform touches the table";
  }
  return {};
}

std::string ArmCollisionWatch::firstContact(const robot::Joints& from, const robot::Joints& to) const {
  // How far any point can move: the links' bound plus each joint's turn times the platform's reach beyond the
  // flange.
  const double platformReach = m_cell.flangeToPlatform.translation().norm() +
                               std::hypot(m_cell.platformRadiusMm, m_cell.platformThicknessMm);
  double turns = 0.0;
  for (std::size_t j = 0; j < 6; ++j) turns += std::abs(to[j] - from[j]);
  const double bound = robot::armMotionBoundMm(m_cell.arm, from, to) + turns * platformReach;
  const int samples = std::max(1, static_cast<int>(std::ceil(bound / kWatchSampleMm)));
  for (int s = 1; s <= samples; ++s) {
    robot::Joints q{};
    for (std::size_t j = 0; j < 6; ++j) q[j] = from[j] + (to[j] - from[j]) * s / samples;
    if (std::string hit = contactAt(q); !hit.empty()) return hit;
  }
  return {};
}

}  // namespace multidir::hardware::sim

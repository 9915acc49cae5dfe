// A movej's straight line in joint space checked against the cell: links continuously (split until the motion
// bound is covered by the clearances at the ends), the carried points every kJointMoveSampleDegrees.
#include "joint_move_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "multidir/robot/arm_links.h"

namespace multidir::robot::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Below this turn of the joint that turns most, the links' check stops splitting.
constexpr double kFinestLinkSplitRad = 1e-4;

Joints between(const Joints& a, const Joints& b, double t) {
  Joints q{};
  for (std::size_t j = 0; j < 6; ++j) q[j] = a[j] + t * (b[j] - a[j]);
  return q;
}

double largestTurn(const Joints& a, const Joints& b) {
  double worst = 0.0;
  for (std::size_t j = 0; j < 6; ++j) worst = std::max(worst, std::abs(b[j] - a[j]));
  return worst;
}

std::string linkHit(const Cell& cell, const Joints& q, const ArmClearance& c) {
  const std::string link = armLinkSolids(cell.arm, q)[static_cast<std::size_t>(c.link)].name;
  if (c.body == "the table")
    return "the arm's " + link + " would come within " + std::to_string(static_cast<int>(cell.margins.tableClearanceMm)) +
           " mm of the table while the platform turns about the nozzle axis";
  return "the arm's " + link + " would hit the extruder's body \"" + c.body +
         "\" while the platform turns about the nozzle axis";
}

std::string linksBetween(const Cell& cell, const Joints& a, const ArmClearance& ca, const Joints& b,
                         const ArmClearance& cb) {
  if (cb.mm <= 0.0) return linkHit(cell, b, cb);
  if (ca.mm + cb.mm > armMotionBoundMm(cell.arm, a, b)) return {};
  if (largestTurn(a, b) < kFinestLinkSplitRad) return {};
  const Joints m = between(a, b, 0.5);
  const ArmClearance cm = armClearance(cell, m);
  if (cm.mm <= 0.0) return linkHit(cell, m, cm);
  std::string hit = linksBetween(cell, a, ca, m, cm);
  if (hit.empty()) hit = linksBetween(cell, m, cm, b, cb);
  return hit;
}

bool insideBody(const Cell& cell, const Eigen::Vector3d& x, std::string& name) {
  for (const CollisionBox& b : cell.boxes) {
    const Eigen::Vector3d local = b.pose.inverse() * x;
    if ((local.cwiseAbs().array() <= (b.sizeMm / 2).array()).all()) {
      name = b.name;
      return true;
    }
  }
  for (const CollisionCylinder& c : cell.cylinders) {
    const Eigen::Vector3d d = x - c.baseMm;
    const double h = d.dot(c.axis);
    if (h >= 0.0 && h <= c.lengthMm && (d - h * c.axis).norm() <= c.radiusMm) {
      name = c.name;
      return true;
    }
  }
  return false;
}

bool inNozzleZone(const Cell& cell, const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = x - cell.nozzleTipMm;
  const double h = d.dot(cell.nozzleAxis);
  return h <= cell.nozzleZoneHeightMm && (d - h * cell.nozzleAxis).norm() <= cell.nozzleZoneRadiusMm;
}

const char* carriedName(CarriedPoint::Kind kind) {
  switch (kind) {
    case CarriedPoint::Kind::Platform:
      return "the platform";
    case CarriedPoint::Kind::EarlierStep:
      return "the part printed in earlier steps";
    case CarriedPoint::Kind::ThisStep:
      return "this step's part";
  }
  return "the part";
}

}  // namespace

std::string jointMoveCollision(const Cell& cell, const std::vector<CarriedPoint>& carried,
                               const Eigen::Isometry3d& platformToFile, double printedUpToFileZ, const Joints& from,
                               const Joints& to) {
  const std::string links = linksBetween(cell, from, armClearance(cell, from), to, armClearance(cell, to));
  if (!links.empty()) return links;
  const int samples =
      std::max(1, static_cast<int>(std::ceil(largestTurn(from, to) / (kJointMoveSampleDegrees * kPi / 180.0))));
  for (int s = 0; s <= samples; ++s) {
    const Joints q = between(from, to, static_cast<double>(s) / samples);
    std::string hit = armOnTable(cell, q);
    if (!hit.empty()) return hit + " while the platform turns about the nozzle axis";
    const Eigen::Isometry3d tcp = platformPose(cell, q);
    for (const CarriedPoint& p : carried) {
      if (p.kind == CarriedPoint::Kind::ThisStep && (platformToFile * p.platformMm).z() > printedUpToFileZ + 1e-6)
        continue;  // not printed yet
      const Eigen::Vector3d world = tcp * p.platformMm;
      if (inNozzleZone(cell, world)) continue;
      std::string body;
      char where[96];
      std::snprintf(where, sizeof where, " (at base x %.1f y %.1f z %.1f mm)", world.x(), world.y(), world.z());
      if (insideBody(cell, world, body))
        return std::string(carriedName(p.kind)) + " would hit the extruder's body \"" + body + "\"" + where +
               " while the platform turns about the nozzle axis";
      if (world.z() < cell.tableZMm + cell.margins.tableClearanceMm)
        return std::string(carriedName(p.kind)) + " would come within " +
               std::to_string(static_cast<int>(cell.margins.tableClearanceMm)) + " mm of the table" + where +
               " while the platform turns about the nozzle axis";
    }
  }
  return {};
}

}  // namespace multidir::robot::detail

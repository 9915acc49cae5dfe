// The arm's links as capsules along the DH model, and their clearance from the cell's bodies and the table.
#include "multidir/robot/arm_links.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace multidir::robot {
namespace {

// Estimated radii of the links' tubes and housings (UR publishes no collision geometry; these are the outer
// radii of the tubes and joint housings as the arms' dimension drawings show them, rounded up), by the arm's size
// like housingRadiusMm: the UR3s (a2 + a3 under 600 mm), the UR5s (under 900 mm) and the larger arms.
struct LinkRadii {
  double upperArm, forearm, wrist;
};
LinkRadii linkRadii(const ArmModel& arm) {
  const double reach = std::abs(arm.a[1]) + std::abs(arm.a[2]);
  if (reach < 600.0) return {45.0, 35.0, 32.0};
  if (reach < 900.0) return {54.0, 40.0, 45.0};
  return {75.0, 60.0, 45.0};
}

// DH frames 0..6 origins and z axes for the joints.
struct Frames {
  std::array<Eigen::Vector3d, 7> origin;
  std::array<Eigen::Vector3d, 7> z;
};
Frames dhFrames(const ArmModel& arm, const Joints& q) {
  Frames f;
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  f.origin[0] = Eigen::Vector3d::Zero();
  f.z[0] = Eigen::Vector3d::UnitZ();
  for (std::size_t j = 0; j < 6; ++j) {
    const double ct = std::cos(q[j]), st = std::sin(q[j]), ca = std::cos(arm.alpha[j]), sa = std::sin(arm.alpha[j]);
    Eigen::Matrix4d m;
    m << ct, -st * ca, st * sa, arm.a[j] * ct, st, ct * ca, -ct * sa, arm.a[j] * st, 0.0, sa, ca, arm.d[j], 0.0, 0.0,
        0.0, 1.0;
    t = t * m;
    f.origin[j + 1] = t.block<3, 1>(0, 3);
    f.z[j + 1] = t.block<3, 1>(0, 2);
  }
  return f;
}

double pointToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double pointToBox(const CollisionBox& box, const Eigen::Isometry3d& baseToBox, const Eigen::Vector3d& p) {
  const Eigen::Vector3d local = baseToBox * p;
  return (local.cwiseAbs() - box.sizeMm / 2).cwiseMax(0.0).norm();
}

double pointToCylinder(const CollisionCylinder& c, const Eigen::Vector3d& p) {
  const Eigen::Vector3d d = p - c.baseMm;
  const double h = d.dot(c.axis);
  const double along = std::max({0.0, -h, h - c.lengthMm});
  const double across = std::max(0.0, (d - h * c.axis).norm() - c.radiusMm);
  return std::hypot(along, across);
}

// The least of a convex function of a point along the segment: the distance to a convex body is convex along a
// line, so a golden-section search finds it (to 1e-6 of the segment's length).
template <typename Distance>
double segmentDistance(const Eigen::Vector3d& a, const Eigen::Vector3d& b, Distance distance) {
  constexpr double kGolden = 0.6180339887498949;
  double lo = 0.0, hi = 1.0;
  double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
  double f1 = distance(a + x1 * (b - a)), f2 = distance(a + x2 * (b - a));
  for (int i = 0; i < 30; ++i) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kGolden * (hi - lo);
      f1 = distance(a + x1 * (b - a));
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kGolden * (hi - lo);
      f2 = distance(a + x2 * (b - a));
    }
  }
  return std::min({f1, f2, distance(a), distance(b)});
}

// Beyond this distance of a body's bounding sphere a link's clearance from the body is that distance (a lower
// bound, enough for every use: a collision is at zero, the motion bound between samples is a few mm).
constexpr double kExactWithinMm = 50.0;

}  // namespace

std::array<ArmLinkSolid, kArmLinkCount> armLinkSolids(const ArmModel& arm, const Joints& q) {
  const Frames f = dhFrames(arm, q);
  const LinkRadii r = linkRadii(arm);
  const double wrist3Length = std::max(0.0, arm.d[5] - r.wrist);
  return {{{"upper arm", f.origin[1], f.origin[2], r.upperArm},
           {"forearm", f.origin[2], f.origin[3], r.forearm},
           {"wrist 1", f.origin[3], f.origin[4], r.wrist},
           {"wrist 2", f.origin[4], f.origin[5], r.wrist},
           {"wrist 3", f.origin[5], f.origin[5] + wrist3Length * f.z[6], r.wrist}}};
}

ArmClearance armClearance(const Cell& cell, const Joints& q) {
  ArmClearance least;
  least.mm = std::numeric_limits<double>::infinity();
  const auto links = armLinkSolids(cell.arm, q);
  auto consider = [&](double mm, int link, const std::string& body) {
    if (mm < least.mm) least = {mm, link, body};
  };
  const double floor = cell.tableZMm + cell.margins.tableClearanceMm;
  for (int i = 0; i < kArmLinkCount; ++i) {
    const ArmLinkSolid& l = links[static_cast<std::size_t>(i)];
    // The upper arm's shoulder end stands where the arm is mounted; its lowest point elsewhere is its elbow end.
    const double lowest = i == 0 ? l.toMm.z() : std::min(l.fromMm.z(), l.toMm.z());
    consider(lowest - l.radiusMm - floor, i, "the table");
    // Each body first by its bounding sphere; the exact distance only when the sphere is near.
    for (const auto& box : cell.boxes) {
      const double sphere = 0.5 * box.sizeMm.norm();
      const double bound = pointToSegment(box.pose.translation(), l.fromMm, l.toMm) - sphere - l.radiusMm;
      if (bound >= least.mm) continue;
      if (bound > kExactWithinMm) {
        consider(bound, i, box.name);
        continue;
      }
      const Eigen::Isometry3d baseToBox = box.pose.inverse();
      consider(segmentDistance(l.fromMm, l.toMm,
                               [&](const Eigen::Vector3d& p) { return pointToBox(box, baseToBox, p); }) -
                   l.radiusMm,
               i, box.name);
    }
    for (const auto& c : cell.cylinders) {
      const Eigen::Vector3d centre = c.baseMm + 0.5 * c.lengthMm * c.axis;
      const double sphere = std::hypot(0.5 * c.lengthMm, c.radiusMm);
      const double bound = pointToSegment(centre, l.fromMm, l.toMm) - sphere - l.radiusMm;
      if (bound >= least.mm) continue;
      if (bound > kExactWithinMm) {
        consider(bound, i, c.name);
        continue;
      }
      consider(segmentDistance(l.fromMm, l.toMm, [&](const Eigen::Vector3d& p) { return pointToCylinder(c, p); }) -
                   l.radiusMm,
               i, c.name);
    }
  }
  return least;
}

double armMotionBoundMm(const ArmModel& arm, const Joints& a, const Joints& b) {
  const LinkRadii r = linkRadii(arm);
  const double rMax = std::max({r.upperArm, r.forearm, r.wrist});
  const double d4 = std::abs(arm.d[3]), d5 = std::abs(arm.d[4]), d6 = std::abs(arm.d[5]);
  const double a3 = std::abs(arm.a[2]);
  const double whole = std::abs(arm.a[1]) + a3 + d4 + d5 + d6 + rMax;
  // The farthest a link point beyond each joint lies from that joint's axis (docs/robot-cell.md, "Collisions").
  const std::array<double, 6> lever = {whole, whole, a3 + d4 + d5 + d6 + rMax, d5 + d6 + rMax, d6 + rMax, rMax};
  double bound = 0.0;
  for (std::size_t j = 0; j < 6; ++j) bound += std::abs(b[j] - a[j]) * lever[j];
  return bound;
}

}  // namespace multidir::robot

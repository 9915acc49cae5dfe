// A movej's straight line in joint space checked against the cell: links continuously (split until the motion
// bound is covered by the clearances at the ends), the housings and the carried points stepping along by their
// clearance (kJointMoveSampleMm at least).
#include "joint_move_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "multidir/robot/arm_frames.h"
#include "multidir/robot/arm_links.h"
#include "step_run.h"

namespace multidir::robot::detail {
namespace {

// Below this turn of the joint that turns most, the links' check stops splitting.
constexpr double kFinestLinkSplitRad = 1e-4;
// A blocked move's refusal says how deep the links go, looked at this many times along it.
constexpr int kDepthLooks = 200;

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

std::string mm1(double v) { return fixedText(v, 1); }

std::string linkHit(const Cell& cell, const Joints& q, const ArmClearance& c) {
  const std::string link = armLinkSolids(cell.arm, q)[static_cast<std::size_t>(c.link)].name;
  if (c.body == "the table")
    return "the arm's " + link + " would come within " + mm1(cell.margins.tableClearanceMm) + " mm of the table";
  return "the arm's " + link + " would hit the extruder's body \"" + c.body + "\"";
}

// The first pose along a to b (in path order) at which a link touches a body or comes within the table's
// clearance, or an empty string: halves are looked at left first, and an interval whose end clearances cover the
// links' motion bound is clear.
std::string linksBetween(const Cell& cell, const Joints& a, const ArmClearance& ca, const Joints& b,
                         const ArmClearance& cb) {
  if (ca.mm > 0.0 && cb.mm > 0.0 && ca.mm + cb.mm > armMotionBoundMm(cell.arm, a, b)) return {};
  if (largestTurn(a, b) < kFinestLinkSplitRad) {
    if (ca.mm <= 0.0) return linkHit(cell, a, ca);
    return cb.mm <= 0.0 ? linkHit(cell, b, cb) : std::string();
  }
  const Joints m = between(a, b, 0.5);
  const ArmClearance cm = armClearance(cell, m);
  std::string hit = linksBetween(cell, a, ca, m, cm);
  if (hit.empty()) hit = linksBetween(cell, m, cm, b, cb);
  return hit;
}

// The least distance from x to the cell's boxes and cylinders (0 inside one), naming the nearest.
double distanceToBodies(const Cell& cell, const Eigen::Vector3d& x, std::string& name) {
  double least = std::numeric_limits<double>::infinity();
  for (const CollisionBox& b : cell.boxes) {
    const Eigen::Vector3d local = b.pose.inverse() * x;
    const double d = (local.cwiseAbs() - b.sizeMm / 2).cwiseMax(0.0).norm();
    if (d < least) {
      least = d;
      name = b.name;
    }
  }
  for (const CollisionCylinder& c : cell.cylinders) {
    const Eigen::Vector3d v = x - c.baseMm;
    const double h = v.dot(c.axis);
    const double d = std::hypot(std::max({-h, h - c.lengthMm, 0.0}), std::max((v - h * c.axis).norm() - c.radiusMm, 0.0));
    if (d < least) {
      least = d;
      name = c.name;
    }
  }
  return least;
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

// A sphere about each body, for the quick test that spares most samples the point-by-point one.
struct Sphere {
  Eigen::Vector3d centre;
  double radius;
};

std::vector<Sphere> bodySpheres(const Cell& cell) {
  std::vector<Sphere> spheres;
  for (const CollisionBox& b : cell.boxes) spheres.push_back({b.pose.translation(), 0.5 * b.sizeMm.norm()});
  for (const CollisionCylinder& c : cell.cylinders)
    spheres.push_back({c.baseMm + 0.5 * c.lengthMm * c.axis, std::hypot(c.radiusMm, 0.5 * c.lengthMm)});
  return spheres;
}

}  // namespace

std::string jointMoveCollision(const JointMoveScene& scene, const Joints& from, const Joints& to) {
  const Cell& cell = *scene.cell;
  const std::string links = linksBetween(cell, from, armClearance(cell, from), to, armClearance(cell, to));
  if (!links.empty()) {
    // How deep: the least clearance of any link from any body or the table along the move (200 looks).
    double least = 0.0;
    for (int k = 0; k <= kDepthLooks; ++k) least = std::min(least, armClearance(cell, between(from, to, static_cast<double>(k) / kDepthLooks)).mm);
    return links + " (the links' least clearance along the move: " + mm1(least) + " mm)";
  }
  // The carried points that count, and how far the farthest lies from the platform's centre and from the flange.
  std::vector<const CarriedPoint*> carried;
  double aboutCentre = 0.0, aboutFlange = 0.0;
  for (const CarriedPoint& p : *scene.carried) {
    if (p.kind == CarriedPoint::Kind::ThisStep && (scene.platformToFile * p.platformMm).z() > scene.printedUpToFileZ + 1e-6)
      continue;  // not printed yet
    carried.push_back(&p);
    aboutCentre = std::max(aboutCentre, p.platformMm.norm());
    aboutFlange = std::max(aboutFlange, (cell.flangeToPlatform * p.platformMm).norm());
  }
  // No point moves farther than the links' bound plus each joint's turn times the carried points' reach beyond
  // the flange: `rate` mm over the whole move, in proportion along it. So from a pose whose housings and carried
  // points are c mm clear, nothing can meet a body or the table before the path has gone c / rate further: the
  // check steps by the clearance, and by kJointMoveSampleMm at least.
  double turns = 0.0;
  for (std::size_t j = 0; j < 6; ++j) turns += std::abs(to[j] - from[j]);
  const double rate = armMotionBoundMm(cell.arm, from, to) + turns * aboutFlange;
  const std::vector<Sphere> spheres = bodySpheres(cell);
  const double floor = cell.tableZMm + cell.margins.tableClearanceMm;
  const double housingFloor = floor + housingRadiusMm(cell.arm);
  double t = 0.0;
  while (true) {
    const Joints q = between(from, to, t);
    const std::array<Eigen::Isometry3d, 7> frames = armFrames(cell.arm, q);
    double clearance = std::numeric_limits<double>::infinity();
    for (std::size_t f = 2; f <= 6; ++f) clearance = std::min(clearance, frames[f].translation().z() - housingFloor);
    if (clearance < 0.0) return armOnTable(cell, q);
    const Eigen::Isometry3d tcp = frames[6] * cell.flangeToPlatform;
    const Eigen::Vector3d centre = tcp.translation();
    // The carried points as a sphere about the platform's centre first; each point only when the sphere is near.
    double gap = centre.z() - aboutCentre - floor;
    for (const Sphere& b : spheres) gap = std::min(gap, (b.centre - centre).norm() - b.radius - aboutCentre);
    if (gap > 0.0) {
      clearance = std::min(clearance, gap);
    } else {
      for (const CarriedPoint* p : carried) {
        const Eigen::Vector3d world = tcp * p->platformMm;
        if (inNozzleZone(cell, world)) continue;
        std::string body;
        const double d = distanceToBodies(cell, world, body);
        const auto where = [&world] {
          return " (at base x " + mm1(world.x()) + " y " + mm1(world.y()) + " z " + mm1(world.z()) + " mm)";
        };
        if (d <= 0.0)
          return std::string(carriedName(p->kind)) + " would hit the extruder's body \"" + body + "\"" + where();
        if (world.z() < floor)
          return std::string(carriedName(p->kind)) + " would come within " + mm1(cell.margins.tableClearanceMm) +
                 " mm of the table" + where();
        clearance = std::min({clearance, d, world.z() - floor});
      }
    }
    if (t >= 1.0 || rate <= 0.0) break;
    t = std::min(1.0, t + std::max(clearance, kJointMoveSampleMm) / rate);
  }
  return {};
}

}  // namespace multidir::robot::detail

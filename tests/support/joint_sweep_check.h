#pragma once
// An independent check of a program's joint moves for the tests (docs/robot-cell.md, "Joint moves"): the
// script's movej targets read in order, each joint path from the one before sampled finely (no joint turns more
// than 0.1 degree between samples), and at every sample the arm's links (points every 1 mm along the capsules of
// armLinkSolids, their radius off), the platform disc's rim (top and bottom) and the given carried points posed by
// forward kinematics against the cell's boxes and cylinders and the table plane itself, with point-to-solid
// distances written here: nothing of the planner's or of its check is used.
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "multidir/robot/arm_links.h"
#include "multidir/robot/cell.h"

namespace multidir::test {

// The joint moves of a URScript program, in order: each movej's start and end joints (radians). A movej after
// movels starts where the last movel ended: its TCP pose solved (the cell's flangeToPlatform) nearest the joints
// before, as the controller's movel does.
struct ScriptJointMove {
  robot::Joints from{}, to{};
};
inline std::vector<ScriptJointMove> scriptJointMoves(const robot::Cell& cell, const robot::Joints& start,
                                                     const std::string& script) {
  std::vector<ScriptJointMove> moves;
  const std::regex move(R"((movej|movel)\((p?)\[([^\]]*)\])");
  robot::Joints at = start;
  std::optional<Eigen::Isometry3d> lastMovel;
  for (auto it = std::sregex_iterator(script.begin(), script.end(), move); it != std::sregex_iterator(); ++it) {
    std::stringstream list((*it)[3].str());
    std::array<double, 6> v{};
    std::string item;
    for (std::size_t j = 0; j < 6 && std::getline(list, item, ','); ++j) v[j] = std::stod(item);
    if ((*it)[1] == "movel") {
      Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();
      tcp.translation() = Eigen::Vector3d(v[0], v[1], v[2]) * 1000.0;
      const Eigen::Vector3d r(v[3], v[4], v[5]);
      if (r.norm() > 0.0) tcp.linear() = Eigen::AngleAxisd(r.norm(), r.normalized()).toRotationMatrix();
      lastMovel = tcp;
      continue;
    }
    if (lastMovel) {
      const auto solved = robot::nearestWithinLimits(
          cell.arm, robot::inverseKinematics(cell.arm, *lastMovel * cell.flangeToPlatform.inverse()), at);
      if (solved) at = *solved;
      lastMovel.reset();
    }
    ScriptJointMove m;
    m.from = at;
    std::copy(v.begin(), v.end(), m.to.begin());
    moves.push_back(m);
    at = m.to;
  }
  return moves;
}

// The distance from a point to a box or a cylinder of the cell (0 inside).
inline double distanceToBox(const robot::CollisionBox& box, const Eigen::Vector3d& x) {
  const Eigen::Vector3d local = box.pose.inverse() * x;
  return (local.cwiseAbs() - box.sizeMm / 2).cwiseMax(0.0).norm();
}
inline double distanceToCylinder(const robot::CollisionCylinder& c, const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = x - c.baseMm;
  const double h = d.dot(c.axis);
  const double radial = (d - h * c.axis).norm();
  return std::hypot(std::max({-h, h - c.lengthMm, 0.0}), std::max(radial - c.radiusMm, 0.0));
}

// The least clearance of anything the arm moves at joints q: links, platform rim, `carried` (platform frame)
// against every body and the table plane (no margin). Negative or zero: they meet. `what` names the worst pair.
inline double sweepClearanceAt(const robot::Cell& cell, const robot::Joints& q,
                               const std::vector<Eigen::Vector3d>& carried, std::string& what) {
  double worst = 1e9;
  auto against = [&](const Eigen::Vector3d& x, double radius, const std::string& name) {
    for (const robot::CollisionBox& b : cell.boxes)
      if (const double d = distanceToBox(b, x) - radius; d < worst) {
        worst = d;
        what = name + " / " + b.name;
      }
    for (const robot::CollisionCylinder& c : cell.cylinders)
      if (const double d = distanceToCylinder(c, x) - radius; d < worst) {
        worst = d;
        what = name + " / " + c.name;
      }
    if (const double d = x.z() - radius - cell.tableZMm; d < worst) {
      worst = d;
      what = name + " / the table";
    }
  };
  for (const robot::ArmLinkSolid& link : robot::armLinkSolids(cell.arm, q)) {
    const double length = (link.toMm - link.fromMm).norm();
    const int points = std::max(1, static_cast<int>(std::ceil(length)));
    for (int i = 0; i <= points; ++i)
      against(link.fromMm + (link.toMm - link.fromMm) * (static_cast<double>(i) / points), link.radiusMm, link.name);
  }
  const Eigen::Isometry3d tcp = robot::forwardKinematics(cell.arm, q) * cell.flangeToPlatform;
  for (int i = 0; i < 72; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * i / 72;
    const Eigen::Vector3d rim(cell.platformRadiusMm * std::cos(a), cell.platformRadiusMm * std::sin(a), 0.0);
    against(tcp * rim, 0.0, "the platform");
    against(tcp * (rim - Eigen::Vector3d(0, 0, cell.platformThicknessMm)), 0.0, "the platform");
  }
  for (const Eigen::Vector3d& p : carried) against(tcp * p, 0.0, "the part");
  return worst;
}

// The least clearance over the program's joint moves (from `start`, the arm's joints when it begins).
inline double leastJointMoveClearance(const robot::Cell& cell, const robot::Joints& start, const std::string& script,
                                      const std::vector<Eigen::Vector3d>& carried, std::string& what) {
  constexpr double kSampleRad = 0.1 * 3.14159265358979323846 / 180.0;
  double least = 1e9;
  for (const ScriptJointMove& m : scriptJointMoves(cell, start, script)) {
    double turn = 0.0;
    for (std::size_t j = 0; j < 6; ++j) turn = std::max(turn, std::abs(m.to[j] - m.from[j]));
    const int samples = std::max(1, static_cast<int>(std::ceil(turn / kSampleRad)));
    for (int s = 0; s <= samples; ++s) {
      robot::Joints q{};
      for (std::size_t j = 0; j < 6; ++j) q[j] = m.from[j] + (m.to[j] - m.from[j]) * s / samples;
      std::string here;
      if (const double c = sweepClearanceAt(cell, q, carried, here); c < least) {
        least = c;
        what = here;
      }
    }
  }
  return least;
}

}  // namespace multidir::test

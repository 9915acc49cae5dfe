#pragma once
// The arm's links as simple solids (docs/robot-cell.md, "Collisions"): one capsule (a segment and a radius) per
// moving link, laid along the DH model, and their clearance from the extruder's bodies and the table. The
// conversion refuses a pose whose links come into a body; the studio can draw the same solids.
#include <Eigen/Geometry>

#include <array>
#include <string>

#include "multidir/robot/cell.h"
#include "multidir/robot/ur_kinematics.h"

namespace multidir::robot {

// A link: the points within radiusMm of the segment fromMm..toMm (base frame).
struct ArmLinkSolid {
  const char* name;  // "upper arm", "forearm", "wrist 1", "wrist 2", "wrist 3"
  Eigen::Vector3d fromMm = Eigen::Vector3d::Zero();
  Eigen::Vector3d toMm = Eigen::Vector3d::Zero();
  double radiusMm = 0.0;
};

constexpr int kArmLinkCount = 5;

// The moving links for the joints (the base and shoulder housings stand still on the table and are not listed):
//   upper arm: DH origin 1 to 2 (shoulder to elbow, in the DH plane), forearm: origin 2 to 3,
//   wrist 1:   origin 3 to 4 (along the wrist 1 axis, d4), wrist 2: origin 4 to 5 (along its axis, d5),
//   wrist 3:   origin 5 towards the flange (along its axis), the segment stopping its radius short of the flange
//              so the rounded end reaches the flange face and no further.
// Radii per model: docs/robot-cell.md "Collisions".
std::array<ArmLinkSolid, kArmLinkCount> armLinkSolids(const ArmModel& arm, const Joints& joints);

// The least distance between the links' surfaces and the cell's bodies (boxes and cylinders) or the table plane
// raised by margins.tableClearanceMm; at or below zero they touch. Exact within 50 mm of a body's bounding sphere;
// farther, the distance to that sphere (a lower bound). `link` indexes armLinkSolids, `body` names the
// body ("the table" for the plane).
struct ArmClearance {
  double mm = 0.0;
  int link = 0;
  std::string body;
};
ArmClearance armClearance(const Cell& cell, const Joints& joints);

// An upper bound on how far any point of the links moves while the joints go from `a` to `b` along a path on which
// each joint turns monotonically: the sum over joints of the turn times the farthest a link point beyond that
// joint can lie from its axis.
double armMotionBoundMm(const ArmModel& arm, const Joints& a, const Joints& b);

}  // namespace multidir::robot

#pragma once
// A joint move (URScript movej: every joint on one profile, so the path is the straight line between the two
// joint sets) checked against the cell before it is written (docs/robot-cell.md, "Re-orientation within a
// step"): the arm's links against the extruder's bodies and the table, the arm's housings above the table, and
// the platform and the part it carries against the bodies and the table.
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "multidir/robot/cell.h"
#include "step_converter.h"

namespace multidir::robot::detail {

// The joint move's carried points are tested at joint sets at most this far apart on the joint that turns most
// (a point 300 mm from the axis moves 5 mm between two); the links are checked continuously (armMotionBoundMm).
constexpr double kJointMoveSampleDegrees = 1.0;

// The first collision on the way from `from` to `to`, or an empty string. `carried` in the platform frame;
// this step's own part only up to `printedUpToFileZ` in the files' frame (`platformToFile`), the layers printed so
// far. Points within the nozzle's zone are exempt, as in every other check.
std::string jointMoveCollision(const Cell& cell, const std::vector<CarriedPoint>& carried,
                               const Eigen::Isometry3d& platformToFile, double printedUpToFileZ, const Joints& from,
                               const Joints& to);

}  // namespace multidir::robot::detail

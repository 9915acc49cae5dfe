#pragma once
// A joint move (URScript movej: every joint on one profile, so the path is the straight line between the two
// joint sets) checked against the cell before it is written (docs/robot-cell.md, "Joint moves"): the arm's links
// against the extruder's bodies and the table, the arm's housings above the table, and the platform and the part
// it carries against the bodies and the table. The one check of every movej the programs contain: from home to a
// step, from a step back home, their via points (joint_path_planner.h) and the re-orientations' turns.
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "multidir/robot/cell.h"
#include "step_converter.h"

namespace multidir::robot::detail {

// The joint move's housings and carried points are looked at along the path stepping by their clearance at the
// last look (no point can move farther than that before the next: a bound from the joints' turns, not the
// distance actually moved), and by this much when nearer: a point may come this close to a body unseen. The
// links are checked continuously (armMotionBoundMm).
constexpr double kJointMoveSampleMm = 2.0;

// What a joint move carries and where: `carried` in the platform frame; this step's own part only up to
// `printedUpToFileZ` in the files' frame (`platformToFile`): the layers printed so far (-infinity before the step,
// +infinity after it). Points within the nozzle's zone are exempt, as in every other check.
struct JointMoveScene {
  const Cell* cell = nullptr;
  const std::vector<CarriedPoint>* carried = nullptr;
  Eigen::Isometry3d platformToFile = Eigen::Isometry3d::Identity();
  double printedUpToFileZ = 0.0;
};

// The first collision on the straight joint path from `from` to `to` (what hits what, where, by how much), or an
// empty string when the path is clear.
std::string jointMoveCollision(const JointMoveScene& scene, const Joints& from, const Joints& to);

}  // namespace multidir::robot::detail

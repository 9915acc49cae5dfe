#pragma once
// Where to put the extruder (`multidir cell reach PLAN --cell CELL`, docs/robot-cell.md "Reach map"): the
// paper placed its nozzle at the centre of the region of the UR5's workspace with the highest reachability. Here
// nozzle positions are sampled on a grid over the arm's workspace (the nozzle axis as the cell has it) and each
// is scored by the share of the plan's needed platform poses that are reachable with the cell's margins.
#include <Eigen/Geometry>

#include <filesystem>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/common/result.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/robot/cell.h"

namespace multidir::robot {

// One step's needs: its pose (platform frame to the files' frame) and the nozzle points (files' frame) its
// toolpath must reach: the corners and centre of its region's and supports' bounding box.
struct ReachStep {
  Eigen::Isometry3d platformToFile = Eigen::Isometry3d::Identity();
  std::vector<Eigen::Vector3d> neededFileMm;
};

// The plan's steps posed as `multidir slice` poses them (core::buildPrintJob, machine frame). Errors: those of
// buildPrintJob.
core::Result<std::vector<ReachStep>> reachStepsOfPlan(const core::LoadedPlan& plan);

struct ReachMapOptions {
  double gridMm = 100.0;              // spacing of the sampled nozzle positions
  double rotationStepDegrees = 30.0;  // the free rotation about the nozzle axis, per step
};

struct ReachPoint {
  Eigen::Vector3d nozzleTipMm = Eigen::Vector3d::Zero();
  double score = 0.0;          // share of the needed poses reachable with margin, 0..1
  double leastMarginMm = 0.0;  // the least reach margin over them (ties between equal scores), mm
};

struct ReachMap {
  std::vector<ReachPoint> points;  // every sampled position, in grid order
  ReachPoint best;                 // the highest score, then the largest least margin, then the first in grid order
};

// One position's score: each step at its best rotation about the axis and arm configuration (one per step, as
// robot-program keeps them), a needed pose counting when it has an IK solution on that configuration within
// the limits with reach margin >= margins.minReachMm and wrist margin >= margins.minWristDegrees.
ReachPoint reachScore(const std::vector<ReachStep>& steps, const Cell& cell, const Eigen::Vector3d& nozzleTipMm,
                      const ReachMapOptions& options);

// Every grid position within the arm's reach (|a2| + |a3| + d5 + d6 of the shoulder) and above the table by the
// platform's radius, scored; positions evaluated on the machine's threads, each into its own slot (the same
// map for any thread count). Cancellable (Cancelled).
core::Result<ReachMap> reachMap(const std::vector<ReachStep>& steps, const Cell& cell, const ReachMapOptions& options,
                                core::JobContext context);

// The map as an ASCII PLY point cloud: x y z (mm, base frame), the score and a colour from red (0) to blue (1).
core::Status writeReachPly(const ReachMap& map, const std::filesystem::path& path);

}  // namespace multidir::robot

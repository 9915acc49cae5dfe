#pragma once
// Where to put the extruder (`multidir cell reach PLAN --cell CELL`, docs/robot-cell.md "Reach map"): the
// paper placed its nozzle at the centre of the region of the UR5's workspace with the highest reachability. Here
// nozzle positions are sampled on a grid over the arm's workspace (the nozzle axis as the cell has it) and each
// is scored by the share of the plan's needed platform poses that are reachable with the cell's margins.
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
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

// The colour of a score, the PLY's and the slice's: red 255 (1 - score), green 0, blue 255 score (rounded).
std::array<std::uint8_t, 3> reachColour(double score);

// A horizontal slice of the map through the best position as a picture (docs/robot-cell.md, "Reach map"): seen
// from above (base x to the right, y up), one square of kPixelsPerCell pixels per grid position of the plane
// z = the best position's, in its score's colour (light grey where no position was sampled: out of the arm's reach
// or too near the table); the best position's cell framed in black; a colour bar with its 0, 50 and 100 % marks
// on the right. The grid's cell with the least x and the greatest y of the whole map is the top-left one, its
// square kMarginPixels in from the picture's corner.
struct ReachSlice {
  static constexpr int kPixelsPerCell = 8;
  static constexpr int kMarginPixels = 10;
  double zMm = 0.0;        // the plane, base frame
  double gridMm = 0.0;     // the map's spacing
  double leftXMm = 0.0;    // x of the leftmost column of cells
  double topYMm = 0.0;     // y of the top row of cells
  int columns = 0, rows = 0;
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // row by row from the top, three bytes a pixel
  // The pixel at the centre of the cell of (x, y) in the plane.
  std::array<int, 2> pixelOf(double xMm, double yMm) const;
};
ReachSlice reachSlice(const ReachMap& map, double gridMm);

}  // namespace multidir::robot

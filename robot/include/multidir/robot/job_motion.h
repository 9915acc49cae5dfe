#pragma once
// The motion the robot programs command, for showing it (the studio's cell view, docs/robot-cell.md "Studio"):
// the same conversion as `multidir robot-program` (planRobotJob), kept as poses instead of URScript. A step the
// checks refuse keeps its poses up to the refused move and says why, where planRobotJob refuses the whole job.
#include <Eigen/Geometry>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/robot/cell.h"
#include "multidir/robot/robot_program.h"

namespace multidir::robot {

// One G-code move's end, as the program's movel commands it.
struct MotionSample {
  int line = 0;                                       // the G-code line (1-based)
  Eigen::Vector3d nozzleFileMm = Eigen::Vector3d::Zero();  // the nozzle's point of the part, files' frame
  Eigen::Vector3d platformMm = Eigen::Vector3d::Zero();    // the TCP (platform centre), base frame
  Joints joints{};                                    // the arm there (radians)
  bool extrudes = false;
  int run = 0;  // which of the step's runs (StepMotion::platformRotations): 0 unless the step is re-oriented
};

// Why a step cannot run, where.
struct MotionWarning {
  int step = 1;
  int line = 0;      // 0: not tied to a line
  std::string text;  // "step 2, line 345 (step-02.gcode): ..." as robot-program refuses it
};

struct StepMotion {
  int step = 1;
  std::string gcodeFile;
  Eigen::Isometry3d platformToFile = Eigen::Isometry3d::Identity();  // platform frame to the files' frame
  // The TCP's orientation in each run: fixed within a run; a step is one run unless it is re-oriented at travel
  // moves (docs/robot-cell.md, "Re-orientation within a step").
  std::vector<Eigen::Matrix3d> platformRotations;
  core::TriangleMesh region;    // platform frame
  core::TriangleMesh supports;  // platform frame; empty without supports
  // Every converted move, in order (up to the refused one); a re-orientation adds three: the part lifted off
  // the nozzle, turned, and back down.
  std::vector<MotionSample> samples;
  std::optional<MotionWarning> warning;
};

// The platform pose (TCP, base frame) at a sample.
Eigen::Isometry3d platformPoseAt(const StepMotion& step, const MotionSample& sample);

// Errors: those of reading the job (FileNotFound, MalformedFile, InvalidParameter); Cancelled. Refusals are not
// errors here: each refused step carries its warning.
core::Result<std::vector<StepMotion>> robotJobMotion(const std::filesystem::path& jobDirectory, const Cell& cell,
                                                     const RobotProgramOptions& options, core::JobContext context);

}  // namespace multidir::robot

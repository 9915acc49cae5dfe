#pragma once
// One step of a sliced job turned into one URScript program, with every check (docs/robot-cell.md,
// "Programs" and "Checks").
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/robot/cell.h"
#include "multidir/robot/job_motion.h"
#include "multidir/robot/robot_program.h"

namespace multidir::robot::detail {

// A point of what the platform carries, in the platform (TCP) frame.
struct CarriedPoint {
  Eigen::Vector3d platformMm;
  enum class Kind { Platform, EarlierStep, ThisStep } kind;
};

struct StepInput {
  int step = 1;
  int stepCount = 1;
  std::string gcodeFile;  // "step-01.gcode"
  std::string gcode;      // its text
  // The step's pose: platform frame to the files' (slicer's) frame, where the printing direction is +Z.
  Eigen::Isometry3d platformToFile = Eigen::Isometry3d::Identity();
  Eigen::Vector3d printerOffsetMm = Eigen::Vector3d::Zero();  // printer coordinates = files' frame + this
  std::vector<CarriedPoint> carried;  // the platform disc, the regions printed before, this step's region
  double slicerSeconds = 0.0;
  bool recordMotion = false;  // keep every move's pose in StepOutput::motion (the studio's view)
};

struct StepOutput {
  RobotStepSummary summary;
  std::string script;
  std::vector<std::string> refusals;  // "step 2, line 345 (step-02.gcode): ..."; empty when the step converts
  int refusalLine = 0;                // the first refusal's G-code line (0: none or not tied to a line)
  // With StepInput::recordMotion: each converted move's end (up to a refused one), and the TCP's orientation in
  // each run (one run unless the step is re-oriented; MotionSample::run indexes it).
  std::vector<MotionSample> motion;
  std::vector<Eigen::Matrix3d> platformRotations;
};

StepOutput convertStep(const StepInput& input, const Cell& cell, const RobotProgramOptions& options,
                       const core::JobContext& context);

// The nozzle's frame in the base: columns u, v, axis (u, v: a fixed choice perpendicular to the axis).
Eigen::Matrix3d nozzleFrame(const Eigen::Vector3d& axis);

// The platform pose (TCP, base frame) putting the nozzle tip at files'-frame point `fileMm` of a step posed by
// `platformToFile`, with the files' +Z along the nozzle axis turned by `rotationRad` about it.
Eigen::Isometry3d platformPoseFor(const Cell& cell, const Eigen::Isometry3d& platformToFile, double rotationRad,
                                  const Eigen::Vector3d& fileMm);

// The arm's joint housings (the DH origins from the elbow to the flange) held above the table by the cell's table
// clearance plus housingRadiusMm (an estimate of the housings' size): the first that comes down on it, or an
// empty string.
double housingRadiusMm(const ArmModel& arm);
std::string armOnTable(const Cell& cell, const Joints& joints);

// The wrist centre's least distance from the workspace's edges (elbow stretched or folded, shoulder singular).
double reachMarginMm(const ArmModel& arm, const Joints& joints);

}  // namespace multidir::robot::detail

#pragma once
// A sliced job turned into the robot cell's programs (`multidir robot-program JOB --cell CELL -o OUT`,
// docs/robot-cell.md "Programs"): every G-code move of every step becomes a platform pose that puts the fixed
// nozzle tip at the move's point of the part with the step's printing direction along the nozzle axis, checked
// (reach, joint limits, one arm configuration per step, joint jumps, singularity margins, joint speeds,
// collisions with the extruder's bodies and the table) and written as URScript, one program per step or, above
// the cell's maxProgramBytes, the step's parts (program_parts.h).
#include <filesystem>
#include <string>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/common/result.h"
#include "multidir/robot/cell.h"

namespace multidir::robot {

// Before a step's first move and after its last, the platform stands this far off the nozzle along its axis (the
// approach and retreat); a paused step backs off and comes back down by the same (docs/robot-cell.md).
constexpr double kStepApproachLiftMm = 30.0;
// The general purpose output integer register a step's program writes the number of the movel it starts to
// (1-based within the program; 0 before the first and in the joint moves), so a pause knows the move the arm is
// on from the robot itself (RTDE's output_int_register_24; docs/robot-cell.md, "Pause and resume"). UR's RTDE
// guide leaves registers 24..47 to external clients; 0..23 may be taken by a fieldbus (EtherNet/IP, PROFINET).
constexpr int kMovelRegister = 24;

struct RobotProgramOptions {
  double rotationStepDegrees = 10.0;  // the free rotation about the nozzle axis is sampled this finely per step
  double sampleMm = 5.0;              // moves are checked at points this far apart (and at both ends)
  // A joint move (home to a step, a step back home) whose straight joint path is not clear gets via points
  // (docs/robot-cell.md, "Joint moves"); false: only straight joint moves, a blocked one refused.
  bool viaPoints = true;
};

// A step that no single rotation about the nozzle axis can print is re-oriented at travel moves
// (docs/robot-cell.md, "Re-orientation within a step"): before G-code line `line` (a travel) the part is lifted off
// the nozzle, turned in joint space to the new rotation and arm configuration, and brought back down.
struct RobotReorientation {
  int line = 0;                  // the G-code line of the travel move it precedes
  double rotationDegrees = 0.0;  // the rotation about the nozzle axis from there on
  int branch = 0;                // the arm configuration from there on
};

// One of the programs a step runs as (one unless the step is above the cell's maxProgramBytes; docs/robot-cell.md,
// "Programs the controller accepts").
struct RobotProgramPart {
  std::string program;    // "step-02.script", or "step-02-part-003.script" for part 3 of a split step
  std::size_t bytes = 0;  // its size
  int firstMovel = 0;     // the step's number (1-based, the movel register's) of its first movel
  int movels = 0;
};

struct RobotStepSummary {
  int step = 1;
  std::string program;              // its first program: "step-01.script", or "step-01-part-001.script"
  std::vector<RobotProgramPart> parts;  // every program of the step, in the order they run
  double seconds = 0.0;             // the robot's own time estimate (trapezoid per move), heating waits excluded
  double filamentMm = 0.0;          // what the program's analog out 0 drives the extruder to push
  double gcodeFilamentMm = 0.0;     // the G-code's E of the step's extrusion moves
  double slicerSeconds = 0.0;       // the slicer's estimate, for comparison
  int moves = 0;                    // movel commands
  int gcodeMoves = 0;               // G-code moves converted (XY or Z motion)
  double reachMarginMm = 0.0;       // least over the step: the wrist centre from the workspace's edges
  double wristMarginDegrees = 0.0;  // least over the step: q5 from 0 and 180 deg
  int slowestJoint = 0;             // 1..6: the joint nearest its speed limit at the requested feeds
  double slowestJointLoad = 0.0;    // its speed over its limit, before slowing (> 1: slowed)
  int slowdowns = 0;                // moves slowed below the G-code's feed for a joint's speed or the extruder's
  double slowdownSeconds = 0.0;     // time the slowdowns add
  double rotationDegrees = 0.0;     // the chosen rotation about the nozzle axis (the first run's)
  int branch = 0;                   // the arm configuration (ur_kinematics.h) the step starts on
  std::vector<RobotReorientation> reorientations;  // in order; empty: the whole step on one rotation
  int viaPointsFromHome = 0;        // movej via points between home and the step's first point
  int viaPointsToHome = 0;          // and between its last point and home
};

struct RobotJob {
  std::string robot;                        // "ur5"
  std::vector<RobotStepSummary> steps;
  std::vector<std::string> scripts;         // URScript text per step, whole
  std::vector<std::vector<std::string>> partScripts;  // per step, its parts' text (RobotStepSummary::parts)
  double conversionSeconds = 0.0;           // wall time of the conversion
};

// Errors: those of reading the job (FileNotFound, MalformedFile, InvalidParameter for a job never sliced),
// CheckFailed listing every refusal: "step 2, line 345 (step-02.gcode): ..." with the reason and what to do.
core::Result<RobotJob> planRobotJob(const std::filesystem::path& jobDirectory, const Cell& cell,
                                    const RobotProgramOptions& options, core::JobContext context);

// Writes OUT/robot-job.json, OUT/cell.json (a copy of `cellFile`), each step's programs (OUT/step-NN.script, or
// OUT/step-NN-part-MMM.script for a split step; a step without partScripts as its whole script) and
// OUT/summary.txt through a staged folder that takes OUT's place only once complete. Errors: WriteFailed naming the path.
core::Status writeRobotJob(const RobotJob& job, const std::filesystem::path& cellFile,
                           const std::filesystem::path& outDirectory);

// The summary table (summary.txt and the command's output).
std::string robotJobSummary(const RobotJob& job);

}  // namespace multidir::robot

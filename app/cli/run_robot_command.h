#pragma once
// `multidir run OUT --robot HOST[:PORT]`: prints a robot job (the folder `multidir robot-program` writes:
// robot-job.json and one URScript program per step) on a Universal Robots cell with hardware's robot run
// (multidir/hardware/robot_run.h: power on, each step's program in order, progress and the time left, faults in
// the robot's own words, pause and resume, the stop latched until the robot confirms it). This side is the
// console's: the arguments, the log lines, Ctrl-C (a stop; a second one powers the arm off) and Ctrl-Z (a
// pause; again, the resume).
#include <ostream>

#include "cli_args.h"

namespace multidir::cli {

// Returns an exit code (kExitOk, kExitBadInput, kExitRunStopped); throws UsageError and FileError.
int runRobotJob(const ParsedArgs& parsed, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli

#pragma once
// `multidir run OUT --robot HOST[:PORT]`: prints a robot job (the folder `multidir robot-program` writes:
// robot-job.json and one URScript program per step) on a Universal Robots cell: connects, powers the arm on,
// sends each step's program in order and waits for it to end, with progress and the time left from the job's
// per-step seconds; a fault stops the run with the robot's own words; Ctrl-C stops the arm (latched until the
// robot confirms it, resent after a reconnect), a second Ctrl-C powers it off.
#include <ostream>

#include "cli_args.h"

namespace multidir::cli {

// Returns an exit code (kExitOk, kExitBadInput, kExitRunStopped); throws UsageError and FileError.
int runRobotJob(const ParsedArgs& parsed, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli

#pragma once
// `multidir slice PLAN_OR_JOB --printer PROFILE [--dialect klipper|marlin|rrf] -o DIR`: every step of a print
// job sliced by PrusaSlicer, checked, stitched when the platform is a firmware axis, with estimates.
#include <ostream>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kSliceHelp;

// Runs the command on the arguments after "slice". Returns an exit code (see cli_args.h); throws UsageError
// for command-line mistakes and FileError for a plan, job or profile that cannot be read.
int runSlice(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli

#pragma once
// `multidir info MODEL [--up D] [--alpha DEG] [--json FILE]`: statistics, the load report and the risky
// (overhanging) area of a model.
#include <ostream>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kInfoHelp;

// Runs the command on the arguments after "info". Returns an exit code (see cli_args.h); throws
// UsageError for command-line mistakes.
int runInfo(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli

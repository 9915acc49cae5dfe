#pragma once
// `multidir report MODEL... [options]`: the paper's table (Table "Computational Statistic") for each model:
// triangles, search time, parts, J_G before and after, and support volume printed along one fixed direction
// against the multi-directional plan, both with the same projected-support generator.
#include <ostream>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kReportHelp;

// Runs the command on the arguments after "report". Returns an exit code (see cli_args.h); throws UsageError
// for command-line mistakes and FileError for a JSON file that cannot be written.
int runReport(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli

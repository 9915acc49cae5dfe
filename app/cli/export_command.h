#pragma once
// `multidir export PLAN_DIR -o OUTDIR [options]`: the print job of a plan folder, one mesh per region in
// printing order posed as the machine holds it, plus print-job.json (docs/plan-format.md).
#include <ostream>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kExportHelp;

// Runs the command on the arguments after "export". Returns an exit code (see cli_args.h); throws UsageError
// for command-line mistakes and FileError for a plan that cannot be read or a job that cannot be written.
int runExport(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli

#pragma once
// `multidir apart PLAN_OR_MODEL -o OUTDIR [--printer PROFILE]`: a plan printed apart on an ordinary printer,
// the parts joined by dowels (docs/apart.md): parts, dowels, plates, one 3MF and G-code per plate.
#include <ostream>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kApartHelp;

// Runs the command on the arguments after "apart". Returns an exit code (see cli_args.h); throws UsageError
// for command-line mistakes and FileError for files that cannot be read or written, a plan that cannot be
// printed apart, or a slicer run that fails.
int runApart(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli

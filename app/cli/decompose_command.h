#pragma once
// `multidir decompose MODEL -o OUTDIR [options]`: the decomposition search, its table of regions, and the
// plan folder (plan.json + region STLs, see docs/plan-format.md).
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kDecomposeHelp;
extern const std::set<std::string> kDecomposeValueOptions;  // the options that take a value, -o included
extern const std::set<std::string> kDecomposeFlags;         // the options that take none, --help included

// Runs the command on the arguments after "decompose". Returns an exit code (see cli_args.h); throws
// UsageError for command-line mistakes and FileError for files that cannot be read or written.
// `err` gets the progress line when it is a terminal (isatty(stderr)).
int runDecompose(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// Checks decompose's options (everything but MODEL and -o) as runDecompose would, without a model: throws
// UsageError for a mistake and FileError for a --profile that cannot be read.
void checkDecomposeOptions(const std::vector<std::string>& options);

}  // namespace multidir::cli

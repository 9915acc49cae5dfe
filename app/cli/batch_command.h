#pragma once
// `multidir batch INPUT -o OUTDIR [decompose options] [--shard I/N] [--table FILE] [--isolate]`: decompose
// every model of a folder or list file into its own plan folder and one results table (docs/batch.md).
#include <ostream>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kBatchHelp;

// Runs the command on the arguments after "batch". Returns kExitOk when every model of the shard has its
// plan, kExitBadInput when any failed (each recorded in the table); throws UsageError for command-line
// mistakes and FileError when INPUT cannot be read or OUTDIR or the table cannot be written.
int runBatch(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli

#pragma once
// `multidir run JOB --printer URL --platform HOST:PORT`: runs a sliced job headless: turns the platform to each
// step's orientation, uploads and starts the step's G-code on the printer, waits for the printer to finish,
// goes on; prints a progress display and a log; Ctrl-C stops both devices.
#include <ostream>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kRunHelp;

// The run did not complete: a device could not be reached, refused, faulted, or the operator pressed Ctrl-C.
constexpr int kExitRunStopped = 4;

// Returns an exit code (cli_args.h, and kExitRunStopped); throws UsageError and FileError.
int runRun(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli

#pragma once
// `multidir simulate [--rotary] [--robot] [--listen ADDRESS] [--port PORT] [--unit ID]`: runs the Modbus
// device simulator (rotary platform controller and/or UR arm registers) until Ctrl-C.
#include <ostream>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kSimulateHelp;

// Runs the command on the arguments after "simulate"; returns when SIGINT or SIGTERM arrives. Returns an
// exit code (see cli_args.h); throws UsageError for command-line mistakes.
int runSimulate(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli

#pragma once
// The printer's API key for `multidir run`: from --api-key-file FILE or --api-key KEY (not both), else from the
// environment variable MULTIDIR_PRINTER_API_KEY. The file or the variable is to be preferred: a key given as
// --api-key is visible to every user of the machine in the process list (ps, /proc/PID/cmdline).
#include <string>

#include "cli_args.h"

namespace multidir::cli {

constexpr const char* kApiKeyVariable = "MULTIDIR_PRINTER_API_KEY";

// "" when none is given. UsageError (naming `command`) for --api-key and --api-key-file together, a file that
// cannot be read, and a key that is empty or holds a control character (a second line, say) once the blanks
// around it are dropped.
std::string printerApiKey(const ParsedArgs& parsed, const std::string& command);

}  // namespace multidir::cli

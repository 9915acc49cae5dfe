#pragma once
// Command-line parsing shared by the subcommands: options with values, flags and positionals, with
// mistakes reported as UsageError (exit code 2).
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "multidir/core/mesh/mesh_io.h"

namespace multidir::cli {

// Exit codes of every subcommand.
constexpr int kExitOk = 0;
constexpr int kExitBadInput = 1;  // the model or another file could not be read, checked or written
constexpr int kExitUsage = 2;     // wrong command, option, value or missing argument
constexpr int kExitInternal = 3;  // a bug in MultiDir

// A mistake on the command line; the message says what was wrong and how to ask for help.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file the command had to read or write failed (exit code 1).
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ParsedArgs {
  std::vector<std::string> positionals;
  std::map<std::string, std::string> values;  // "--up" -> "y"
  std::set<std::string> flags;                // "--help"

  bool has(const std::string& option) const { return values.count(option) > 0 || flags.count(option) > 0; }
  std::string value(const std::string& option, const std::string& fallback) const;
};

// Parses `args` (without the program and command names). `valueOptions` take one value ("--up y" or
// "--up=y"; a short option such as "-o" only as "-o DIR"), `flagOptions` none. Throws UsageError for an unknown option, a missing value or a repeated
// option; `command` names the command in messages.
ParsedArgs parseArgs(const std::vector<std::string>& args, const std::set<std::string>& valueOptions,
                     const std::set<std::string>& flagOptions, const std::string& command);

// The one positional argument of commands that take exactly one (`what`: "model", "plan"); UsageError when
// there is none (with `usage`, "multidir info MODEL [options]") or more than one.
std::string onlyPositional(const ParsedArgs& parsed, const std::string& command, const std::string& what,
                           const std::string& usage);

// The folder named by the required option -o; UsageError when -o is missing (saying that the folder receives
// `contents`, "the plan") or empty.
std::string outputFolder(const ParsedArgs& parsed, const std::string& command, const std::string& contents);

// Load options for the model of `command`: --scale FACTOR (coordinates times FACTOR, for a model saved in
// other units) when given. UsageError when FACTOR is not a number from 1e-6 to 1e6.
core::LoadOptions modelLoadOptions(const ParsedArgs& parsed, const std::string& command);

// Refuses an output folder that cannot be written, before any work: it must be a writable folder, or not
// exist yet below a writable folder (it is created only when the results are saved). Throws FileError.
void checkOutputFolder(const std::string& folder, const std::string& command);

// The whole text must be a finite number, else UsageError naming the option.
double parseNumber(const std::string& text, const std::string& option);

}  // namespace multidir::cli

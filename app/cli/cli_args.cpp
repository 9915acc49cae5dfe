#include "cli_args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <unistd.h>

namespace multidir::cli {

std::string ParsedArgs::value(const std::string& option, const std::string& fallback) const {
  auto it = values.find(option);
  return it == values.end() ? fallback : it->second;
}

ParsedArgs parseArgs(const std::vector<std::string>& args, const std::set<std::string>& valueOptions,
                     const std::set<std::string>& flagOptions, const std::string& command) {
  const std::string help = "Run 'multidir help " + command + "' for its options.";
  ParsedArgs parsed;
  bool onlyPositionals = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool shortOption = arg == "-h" || valueOptions.count(arg) > 0 || flagOptions.count(arg) > 0;
    if (onlyPositionals || arg.size() < 2 || arg[0] != '-' || (arg[1] != '-' && !shortOption)) {
      parsed.positionals.push_back(arg);
      continue;
    }
    if (arg == "--") {
      onlyPositionals = true;
      continue;
    }
    std::string name = arg == "-h" ? "--help" : arg;
    std::string value;
    bool inlineValue = false;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      inlineValue = true;
    }
    if (flagOptions.count(name) > 0) {
      if (inlineValue) throw UsageError("multidir " + command + ": " + name + " takes no value. " + help);
      parsed.flags.insert(name);
    } else if (valueOptions.count(name) > 0) {
      if (!inlineValue) {
        if (i + 1 >= args.size()) throw UsageError("multidir " + command + ": " + name + " needs a value. " + help);
        value = args[++i];
      }
      if (!parsed.values.emplace(name, value).second)
        throw UsageError("multidir " + command + ": " + name + " is given twice. " + help);
    } else {
      throw UsageError("multidir " + command + ": unknown option '" + name + "'. " + help);
    }
  }
  return parsed;
}

std::string onlyPositional(const ParsedArgs& parsed, const std::string& command, const std::string& what,
                           const std::string& usage) {
  if (parsed.positionals.empty()) throw UsageError("multidir " + command + ": which " + what + "? Usage: " + usage);
  if (parsed.positionals.size() > 1)
    throw UsageError("multidir " + command + ": one " + what + " at a time (got '" + parsed.positionals[0] + "' and '" +
                     parsed.positionals[1] + "')");
  return parsed.positionals[0];
}

std::string outputFolder(const ParsedArgs& parsed, const std::string& command, const std::string& contents) {
  if (!parsed.has("-o"))
    throw UsageError("multidir " + command + ": -o OUTDIR is missing: name the folder to write " + contents + " to");
  std::string folder = parsed.value("-o", "");
  if (folder.empty()) throw UsageError("multidir " + command + ": -o needs a folder name");
  return folder;
}

core::LoadOptions modelLoadOptions(const ParsedArgs& parsed, const std::string& command) {
  core::LoadOptions options;
  if (!parsed.has("--scale")) return options;
  options.scale = parseNumber(parsed.value("--scale", ""), "multidir " + command + ": --scale");
  if (!(options.scale >= 1e-6 && options.scale <= 1e6))
    throw UsageError("multidir " + command + ": --scale must be from 0.000001 to 1000000 (0.001 turns micrometres "
                     "into millimetres, 25.4 inches), not " + parsed.value("--scale", ""));
  return options;
}

void checkOutputFolder(const std::string& folder, const std::string& command) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path existing = fs::absolute(fs::path(folder), ec).lexically_normal();
  if (ec) throw FileError("multidir " + command + ": -o " + folder + ": " + ec.message());
  // The folder itself, or the nearest folder above it that exists (where it would be created).
  while (!fs::exists(existing, ec) && existing.has_parent_path() && existing.parent_path() != existing)
    existing = existing.parent_path();
  const bool isFolder = fs::is_directory(existing, ec);
  if (!isFolder)
    throw FileError("multidir " + command + ": -o " + folder + ": " + existing.string() +
                    " is a file, not a folder; choose another output folder");
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    throw FileError("multidir " + command + ": -o " + folder + ": the folder " + existing.string() +
                    " is not writable (" + std::strerror(errno) + "); choose another output folder");
}

double parseNumber(const std::string& text, const std::string& option) {
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value))
    throw UsageError(option + " expects a number, got '" + text + "'");
  return value;
}

}  // namespace multidir::cli

#include "batch_command.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "batch_models.h"
#include "batch_table.h"
#include "cli_args.h"
#include "decompose_command.h"
#include "multidir/core/common/atomic_file.h"
#include "number_text.h"
#include "peak_memory.h"

extern char** environ;

namespace multidir::cli {

const char* const kBatchHelp =
    "Usage: multidir batch INPUT -o OUTDIR [decompose options] [--shard I/N] [--table FILE] [--isolate]\n"
    "\n"
    "Decomposes every model of INPUT, a folder (its .stl, .obj, .off and .ply files) or a list file (one path\n"
    "per line, relative to the list file's folder; # starts a comment), as 'multidir decompose' does, into\n"
    "one plan folder per model, OUTDIR/<model file name>/, and writes one table row per model: model, status,\n"
    "faces, J_G before and after (mm^2), regions, seconds, peak memory (MiB) and the error of a model that\n"
    "failed. A model that fails (a broken mesh) is recorded and the batch goes on.\n"
    "\n"
    "Resumable: a model whose plan folder is complete (plan.json and batch-row.json, written last and\n"
    "atomically) is skipped and its row taken from batch-row.json; run the same command again after a crash.\n"
    "\n"
    "Options:\n"
    "  -o OUTDIR            folder for the plan folders (created if missing; required)\n"
    "  --shard I/N          take only the models whose index in the sorted list is I modulo N (0 <= I < N):\n"
    "                       N machines or array tasks share a dataset (docs/batch.md)\n"
    "  --table FILE         the results table: CSV, or JSON when FILE ends in .json (default:\n"
    "                       OUTDIR/batch-results.csv, OUTDIR/batch-results-I-of-N.csv with --shard)\n"
    "  --isolate            run each model in a child process, so that a crash or the memory killer ends only\n"
    "                       that model (recorded as failed); default: all models in this process\n"
    "  decompose options    every option of 'multidir decompose' but -o and --summary (see\n"
    "                       'multidir help decompose'), applied to every model\n"
    "  -h, --help           show this help\n"
    "\n"
    "Exit codes: 0 every model has its plan, 1 at least one model failed (see the table) or INPUT, OUTDIR or\n"
    "the table cannot be read or written, 2 usage error.\n";

namespace {

namespace fs = std::filesystem;

const std::string kCommand = "multidir batch";
const char* const kRowFile = "batch-row.json";
const std::string kCancelled = "the search was cancelled (Ctrl-C)";

struct Settings {
  std::string input;
  std::string outDir;
  std::string table;
  Shard shard;
  bool isolate = false;
  std::vector<std::string> decomposeOptions;  // passed to every model's decompose
};

Settings settingsFrom(const std::vector<std::string>& args, bool& helpOnly) {
  std::set<std::string> values = kDecomposeValueOptions;
  values.insert({"--shard", "--table"});
  std::set<std::string> flags = kDecomposeFlags;
  flags.insert("--isolate");
  const ParsedArgs parsed = parseArgs(args, values, flags, "batch");
  helpOnly = parsed.has("--help");
  Settings s;
  if (helpOnly) return s;
  s.input = onlyPositional(parsed, "batch", "folder or list file", "multidir batch INPUT -o OUTDIR [options]");
  s.outDir = outputFolder(parsed, "batch", "the plan folders");
  if (parsed.has("--summary"))
    throw UsageError(kCommand + ": --summary is decompose's; the batch writes one table for all models (--table)");
  if (parsed.has("--shard")) s.shard = parseShard(parsed.value("--shard", ""));
  s.isolate = parsed.has("--isolate");
  s.table = parsed.value("--table", "");
  if (parsed.has("--table") && s.table.empty()) throw UsageError(kCommand + ": --table needs a file name");
  if (s.table.empty())
    s.table = (fs::path(s.outDir) / (parsed.has("--shard") ? "batch-results-" + std::to_string(s.shard.index) + "-of-" +
                                                                 std::to_string(s.shard.count) + ".csv"
                                                           : std::string("batch-results.csv")))
                  .string();
  for (const auto& [option, value] : parsed.values)
    if (option != "-o" && option != "--shard" && option != "--table") s.decomposeOptions.insert(s.decomposeOptions.end(), {option, value});
  for (const std::string& flag : parsed.flags)
    if (flag != "--isolate") s.decomposeOptions.push_back(flag);
  // Every model gets these options: a mistake is reported once, before any model.
  checkDecomposeOptions(s.decomposeOptions);
  return s;
}

// What one model's decompose left: its exit code, the last line it wrote to stderr, and how long and how
// much memory it took.
struct RunOutcome {
  int exitCode = kExitInternal;
  std::string lastError;
  double seconds = 0.0;
  double peakMemoryMiB = 0.0;
};

std::string lastLine(const std::string& text) {
  std::string last;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const auto cr = line.find_last_of('\r');  // a progress line rewritten in place: its last state
    if (cr != std::string::npos) line = line.substr(cr + 1);
    if (line.find_first_not_of(" \t") != std::string::npos) last = line;
  }
  return last;
}

RunOutcome runHere(const std::vector<std::string>& args) {
  RunOutcome outcome;
  std::ostringstream out, err;
  resetPeakMemory();
  const auto start = std::chrono::steady_clock::now();
  try {
    outcome.exitCode = runDecompose(args, out, err);
  } catch (const UsageError& e) {
    outcome.exitCode = kExitUsage;
    err << e.what() << "\n";
  } catch (const FileError& e) {
    outcome.exitCode = kExitBadInput;
    err << e.what() << "\n";
  } catch (const std::bad_alloc&) {
    outcome.exitCode = kExitBadInput;
    err << "multidir decompose: out of memory\n";
  } catch (const std::exception& e) {
    outcome.exitCode = kExitInternal;
    err << "multidir decompose: internal error: " << e.what() << "\n";
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.peakMemoryMiB = peakMemoryMiB();
  outcome.lastError = lastLine(err.str());
  return outcome;
}

// The same in a child process (this program's own executable), its stderr in `logPath`.
RunOutcome runIsolated(const std::vector<std::string>& args, const std::string& logPath) {
  RunOutcome outcome;
  std::vector<std::string> words = {"multidir", "decompose"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  // Ctrl-C reaches the child too (one process group): the child stops its search and saves its plan marked
  // cancelled, and the batch, ignoring the signal meanwhile, sees that and stops after it. The child starts
  // with the default action, whatever the batch's.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  posix_spawnattr_setsigdefault(&attributes, &interrupt);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  struct sigaction previous {};
  sigaction(SIGINT, &ignore, &previous);
  const auto start = std::chrono::steady_clock::now();
  pid_t child = 0;
  const int spawned = posix_spawn(&child, "/proc/self/exe", &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) {
    sigaction(SIGINT, &previous, nullptr);
    outcome.lastError = kCommand + ": cannot start a child process: " + std::strerror(spawned);
    return outcome;
  }
  int status = 0;
  rusage usage{};
  while (wait4(child, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  sigaction(SIGINT, &previous, nullptr);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.peakMemoryMiB = usage.ru_maxrss / 1024.0;  // kB on Linux
  std::ifstream log(logPath);
  std::stringstream text;
  text << log.rdbuf();
  outcome.lastError = lastLine(text.str());
  if (WIFEXITED(status)) {
    outcome.exitCode = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    outcome.exitCode = kExitInternal;
    outcome.lastError = "multidir decompose was ended by signal " + std::to_string(WTERMSIG(status)) + " (" +
                        strsignal(WTERMSIG(status)) + ")" + (outcome.lastError.empty() ? "" : "; it last said: " + outcome.lastError);
  }
  return outcome;
}

// A finished model's row, from the record beside its plan; nothing when its plan folder is not complete.
std::optional<BatchRow> finishedRow(const fs::path& planDir) {
  std::error_code ec;
  if (!fs::exists(planDir / "plan.json", ec) || !fs::exists(planDir / kRowFile, ec)) return std::nullopt;
  std::ifstream in(planDir / kRowFile);
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded()) return std::nullopt;
  try {
    return rowFromJson(json);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // not a record this version wrote: the model is run again
  }
}

BatchRow runModel(const Settings& s, const BatchModel& model, const fs::path& workDir) {
  const fs::path planDir = fs::path(s.outDir) / model.name;
  const fs::path summary = workDir / (model.name + ".summary.json");
  std::vector<std::string> args = {model.path, "-o", planDir.string(), "--summary", summary.string()};
  args.insert(args.end(), s.decomposeOptions.begin(), s.decomposeOptions.end());
  std::error_code ec;
  fs::remove(summary, ec);
  const fs::path log = workDir / (model.name + ".log");
  const RunOutcome outcome = s.isolate ? runIsolated(args, log.string()) : runHere(args);
  fs::remove(log, ec);
  BatchRow row;
  row.model = model.path;
  row.seconds = outcome.seconds;
  row.peakMemoryMiB = outcome.peakMemoryMiB;
  std::ifstream in(summary);
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  fs::remove(summary, ec);
  const bool summarised = json.is_object();
  const bool cancelled = summarised && json.value("cancelled", false);
  if (outcome.exitCode != kExitOk || !summarised || cancelled) {
    row.status = "failed";
    row.error = cancelled                    ? kCancelled
                : !outcome.lastError.empty() ? outcome.lastError
                                             : "multidir decompose exited with code " + std::to_string(outcome.exitCode);
    return row;
  }
  row.status = "done";
  row.faces = json.value("triangles", 0LL);
  row.jgBeforeMm2 = json.value("jg_before", 0.0);
  row.jgAfterMm2 = json.value("jg_after", 0.0);
  row.regions = json.value("regions", 0);
  // Written last and atomically: only now does the plan folder count as complete.
  if (const core::Status written = core::writeTextFileAtomically((planDir / kRowFile).string(), rowToJson(row).dump(2) + "\n");
      !written) {
    row.status = "failed";
    row.error = "the plan was written but its batch record was not: " + written.error().describe();
  }
  return row;
}

}  // namespace

int runBatch(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  bool helpOnly = false;
  const Settings s = settingsFrom(args, helpOnly);
  if (helpOnly) {
    out << kBatchHelp;
    return kExitOk;
  }
  const std::vector<BatchModel> all = batchModels(s.input);
  const std::vector<BatchModel> share = shardOf(all, s.shard);
  checkOutputFolder(s.outDir, "batch");
  const fs::path workDir = fs::path(s.outDir) / ".batch";
  std::error_code ec;
  fs::create_directories(workDir, ec);
  if (ec) throw FileError(kCommand + ": cannot create " + workDir.string() + ": " + ec.message());
  out << kCommand << ": " << share.size() << " of " << all.size() << " models (shard " << s.shard.index << "/"
      << s.shard.count << "), plans in " << s.outDir << ", table " << s.table << "\n";

  std::vector<BatchRow> rows;
  int failed = 0;
  for (std::size_t k = 0; k < share.size(); ++k) {
    const BatchModel& model = share[k];
    out << "[" << k + 1 << "/" << share.size() << "] " << model.path << ": " << std::flush;
    BatchRow row;
    if (std::optional<BatchRow> before = finishedRow(fs::path(s.outDir) / model.name)) {
      row = *before;
      row.status = "done before";
    } else {
      row = runModel(s, model, workDir);
    }
    if (row.status == "failed") {
      ++failed;
      out << "failed: " << row.error << "\n";
    } else {
      out << row.status << ", J_G " << formatNumber("%.2f", row.jgBeforeMm2) << " -> "
          << formatNumber("%.2f", row.jgAfterMm2) << " mm^2, " << row.regions << " regions, "
          << formatNumber("%.2f", row.seconds) << " s\n";
    }
    const bool cancelled = row.error == kCancelled;
    rows.push_back(std::move(row));
    writeTable(s.table, rows);  // after every model: a crash keeps the rows so far
    if (cancelled) {  // Ctrl-C: the user stops the batch, not one model
      err << kCommand << ": stopped; run the same command again to go on from " << model.path << "\n";
      return kExitBadInput;
    }
  }
  fs::remove(workDir, ec);  // only when empty: another shard may be using it
  if (share.empty()) writeTable(s.table, rows);
  out << kCommand << ": " << rows.size() - static_cast<std::size_t>(failed) << " done, " << failed << " failed; table "
      << s.table << "\n";
  if (failed > 0) err << kCommand << ": " << failed << " of " << rows.size() << " models failed; see " << s.table << "\n";
  return failed > 0 ? kExitBadInput : kExitOk;
}

}  // namespace multidir::cli

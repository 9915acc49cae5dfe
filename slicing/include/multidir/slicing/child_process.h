#pragma once
// Runs another program (the slicer) as a child process: posix_spawn, its stdout and stderr captured through
// one pipe, cancellable from any thread through the JobContext (the child is sent SIGTERM, then SIGKILL).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/common/result.h"

namespace multidir::slicing {

struct ChildOutput {
  int exitCode = 0;    // the program's exit status; 128 + N when signal N ended it
  std::string output;  // stdout and stderr interleaved as the program wrote them (at most the last 1 MiB)
};

// The command as a person would type it, for messages: arguments with spaces or quotes are quoted.
std::string commandText(const std::vector<std::string>& argv);

// The last `count` non-empty lines of `text`, joined by newlines.
std::string lastLines(const std::string& text, int count);

// Where `program` is found: itself when it contains a '/', else the first executable match on PATH; empty
// when there is none.
std::string findExecutable(const std::string& program);

// The CPUs the calling thread may run on (sched_getaffinity), in increasing order; never empty (a thread runs
// somewhere: when the mask cannot be read, the CPU it is on now).
std::vector<int> usableCpus();

// Runs argv[0] (looked up on PATH) with the arguments argv[1..] and waits for it, reading its output. Checks
// the context about every 50 ms; once cancelled the child is terminated and the result is Cancelled.
// A non-zero exit is not an error here (the caller decides), only a program that cannot be started.
// Errors: FileNotFound (argv[0] is not an executable on PATH; the message names the command),
// ExternalToolFailed (the process could not be started), Cancelled, InvalidParameter (empty argv).
// `onOutput`, when given, gets each piece of output as it arrives (on the calling thread), and an empty piece
// about every 50 ms while the program is quiet, e.g. to follow its own progress lines or the file it writes. Thread-safe: each call owns its child.
// `environment`: NAME=VALUE entries that replace or add to the calling process' environment for the child.
// `onlyCpu`: when given, the child runs on that one CPU only (its affinity mask, set before it executes its
// first instruction and inherited by its threads); it must be one of usableCpus(), else InvalidParameter.
core::Result<ChildOutput> runChildProcess(const std::vector<std::string>& argv, core::JobContext& context,
                                          const std::function<void(const std::string& piece)>& onOutput = {},
                                          const std::vector<std::string>& environment = {},
                                          std::optional<int> onlyCpu = std::nullopt);

}  // namespace multidir::slicing

#pragma once
// Runs the built `multidir` command line (MULTIDIR_CLI_PATH) through the shell and captures what it printed.
#include <functional>
#include <string>

namespace multidir::test {

struct CliRun {
  int exitCode = -1;  // -1 when the program did not exit normally (killed by a signal)
  std::string out;
  std::string err;
};

// The whole text of a file; "" when it cannot be read.
std::string readAll(const std::string& path);

// Runs `prefix 'multidir' arguments` with stdout and stderr sent to stdout.txt and stderr.txt in `dir`.
// `arguments` are shell words, quoted by the caller. `prefix` goes before the program (e.g. "timeout -s INT 1").
CliRun runCli(const std::string& arguments, const std::string& dir, const std::string& prefix = "");

// A runCli prefix that runs the program under `timeout SECONDS` and first writes its process id to `pidFile`
// (removed here if left from before), for a test that signals it with signalCliWhen.
std::string pidRecordingPrefix(const std::string& pidFile, int timeoutSeconds = 60);

// Polls `when` every 10 ms for at most 30 s and, the first time it holds, sends `signal` to the process whose
// id `pidFile` holds. Returns whether the signal was sent.
bool signalCliWhen(const std::string& pidFile, int signal, const std::function<bool()>& when);

}  // namespace multidir::test

#include "support/cli_runner.h"

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

namespace multidir::test {

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

CliRun runCli(const std::string& arguments, const std::string& dir, const std::string& prefix) {
  const std::string outPath = dir + "/stdout.txt", errPath = dir + "/stderr.txt";
  const std::string command = (prefix.empty() ? std::string() : prefix + " ") + "'" + MULTIDIR_CLI_PATH + "' " +
                              arguments + " > '" + outPath + "' 2> '" + errPath + "'";
  const int status = std::system(command.c_str());
  CliRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = readAll(outPath);
  run.err = readAll(errPath);
  return run;
}

std::string pidRecordingPrefix(const std::string& pidFile, int timeoutSeconds) {
  std::remove(pidFile.c_str());
  return "timeout " + std::to_string(timeoutSeconds) + " sh -c 'echo $$ > \"" + pidFile + "\"; exec \"$0\" \"$@\"'";
}

bool signalCliWhen(const std::string& pidFile, int signal, const std::function<bool()>& when) {
  for (int i = 0; i < 3000; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (!when()) continue;
    const std::string pid = readAll(pidFile);
    if (pid.empty()) continue;  // the shell has not written it yet
    return ::kill(std::stoi(pid), signal) == 0;
  }
  return false;
}

}  // namespace multidir::test

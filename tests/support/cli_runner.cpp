#include "support/cli_runner.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

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

}  // namespace multidir::test

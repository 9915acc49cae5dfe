#include "multidir/slicing/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <thread>

extern char** environ;

namespace multidir::slicing {

namespace {

constexpr std::size_t kMaxCapturedBytes = 1 << 20;

using core::Error;
using core::ErrorCode;

bool isExecutableFile(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

// Closes a descriptor once, whatever path leaves the scope.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

int exitCodeOf(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

// Terminates the child politely, then for good if it has not ended after a second.
void terminate(pid_t pid) {
  ::kill(pid, SIGTERM);
  for (int i = 0; i < 20; ++i) {
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
}

// posix_spawn has no affinity attribute, but its child starts with the affinity of the thread that spawns it:
// this narrows the calling thread's mask to one CPU for the spawn and puts the mask back when it goes.
class ThreadPinnedForSpawn {
 public:
  ThreadPinnedForSpawn() = default;
  ThreadPinnedForSpawn(const ThreadPinnedForSpawn&) = delete;
  ThreadPinnedForSpawn& operator=(const ThreadPinnedForSpawn&) = delete;
  ~ThreadPinnedForSpawn() {
    if (m_pinned) ::pthread_setaffinity_np(::pthread_self(), sizeof m_before, &m_before);
  }

  // 0, or the errno of the failure.
  int pin(int cpu) {
    if (const int e = ::pthread_getaffinity_np(::pthread_self(), sizeof m_before, &m_before); e != 0) return e;
    cpu_set_t only;
    CPU_ZERO(&only);
    CPU_SET(static_cast<std::size_t>(cpu), &only);
    if (const int e = ::pthread_setaffinity_np(::pthread_self(), sizeof only, &only); e != 0) return e;
    m_pinned = true;
    return 0;
  }

 private:
  cpu_set_t m_before{};
  bool m_pinned = false;
};

}  // namespace

std::vector<int> usableCpus() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  std::vector<int> cpus;
  if (::sched_getaffinity(0, sizeof mask, &mask) == 0)
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
      if (CPU_ISSET(static_cast<std::size_t>(cpu), &mask)) cpus.push_back(cpu);
  if (cpus.empty()) cpus.push_back(std::max(0, ::sched_getcpu()));
  return cpus;
}

std::string commandText(const std::vector<std::string>& argv) {
  std::string text;
  for (const std::string& arg : argv) {
    if (!text.empty()) text += ' ';
    const bool plain = !arg.empty() && arg.find_first_of(" \t\n'\"\\$;&|<>()*?") == std::string::npos;
    if (plain) {
      text += arg;
    } else {
      text += '\'';
      for (char c : arg) text += c == '\'' ? std::string("'\\''") : std::string(1, c);
      text += '\'';
    }
  }
  return text;
}

std::string lastLines(const std::string& text, int count) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") != std::string::npos) lines.push_back(line);
  }
  std::string joined;
  const std::size_t first = lines.size() > static_cast<std::size_t>(count) ? lines.size() - count : 0;
  for (std::size_t i = first; i < lines.size(); ++i) joined += (joined.empty() ? "" : "\n") + lines[i];
  return joined;
}

std::string findExecutable(const std::string& program) {
  if (program.empty()) return {};
  if (program.find('/') != std::string::npos) return isExecutableFile(program) ? program : std::string();
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
    if (isExecutableFile(candidate)) return candidate;
  }
  return {};
}

core::Result<ChildOutput> runChildProcess(const std::vector<std::string>& argv, core::JobContext& context,
                                          const std::function<void(const std::string& piece)>& onOutput,
                                          const std::vector<std::string>& environment,
                                          std::optional<int> onlyCpu) {
  if (argv.empty()) return Error{ErrorCode::InvalidParameter, "no program to run", "child process"};
  const std::string command = commandText(argv);
  const std::string executable = findExecutable(argv[0]);
  if (executable.empty())
    return Error{ErrorCode::FileNotFound,
                 "'" + argv[0] + "' was not found (no executable of that name on PATH); install it (Debian: "
                 "scripts/install-deps.sh) or give its full path. Command: " + command,
                 argv[0]};
  if (context.isCancelled()) return Error{ErrorCode::Cancelled, "cancelled before " + argv[0] + " started", argv[0]};
  if (onlyCpu) {
    const std::vector<int> cpus = usableCpus();
    if (std::find(cpus.begin(), cpus.end(), *onlyCpu) == cpus.end())
      return Error{ErrorCode::InvalidParameter,
                   "CPU " + std::to_string(*onlyCpu) + " is not one this process may run on (" +
                       std::to_string(cpus.size()) + " usable, from " + std::to_string(cpus.front()) +
                       "); pick one of usableCpus(). Command: " + command,
                   argv[0]};
  }

  int pipeFds[2];
  if (::pipe2(pipeFds, O_CLOEXEC) != 0)
    return Error{ErrorCode::ExternalToolFailed, std::string("cannot create a pipe: ") + std::strerror(errno), command};
  Fd readEnd{pipeFds[0]};
  Fd writeEnd{pipeFds[1]};

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, writeEnd.fd, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, writeEnd.fd, STDERR_FILENO);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  // The parent's environment with `environment`'s entries in place of those of the same name.
  std::vector<std::string> variables = environment;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('=') + 1);
    bool replaced = false;
    for (const std::string& v : environment) replaced = replaced || v.rfind(name, 0) == 0;
    if (!replaced) variables.push_back(entry);
  }
  std::vector<char*> envp;
  for (std::string& v : variables) envp.push_back(v.data());
  envp.push_back(nullptr);
  pid_t pid = 0;
  int spawned = 0;
  {
    ThreadPinnedForSpawn pinned;
    if (onlyCpu) spawned = pinned.pin(*onlyCpu);
    if (spawned == 0)
      spawned = ::posix_spawn(&pid, executable.c_str(), &actions, nullptr, args.data(), envp.data());
  }
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
    return Error{ErrorCode::ExternalToolFailed, std::string("cannot start: ") + std::strerror(spawned), command};
  ::close(writeEnd.fd);
  writeEnd.fd = -1;

  ChildOutput result;
  char buffer[8192];
  bool open = true;
  while (open) {
    if (context.isCancelled()) {
      terminate(pid);
      return Error{ErrorCode::Cancelled, "cancelled; " + argv[0] + " was stopped", command};
    }
    pollfd p{readEnd.fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, 50);
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) {
      if (onOutput) onOutput(std::string());
      continue;
    }
    const ssize_t n = ::read(readEnd.fd, buffer, sizeof buffer);
    if (n > 0) {
      if (onOutput) onOutput(std::string(buffer, static_cast<std::size_t>(n)));
      result.output.append(buffer, static_cast<std::size_t>(n));
      if (result.output.size() > kMaxCapturedBytes)
        result.output.erase(0, result.output.size() - kMaxCapturedBytes);
    } else if (n == 0 || errno != EINTR) {
      open = false;
    }
  }
  // The pipe closed: the child is ending (or closed its output and goes on; cancellation still reaches it).
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) break;
    if (context.isCancelled()) {
      terminate(pid);
      return Error{ErrorCode::Cancelled, "cancelled; " + argv[0] + " was stopped", command};
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  result.exitCode = exitCodeOf(status);
  return result;
}

}  // namespace multidir::slicing

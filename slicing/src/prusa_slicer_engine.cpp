#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

#include "multidir/slicing/child_process.h"
#include "multidir/slicing/slicer_engine.h"

namespace multidir::slicing {

namespace {

using core::Error;
using core::ErrorCode;

constexpr int kOutputLinesInErrors = 8;

// Built beside the slicing library (slicing/CMakeLists.txt).
constexpr const char* kOneTbbThreadLibrary = MULTIDIR_ONE_TBB_THREAD_LIBRARY;

// PrusaSlicer's own stages, as it prints them ("70 => Infilling layers"), in percent; it writes the G-code from
// 90 % on.
constexpr double kExportStartPercent = 90.0;

// Follows a run's output and the G-code it writes, for SliceRequest::progress.
class ProgressFollower {
 public:
  explicit ProgressFollower(const SliceRequest& request) : m_request(request) {}

  void take(const std::string& piece) {
    m_pending += piece;
    for (std::size_t end = m_pending.find('\n'); end != std::string::npos; end = m_pending.find('\n')) {
      const std::string line = m_pending.substr(0, end);
      m_pending.erase(0, end + 1);
      int percent = 0;
      char arrow[3] = {};
      if (std::sscanf(line.c_str(), "%d %2[=>]", &percent, arrow) == 2 && std::string(arrow) == "=>" &&
          percent >= 0 && percent <= 100)
        m_stagePercent = std::max(m_stagePercent, static_cast<double>(percent));
    }
    if (m_pending.size() > 4096) m_pending.clear();  // not a line of status: nothing to follow
    double fraction = m_stagePercent / 100.0;
    if (m_stagePercent >= kExportStartPercent && m_request.heightMm > 0.0) {
      const auto now = std::chrono::steady_clock::now();
      if (now - m_lastLook > std::chrono::milliseconds(250)) {
        m_lastLook = now;
        m_writtenFraction = std::max(m_writtenFraction, writtenFraction());
      }
      fraction = (kExportStartPercent + (100.0 - kExportStartPercent) * m_writtenFraction) / 100.0;
    }
    if (fraction > m_reported + 1e-3) {
      m_reported = fraction;
      m_request.progress(std::min(fraction, 1.0));
    }
  }

 private:
  // The height reached by the G-code being written (PrusaSlicer writes OUT.tmp, then renames it), over the
  // mesh's height: the last ";Z:" layer comment of the file's tail.
  double writtenFraction() const {
    std::ifstream in(m_request.outputFile + ".tmp", std::ios::binary | std::ios::ate);
    if (!in) return 0.0;
    const std::streamoff size = in.tellg();
    const std::streamoff tail = std::min<std::streamoff>(size, 65536);
    std::string text(static_cast<std::size_t>(tail), '\0');
    in.seekg(size - tail);
    in.read(text.data(), tail);
    const std::size_t at = text.rfind(";Z:");
    if (at == std::string::npos) return 0.0;
    const double z = std::strtod(text.c_str() + at + 3, nullptr);
    return std::clamp((z - m_request.zOffsetMm) / m_request.heightMm, 0.0, 1.0);
  }

  const SliceRequest& m_request;
  std::string m_pending;
  double m_stagePercent = 0.0;
  double m_writtenFraction = 0.0;
  double m_reported = 0.0;
  std::chrono::steady_clock::time_point m_lastLook{};
};

// PrusaSlicer prints its stage lines with C stdio, which a pipe buffers until the program ends. coreutils'
// libstdbuf (what stdbuf -oL preloads), when installed, makes its stdout line-buffered so the lines arrive as
// it prints them; without it they arrive at the end and only the G-code's height moves the progress.
std::optional<std::string> lineBufferingLibrary() {
  for (const char* library : {"/usr/libexec/coreutils/libstdbuf.so", "/usr/lib/coreutils/libstdbuf.so",
                              "/usr/local/libexec/coreutils/libstdbuf.so"})
    if (::access(library, R_OK) == 0) return std::string(library);
  return std::nullopt;
}

// The child's environment: the library that keeps it on one thread (one_tbb_thread.cpp) preloaded, and
// libstdbuf with line-buffered stdout when its progress is followed, before what LD_PRELOAD held already.
std::vector<std::string> slicerEnvironment(bool followProgress) {
  std::string preload = kOneTbbThreadLibrary;
  std::vector<std::string> environment;
  if (followProgress) {
    if (const std::optional<std::string> stdbuf = lineBufferingLibrary()) {
      preload += ":" + *stdbuf;
      environment.push_back("_STDBUF_O=L");
    }
  }
  const char* preloaded = std::getenv("LD_PRELOAD");
  if (preloaded && *preloaded) preload += std::string(":") + preloaded;
  environment.push_back("LD_PRELOAD=" + preload);
  return environment;
}

std::string numberText(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.6f", value);
  return text;
}

}  // namespace

PrusaSlicerEngine::PrusaSlicerEngine(std::string executable) : m_executable(std::move(executable)) {}

core::Result<SliceRun> PrusaSlicerEngine::slice(const SliceRequest& request, core::JobContext& context) const {
  std::vector<std::string> argv = {m_executable, "--loglevel", "1", "--export-gcode"};
  for (const std::string& config : request.configFiles) {
    argv.push_back("--load");
    argv.push_back(config);
  }
  argv.insert(argv.end(), {"--dont-arrange", "--z-offset", numberText(request.zOffsetMm), "-o", request.outputFile,
                           request.meshFile});
  SliceRun run;
  run.command = commandText(argv);
  std::error_code ec;
  std::filesystem::remove(request.outputFile, ec);

  const auto start = std::chrono::steady_clock::now();
  ProgressFollower follower(request);
  // One CPU and one thread: the same G-code for the same request (side_by_side.h). The library's cap holds only
  // in a process confined to one CPU, hence both.
  if (::access(kOneTbbThreadLibrary, R_OK) != 0)
    return Error{ErrorCode::FileNotFound,
                 std::string("the library that keeps PrusaSlicer on one thread, ") + kOneTbbThreadLibrary +
                     ", is missing; build the target multidir_one_tbb_thread (it is built with multidir_slicing)",
                 kOneTbbThreadLibrary};
  const int cpu = request.cpu.value_or(usableCpus().front());
  const bool followProgress = static_cast<bool>(request.progress);
  core::Result<ChildOutput> child = runChildProcess(
      argv, context,
      followProgress ? std::function<void(const std::string&)>(
                           [&follower](const std::string& piece) { follower.take(piece); })
                     : std::function<void(const std::string&)>(),
      slicerEnvironment(followProgress), cpu);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!child) return child.error();
  const std::string tail = lastLines(child->output, kOutputLinesInErrors);
  if (child->exitCode != 0)
    return Error{ErrorCode::ExternalToolFailed,
                 "PrusaSlicer failed (exit code " + std::to_string(child->exitCode) + "). Command: " + run.command +
                     "\nIts last output:\n" + (tail.empty() ? "(none)" : tail),
                 m_executable};
  std::ifstream in(request.outputFile, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  run.gcode = text.str();
  if (run.gcode.empty())
    return Error{ErrorCode::ExternalToolFailed,
                 "PrusaSlicer ended without writing " + request.outputFile + ". Command: " + run.command +
                     "\nIts last output:\n" + (tail.empty() ? "(none)" : tail),
                 m_executable};
  return run;
}

}  // namespace multidir::slicing

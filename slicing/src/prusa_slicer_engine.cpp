#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "multidir/slicing/child_process.h"
#include "multidir/slicing/slicer_engine.h"

namespace multidir::slicing {

namespace {

using core::Error;
using core::ErrorCode;

constexpr int kOutputLinesInErrors = 8;

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
  core::Result<ChildOutput> child = runChildProcess(argv, context);
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

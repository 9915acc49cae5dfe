// A sliced job read and converted step by step (step_converter.*), then written as the contract's folder.
#include "multidir/robot/robot_program.h"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "multidir/core/common/atomic_file.h"
#include "multidir/core/common/staged_folder.h"
#include "job_inputs.h"
#include "program_parts.h"
#include "step_converter.h"

namespace multidir::robot {
namespace {

std::string fixed(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

}  // namespace

core::Result<RobotJob> planRobotJob(const std::filesystem::path& jobDirectory, const Cell& cell,
                                    const RobotProgramOptions& options, core::JobContext context) {
  const auto started = std::chrono::steady_clock::now();
  auto inputs = detail::readJobInputs(jobDirectory, cell);
  if (!inputs) return inputs.error();
  RobotJob result;
  result.robot = cell.arm.name;
  std::vector<std::string> refusals;
  const std::size_t stepCount = inputs->steps.size();
  for (std::size_t k = 0; k < stepCount; ++k) {
    const detail::StepInput& input = inputs->steps[k];
    context.setProgress(static_cast<double>(k) / static_cast<double>(stepCount), "step " + std::to_string(input.step));
    detail::StepOutput converted = detail::convertStep(input, cell, options, context);
    if (context.isCancelled()) return core::Error{core::ErrorCode::Cancelled, "cancelled", jobDirectory.string()};
    refusals.insert(refusals.end(), converted.refusals.begin(), converted.refusals.end());
    std::vector<std::string> partScripts;
    if (converted.refusals.empty()) {
      auto parts = detail::splitStepProgram(converted.script, input.step, cell.maxProgramBytes);
      if (!parts) {
        refusals.push_back(parts.error().message);
      } else {
        const int count = static_cast<int>(parts->size());
        for (int p = 0; p < count; ++p) {
          detail::ProgramPart& part = (*parts)[static_cast<std::size_t>(p)];
          converted.summary.parts.push_back(
              {detail::partFileName(input.step, p + 1, count), part.text.size(), part.firstMovel, part.movels});
          partScripts.push_back(std::move(part.text));
        }
        converted.summary.program = converted.summary.parts.front().program;
      }
    }
    result.steps.push_back(converted.summary);
    result.scripts.push_back(std::move(converted.script));
    result.partScripts.push_back(std::move(partScripts));
  }
  if (!refusals.empty()) {
    std::string message = "the job cannot run on the cell (" + std::to_string(refusals.size()) + " step(s) refused):";
    for (const auto& r : refusals) message += "\n  " + r;
    message += "\nNothing was written.";
    return core::Error{core::ErrorCode::CheckFailed, message, jobDirectory.string()};
  }
  result.conversionSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  context.setProgress(1.0, "done");
  return result;
}

std::string robotJobSummary(const RobotJob& job) {
  std::ostringstream s;
  s << "Robot programs for a " << job.robot << " (robot-job.json; docs/robot-cell.md)\n\n";
  s << "step  program                  parts  moves  robot time  slicer time  filament mm  reach margin  wrist margin  slowest joint  "
       "slowdowns  rotation  branch  re-orientations\n";
  double seconds = 0.0, slicer = 0.0, filament = 0.0;
  int moves = 0, slowdowns = 0;
  for (const auto& st : job.steps) {
    char line[320];
    std::snprintf(line, sizeof line, "%4d  %-23s %6zu %6d  %8.0f s  %9.0f s  %11.1f  %9.1f mm  %8.1f deg  %6d (%3.0f%%)  %9d  %5.0f deg  %6d  %15zu\n",
                  st.step, st.program.c_str(), std::max<std::size_t>(st.parts.size(), 1), st.moves, st.seconds, st.slicerSeconds, st.filamentMm, st.reachMarginMm,
                  st.wristMarginDegrees, st.slowestJoint, 100.0 * st.slowestJointLoad, st.slowdowns,
                  st.rotationDegrees, st.branch, st.reorientations.size());
    s << line;
    seconds += st.seconds;
    slicer += st.slicerSeconds;
    filament += st.filamentMm;
    moves += st.moves;
    slowdowns += st.slowdowns;
  }
  s << "total " << moves << " moves, robot " << fixed(seconds / 60.0, 1) << " min (slicer's estimate "
    << fixed(slicer / 60.0, 1) << " min), filament " << fixed(filament, 1) << " mm, " << slowdowns
    << " moves slowed\n";
  for (const auto& st : job.steps) {
    if (st.parts.size() < 2) continue;
    std::size_t largest = 0, total = 0;
    for (const auto& part : st.parts) {
      largest = std::max(largest, part.bytes);
      total += part.bytes;
    }
    s << "step " << st.step << " split into " << st.parts.size() << " programs (" << st.parts.front().program << " to "
      << st.parts.back().program << "), " << fixed(static_cast<double>(total) / 1000.0, 1) << " kB in all, the largest "
      << fixed(static_cast<double>(largest) / 1000.0, 1) << " kB\n";
  }
  for (const auto& st : job.steps)
    for (const auto& r : st.reorientations) {
      char line[200];
      std::snprintf(line, sizeof line,
                    "step %d re-oriented before G-code line %d: rotation about the nozzle axis %.0f deg, branch %d\n",
                    st.step, r.line, r.rotationDegrees, r.branch);
      s << line;
    }
  for (const auto& st : job.steps)
    if (st.viaPointsFromHome + st.viaPointsToHome > 0)
      s << "step " << st.step << " joint moves: " << st.viaPointsFromHome << " via point(s) from home, "
        << st.viaPointsToHome << " back home (the straight joint move is not clear)\n";
  s << "\nrobot time: the arm's trapezoid per move at the tool acceleration, heating waits excluded; slowest joint: "
       "its peak speed as a share of its limit at the G-code's feeds (over 100 %: the move was slowed).\n";
  return s.str();
}

core::Status writeRobotJob(const RobotJob& job, const std::filesystem::path& cellFile,
                           const std::filesystem::path& outDirectory) {
  std::error_code ec;
  const std::filesystem::path parent = std::filesystem::absolute(outDirectory, ec).parent_path();
  std::filesystem::create_directories(parent, ec);
  auto staged = core::StagedFolder::beside(outDirectory.string());
  if (!staged) return staged.error();
  const std::filesystem::path dir = staged->path();
  nlohmann::ordered_json steps = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < job.steps.size(); ++i) {
    const RobotStepSummary& st = job.steps[i];
    nlohmann::ordered_json parts = nlohmann::ordered_json::array();
    const bool split = i < job.partScripts.size() && !job.partScripts[i].empty();
    const std::size_t count = split ? job.partScripts[i].size() : 1;
    for (std::size_t p = 0; p < count; ++p) {
      const std::string& text = split ? job.partScripts[i][p] : job.scripts[i];
      const std::string name = split ? st.parts[p].program : st.program;
      auto written = core::writeTextFileAtomically((dir / name).string(), text);
      if (!written) return written.error();
      parts.push_back({{"program", name},
                       {"bytes", text.size()},
                       {"firstMovel", split ? st.parts[p].firstMovel : 1},
                       {"movels", split ? st.parts[p].movels : st.moves}});
    }
    nlohmann::ordered_json entry;
    entry["step"] = st.step;
    entry["program"] = st.program;
    entry["parts"] = parts;
    entry["seconds"] = std::round(st.seconds * 10.0) / 10.0;
    entry["filamentMm"] = std::round(st.filamentMm * 10.0) / 10.0;
    entry["moves"] = st.moves;
    entry["reachMarginMm"] = std::round(st.reachMarginMm * 10.0) / 10.0;
    entry["slowestJoint"] = st.slowestJoint;
    entry["slowdowns"] = st.slowdowns;
    entry["wristMarginDegrees"] = std::round(st.wristMarginDegrees * 10.0) / 10.0;
    entry["gcodeFilamentMm"] = std::round(st.gcodeFilamentMm * 10.0) / 10.0;
    entry["slicerSeconds"] = st.slicerSeconds;
    entry["rotationDegrees"] = st.rotationDegrees;
    entry["branch"] = st.branch;
    nlohmann::ordered_json reorientations = nlohmann::ordered_json::array();
    for (const auto& r : st.reorientations)
      reorientations.push_back({{"line", r.line}, {"rotationDegrees", r.rotationDegrees}, {"branch", r.branch}});
    entry["reorientations"] = reorientations;
    entry["viaPoints"] = {{"fromHome", st.viaPointsFromHome}, {"toHome", st.viaPointsToHome}};
    steps.push_back(entry);
  }
  std::ifstream cellIn(cellFile, std::ios::binary);
  if (!cellIn) return core::Error{core::ErrorCode::FileNotFound, "cannot read the cell file to copy it", cellFile.string()};
  std::ostringstream cellText;
  cellText << cellIn.rdbuf();
  auto cellWritten = core::writeTextFileAtomically((dir / "cell.json").string(), cellText.str());
  if (!cellWritten) return cellWritten.error();
  auto summaryWritten = core::writeTextFileAtomically((dir / "summary.txt").string(), robotJobSummary(job));
  if (!summaryWritten) return summaryWritten.error();
  nlohmann::ordered_json root;
  root["format"] = "multidir-robot-job";
  root["version"] = 2;  // 2: each step lists its programs ("parts"); 1 had one program per step
  root["robot"] = job.robot;
  root["cell"] = "cell.json";
  root["steps"] = steps;
  auto jobWritten = core::writeTextFileAtomically((dir / "robot-job.json").string(), root.dump(2) + "\n");
  if (!jobWritten) return jobWritten.error();
  return staged->replaceTarget();
}

}  // namespace multidir::robot

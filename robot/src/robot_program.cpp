// A sliced job read and converted step by step (step_converter.*), then written as the contract's folder.
#include "multidir/robot/robot_program.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "multidir/core/common/atomic_file.h"
#include "multidir/core/common/staged_folder.h"
#include "multidir/slicing/audit.h"
#include "step_converter.h"

namespace multidir::robot {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Part points are the meshes' corners, one per cell of this size (docs/robot-cell.md, "Collisions").
constexpr double kPointCellMm = 2.0;
// The platform's rim is sampled this often.
constexpr int kRimSamples = 72;

// The meshes' corners in the platform frame, one per kPointCellMm cube.
void addCorners(const core::TriangleMesh& mesh, const Eigen::Isometry3d& modelToPlatform,
                detail::CarriedPoint::Kind kind, std::vector<detail::CarriedPoint>& out) {
  std::unordered_set<long long> seen;
  for (const core::Vec3& v : mesh.vertices) {
    const Eigen::Vector3d p = modelToPlatform * v;
    const long long ix = static_cast<long long>(std::floor(p.x() / kPointCellMm)) & 0x1fffff;
    const long long iy = static_cast<long long>(std::floor(p.y() / kPointCellMm)) & 0x1fffff;
    const long long iz = static_cast<long long>(std::floor(p.z() / kPointCellMm)) & 0x1fffff;
    if (!seen.insert((ix << 42) | (iy << 21) | iz).second) continue;
    out.push_back({p, kind});
  }
}

std::string fixed(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

}  // namespace

core::Result<RobotJob> planRobotJob(const std::filesystem::path& jobDirectory, const Cell& cell,
                                    const RobotProgramOptions& options, core::JobContext context) {
  const auto started = std::chrono::steady_clock::now();
  auto job = slicing::readAuditJob(jobDirectory.string());
  if (!job) return job.error();
  if (job->platform == slicing::AuditPlatform::FirmwareAxis || job->platform == slicing::AuditPlatform::FirmwareTwoAxis) {
    return core::Error{core::ErrorCode::InvalidParameter,
                       "the job was sliced for a printer with platform axes in its firmware; slice it with the cell's "
                       "profile (multidir slice PLAN --printer ur5-cell-0.8)",
                       jobDirectory.string()};
  }
  // The slicer's estimates, for the summary.
  std::vector<double> slicerSeconds(job->steps.size(), 0.0);
  {
    std::ifstream in(jobDirectory / "print-job.json");
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (!j.is_discarded() && j.contains("slicing") && j["slicing"].contains("steps")) {
      const auto& steps = j["slicing"]["steps"];
      for (std::size_t i = 0; i < steps.size() && i < slicerSeconds.size(); ++i) {
        if (steps[i].contains("estimate") && steps[i]["estimate"].contains("printSeconds") &&
            steps[i]["estimate"]["printSeconds"].is_number())
          slicerSeconds[i] = steps[i]["estimate"]["printSeconds"].get<double>();
      }
    }
  }
  // The platform frame: z = the plan's up, origin the pivot (the platform centre), as the rest pose.
  slicing::AuditMachine rest = job->machine;
  rest.kind = core::MachineKind::ThreeAxis;
  const Eigen::Isometry3d modelToPlatform = slicing::auditModelToFile(rest, {});
  const Eigen::Isometry3d platformToModel = modelToPlatform.inverse();

  std::vector<detail::CarriedPoint> rim;
  for (int i = 0; i < kRimSamples; ++i) {
    const double a = 2.0 * kPi * i / kRimSamples;
    const Eigen::Vector3d edge(cell.platformRadiusMm * std::cos(a), cell.platformRadiusMm * std::sin(a), 0.0);
    rim.push_back({edge, detail::CarriedPoint::Kind::Platform});
    rim.push_back({edge - Eigen::Vector3d(0, 0, cell.platformThicknessMm), detail::CarriedPoint::Kind::Platform});
  }
  rim.push_back({Eigen::Vector3d(0, 0, -cell.platformThicknessMm), detail::CarriedPoint::Kind::Platform});

  RobotJob result;
  result.robot = cell.arm.name;
  std::vector<std::string> refusals;
  std::vector<detail::CarriedPoint> earlier;
  for (std::size_t k = 0; k < job->steps.size(); ++k) {
    const slicing::AuditStep& step = job->steps[k];
    context.setProgress(static_cast<double>(k) / static_cast<double>(job->steps.size()),
                        "step " + std::to_string(step.index));
    detail::StepInput input;
    input.step = step.index;
    input.stepCount = static_cast<int>(job->steps.size());
    input.gcodeFile = step.gcodeFile;
    input.gcode = step.gcode;
    input.platformToFile = step.recordedModelToFile * platformToModel;
    input.printerOffsetMm = job->printerOffset;
    input.slicerSeconds = slicerSeconds[k];
    input.carried = rim;
    input.carried.insert(input.carried.end(), earlier.begin(), earlier.end());
    std::vector<detail::CarriedPoint> own;
    addCorners(step.region, modelToPlatform, detail::CarriedPoint::Kind::ThisStep, own);
    addCorners(step.supports, modelToPlatform, detail::CarriedPoint::Kind::ThisStep, own);
    input.carried.insert(input.carried.end(), own.begin(), own.end());
    detail::StepOutput converted = detail::convertStep(input, cell, options, context);
    if (context.isCancelled()) return core::Error{core::ErrorCode::Cancelled, "cancelled", jobDirectory.string()};
    refusals.insert(refusals.end(), converted.refusals.begin(), converted.refusals.end());
    result.steps.push_back(converted.summary);
    result.scripts.push_back(std::move(converted.script));
    for (auto& p : own) p.kind = detail::CarriedPoint::Kind::EarlierStep;
    earlier.insert(earlier.end(), own.begin(), own.end());
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
  s << "step  program          moves  robot time  slicer time  filament mm  reach margin  wrist margin  slowest joint  "
       "slowdowns  rotation  branch\n";
  double seconds = 0.0, slicer = 0.0, filament = 0.0;
  int moves = 0, slowdowns = 0;
  for (const auto& st : job.steps) {
    char line[256];
    std::snprintf(line, sizeof line, "%4d  %-15s %6d  %8.0f s  %9.0f s  %11.1f  %9.1f mm  %8.1f deg  %6d (%3.0f%%)  %9d  %5.0f deg  %6d\n",
                  st.step, st.program.c_str(), st.moves, st.seconds, st.slicerSeconds, st.filamentMm, st.reachMarginMm,
                  st.wristMarginDegrees, st.slowestJoint, 100.0 * st.slowestJointLoad, st.slowdowns,
                  st.rotationDegrees, st.branch);
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
    auto written = core::writeTextFileAtomically((dir / st.program).string(), job.scripts[i]);
    if (!written) return written.error();
    nlohmann::ordered_json entry;
    entry["step"] = st.step;
    entry["program"] = st.program;
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
  root["version"] = 1;
  root["robot"] = job.robot;
  root["cell"] = "cell.json";
  root["steps"] = steps;
  auto jobWritten = core::writeTextFileAtomically((dir / "robot-job.json").string(), root.dump(2) + "\n");
  if (!jobWritten) return jobWritten.error();
  return staged->replaceTarget();
}

}  // namespace multidir::robot

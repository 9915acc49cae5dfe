// buildPrintJob, writePrintJob and exportPrintJob: a plan's regions posed as the machine prints them, and
// print-job.json.
#include "multidir/core/plan/print_job.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <new>

#include "multidir/core/common/units.h"
#include "multidir/core/mesh/mesh_io.h"
#include "plan/json_file.h"
#include "plan/output_folder.h"
#include "plan/settings_json.h"

namespace multidir::core {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

constexpr const char* kPrintJobSchema = "multidir-print-job";
constexpr const char* kPrintJobFileName = "print-job.json";
// The slack loadPlan grants printing directions (plan_json.cpp): well above the search's rounding, well below
// a stepper step.
constexpr double kRealizableToleranceRadians = 1e-4;
// How far a direction may be from up, or from its base plane's normal, and still be that direction.
constexpr double kSameDirectionTolerance = 1e-6;

Error inconsistent(const std::string& what) { return Error{ErrorCode::InvalidParameter, what, "print job"}; }

std::string stepFileName(std::size_t index, const char* kind, const std::string& format) {
  char name[64];
  std::snprintf(name, sizeof name, "step-%02zu-%s.", index + 1, kind);
  return name + format;
}

// Rows of the files' frame: the platform frame (x, up x x, up) becomes (+X, +Y, +Z).
Eigen::Matrix3d upToZ(const Vec3& up) {
  const Vec3 x = platformFrameX(up);
  Eigen::Matrix3d rows;
  rows.row(0) = x.transpose();
  rows.row(1) = up.cross(x).transpose();
  rows.row(2) = up.transpose();
  return rows;
}

TriangleMesh moved(const TriangleMesh& mesh, const Eigen::Isometry3d& motion) {
  TriangleMesh out = mesh;
  for (Vec3& v : out.vertices) v = motion * v;
  return out;
}

// The checks that make every pose meaningful; the first violation, naming the region.
Status checkPlan(const LoadedPlan& plan, const MachineSpec& machine) {
  const std::vector<Region>& regions = plan.decomposition.regions;
  if (regions.empty()) return inconsistent("the plan has no regions: there is nothing to print");
  if (Status valid = validate(machine); !valid)
    return inconsistent("the plan's machine is invalid: " + valid.error().describe());
  if (!plan.supports.empty() && plan.supports.size() != regions.size())
    return inconsistent("the plan has " + std::to_string(plan.supports.size()) + " support sets for " +
                        std::to_string(regions.size()) + " regions: it needs one per region or none");
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const Region& region = regions[i];
    const std::string name = "region " + std::to_string(i + 1);
    if (region.mesh.empty()) return inconsistent(name + " has no faces");
    for (std::size_t f = 0; f < region.mesh.triangles.size(); ++f)
      for (std::int32_t v : region.mesh.triangles[f])
        if (v < 0 || static_cast<std::size_t>(v) >= region.mesh.vertices.size())
          return inconsistent(name + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                              ", which does not exist");
    const Vec3& d = region.printingDirection;
    if (!d.allFinite() || std::abs(d.norm() - 1.0) > kSameDirectionTolerance)
      return inconsistent(name + ": the printing direction is not a unit vector");
    if (i == 0 && (d - machine.up).norm() > kSameDirectionTolerance)
      return inconsistent(name + " stands on the platform but is not printed along the machine's up");
    if (i > 0 && !region.basePlane)
      return inconsistent(name + " has no base plane: every region after the first stands on a clipping plane");
    if (region.basePlane && (region.basePlane->normal - d).norm() > kSameDirectionTolerance)
      return inconsistent(name + ": the printing direction differs from the base plane's normal");
    // The first region is printed with the platform at rest, whether or not 0 is a step of the stepper.
    if (i > 0 && !isRealizable(machine, d, kRealizableToleranceRadians))
      return inconsistent(name + ": the " + std::string(machineKindName(machine.kind)) +
                          " machine cannot print along its direction");
    if (!plan.supports.empty() && plan.supports[i].regionIndex != static_cast<int>(i))
      return inconsistent("support set " + std::to_string(i + 1) + " says it belongs to region " +
                          std::to_string(plan.supports[i].regionIndex + 1));
  }
  return Done{};
}

PrintJobStep makeStep(const LoadedPlan& plan, std::size_t i, const PrintJob& job) {
  const Region& region = plan.decomposition.regions[i];
  const MachineSpec& machine = job.machine;
  const Vec3& pivot = job.platform.center;
  PrintJobStep step;
  step.index = static_cast<int>(i + 1);
  step.regionFile = stepFileName(i, "region", job.options.format);
  step.printingDirection = region.printingDirection;
  step.angles = machineAnglesFor(machine, region.printingDirection);
  step.basePlane = region.basePlane;
  step.volumeMm3 = region.volumeMm3;
  step.riskyAreaMm2 = region.riskyAreaMm2;

  Eigen::Isometry3d machineFrame = Eigen::Isometry3d::Identity();
  machineFrame.linear() = upToZ(machine.up);
  machineFrame.translation() = -(machineFrame.linear() * pivot);
  machineFrame = machineFrame * machinePose(machine, region.printingDirection, pivot);
  step.lowestHeightMm = std::numeric_limits<double>::infinity();
  for (const Vec3& v : region.mesh.vertices)
    step.lowestHeightMm = std::min(step.lowestHeightMm, (machineFrame * v).z());
  if (job.options.frame == PrintJobOptions::Frame::Machine) step.modelToFile = machineFrame;

  step.region = moved(region.mesh, step.modelToFile);
  if (job.options.supports && !plan.supports.empty()) {
    const SupportSet& set = plan.supports[i];
    if (!set.empty() && !set.mesh.empty()) {
      step.supportsFile = stepFileName(i, "supports", job.options.format);
      step.supports = moved(set.mesh, step.modelToFile);
      step.supportVolumeMm3 = set.volumeMm3;
    }
  }
  return step;
}

ordered_json anglesToJson(MachineKind kind, const MachineAngles& angles) {
  switch (kind) {
    case MachineKind::ThreeAxis:
      return ordered_json::object();
    case MachineKind::RotaryPlatform:
      return {{"rotaryDegrees", angles.rotaryDegrees}};
    case MachineKind::TiltRotate:
    case MachineKind::Apart:
      return {{"tiltDegrees", angles.tiltDegrees}, {"azimuthDegrees", angles.azimuthDegrees}};
  }
  return ordered_json::object();
}

ordered_json motionToJson(const Eigen::Isometry3d& motion) {
  ordered_json rows = ordered_json::array();
  for (int r = 0; r < 3; ++r)
    rows.push_back({motion.linear()(r, 0), motion.linear()(r, 1), motion.linear()(r, 2), motion.translation()(r)});
  return rows;
}

ordered_json stepToJson(const PrintJobStep& step, MachineKind kind) {
  const ordered_json files = {
      {"region", step.regionFile},
      {"supports", step.supportsFile.empty() ? ordered_json(nullptr) : ordered_json(step.supportsFile)}};
  const ordered_json base = step.basePlane ? ordered_json{{"normal", detail::toJson(step.basePlane->normal)},
                                                          {"offsetMm", step.basePlane->offset}}
                                           : ordered_json(nullptr);
  return {{"index", step.index},
          {"files", files},
          {"printingDirection", detail::toJson(step.printingDirection)},
          {"angles", anglesToJson(kind, step.angles)},
          {"basePlane", base},
          {"lowestHeightMm", step.lowestHeightMm},
          {"volumeMm3", step.volumeMm3},
          {"riskyAreaMm2", step.riskyAreaMm2},
          {"supportVolumeMm3", step.supportVolumeMm3},
          {"modelToFile", motionToJson(step.modelToFile)}};
}

std::string printJobText(const PrintJob& job) {
  ordered_json steps = ordered_json::array();
  for (const PrintJobStep& step : job.steps) steps.push_back(stepToJson(step, job.machine.kind));
  const ordered_json document = {
      {"schema", kPrintJobSchema},
      {"version", kPrintJobFormatVersion},
      {"units", {{"length", "mm"}, {"angle", "degrees"}}},
      {"model",
       {{"path", job.modelPath},
        {"checksum", job.modelChecksum.empty() ? ordered_json(nullptr) : ordered_json(job.modelChecksum)},
        {"up", detail::toJson(job.modelUp)}}},
      {"plan", job.planDirectory},
      {"machine", detail::machineToJson(job.machine)},
      {"frame", printJobFrameName(job.options.frame)},
      {"format", job.options.format},
      {"pivot",
       {{"point", detail::toJson(job.platform.center)},
        {"name", "platform centre"},
        {"platformRadiusMm", job.platform.radiusMm}}},
      {"steps", steps}};
  return document.dump(2) + "\n";
}

// A file name the job may write: inside the folder, with the job's extension.
bool isStepFileName(const std::string& name, const std::string& format) {
  const std::string extension = "." + format;
  return name.size() > extension.size() && name[0] != '.' && name.find('/') == std::string::npos &&
         name.find('\\') == std::string::npos &&
         name.compare(name.size() - extension.size(), extension.size(), extension) == 0;
}

Status checkJob(const PrintJob& job) {
  if (Status valid = validate(job.options); !valid) return valid;
  if (job.steps.empty()) return inconsistent("the job has no steps: there is nothing to write");
  for (const PrintJobStep& step : job.steps) {
    const std::string name = "step " + std::to_string(step.index);
    if (!isStepFileName(step.regionFile, job.options.format))
      return inconsistent(name + ": '" + step.regionFile + "' is not a ." + job.options.format +
                          " file name inside the job's folder");
    if (!step.supportsFile.empty() && !isStepFileName(step.supportsFile, job.options.format))
      return inconsistent(name + ": '" + step.supportsFile + "' is not a ." + job.options.format +
                          " file name inside the job's folder");
  }
  return Done{};
}

}  // namespace

Eigen::Isometry3d machinePose(const MachineSpec& machine, const Vec3& printingDirection, const Vec3& pivot) {
  const Eigen::Matrix3d rotation = platformRotation(machine, machineAnglesFor(machine, printingDirection.normalized()));
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation;
  pose.translation() = pivot - rotation * pivot;
  return pose;
}

const char* printJobFrameName(PrintJobOptions::Frame frame) {
  return frame == PrintJobOptions::Frame::Machine ? "machine" : "model";
}

Result<PrintJobOptions::Frame> parsePrintJobFrame(const std::string& text) {
  if (text == "machine") return PrintJobOptions::Frame::Machine;
  if (text == "model") return PrintJobOptions::Frame::Model;
  return Error{ErrorCode::InvalidParameter,
               "'" + text + "' is not a frame: use machine (as the machine holds each region, up = +Z) or model",
               "frame"};
}

Status validate(const PrintJobOptions& options) {
  const std::string& f = options.format;
  if (f != "stl" && f != "obj" && f != "ply" && f != "off")
    return Error{ErrorCode::UnsupportedFormat,
                 "'" + f + "' is not a mesh format MultiDir writes: use stl, obj, ply or off", "format"};
  return Done{};
}

Result<PrintJob> buildPrintJob(const LoadedPlan& plan, const PrintJobOptions& options) {
  if (Status valid = validate(options); !valid) return valid.error();
  try {
    PrintJob job;
    job.options = options;
    job.machine = plan.metadata.machine;
    // 4-DOF plans are printed about the axis the search chose, which an axis search may have turned.
    if (job.machine.kind == MachineKind::RotaryPlatform) job.machine.rotationAxis = plan.decomposition.rotationAxis;
    if (Status consistent = checkPlan(plan, job.machine); !consistent) return consistent.error();
    job.platform = platformRegionFor(plan.decomposition.regions.front().mesh, job.machine);
    job.modelPath = plan.metadata.modelPath;
    job.modelChecksum = plan.metadata.modelChecksum;
    job.modelUp = plan.metadata.up;
    job.planDirectory = plan.directory;
    for (std::size_t i = 0; i < plan.decomposition.regions.size(); ++i) job.steps.push_back(makeStep(plan, i, job));
    return job;
  } catch (const std::bad_alloc&) {
    return Error{ErrorCode::TooLarge, "there is not enough memory to pose this plan's regions", "print job"};
  }
}

Status writePrintJob(const PrintJob& job, const std::string& directory) {
  if (Status valid = checkJob(job); !valid) return valid;
  try {
    const std::string text = printJobText(job);
    const fs::path folder(directory);
    if (Status made = detail::makeOutputFolder(folder, "print job folder"); !made) return made;
    std::error_code ec;
    fs::remove(folder / kPrintJobFileName, ec);
    if (ec)
      return Error{ErrorCode::WriteFailed, "cannot remove the older print job description: " + ec.message(),
                   (folder / kPrintJobFileName).string()};
    for (const PrintJobStep& step : job.steps) {
      if (Status saved = saveMesh(step.region, (folder / step.regionFile).string()); !saved) return saved;
      if (!step.supportsFile.empty())
        if (Status saved = saveMesh(step.supports, (folder / step.supportsFile).string()); !saved) return saved;
    }
    return detail::writeTextFile((folder / kPrintJobFileName).string(), text, kPrintJobFileName);
  } catch (const std::bad_alloc&) {
    return Error{ErrorCode::WriteFailed, "there is not enough memory to write the print job", directory};
  } catch (const std::exception& e) {
    return Error{ErrorCode::WriteFailed, std::string("writing the print job failed: ") + e.what(), directory};
  }
}

Status exportPrintJob(const LoadedPlan& plan, const PrintJobOptions& options, const std::string& directory) {
  const Result<PrintJob> job = buildPrintJob(plan, options);
  if (!job) return job.error();
  return writePrintJob(*job, directory);
}

}  // namespace multidir::core

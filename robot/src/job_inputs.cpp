// A sliced job read into the step converter's inputs: each step's G-code, its pose (platform frame to the
// files' frame), and what the platform carries while it prints (the platform disc, the regions printed before,
// its own region) as points for the collision checks.
#include "job_inputs.h"

#include <cmath>
#include <fstream>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "multidir/slicing/audit.h"

namespace multidir::robot::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Part points are the meshes' corners, one per cell of this size (docs/robot-cell.md, "Collisions").
constexpr double kPointCellMm = 2.0;
// The platform's rim is sampled this often.
constexpr int kRimSamples = 72;

// The meshes' corners in the platform frame, one per kPointCellMm cube.
void addCorners(const core::TriangleMesh& mesh, const Eigen::Isometry3d& modelToPlatform, CarriedPoint::Kind kind,
                std::vector<CarriedPoint>& out) {
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

core::TriangleMesh moved(core::TriangleMesh mesh, const Eigen::Isometry3d& transform) {
  for (core::Vec3& v : mesh.vertices) v = transform * v;
  return mesh;
}

}  // namespace

core::Result<JobInputs> readJobInputs(const std::filesystem::path& jobDirectory, const Cell& cell) {
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

  std::vector<CarriedPoint> rim;
  for (int i = 0; i < kRimSamples; ++i) {
    const double a = 2.0 * kPi * i / kRimSamples;
    const Eigen::Vector3d edge(cell.platformRadiusMm * std::cos(a), cell.platformRadiusMm * std::sin(a), 0.0);
    rim.push_back({edge, CarriedPoint::Kind::Platform});
    rim.push_back({edge - Eigen::Vector3d(0, 0, cell.platformThicknessMm), CarriedPoint::Kind::Platform});
  }
  rim.push_back({Eigen::Vector3d(0, 0, -cell.platformThicknessMm), CarriedPoint::Kind::Platform});

  JobInputs inputs;
  std::vector<CarriedPoint> earlier;
  for (std::size_t k = 0; k < job->steps.size(); ++k) {
    slicing::AuditStep& step = job->steps[k];
    StepInput input;
    input.step = step.index;
    input.stepCount = static_cast<int>(job->steps.size());
    input.gcodeFile = step.gcodeFile;
    input.gcode = std::move(step.gcode);
    input.platformToFile = step.recordedModelToFile * platformToModel;
    input.printerOffsetMm = job->printerOffset;
    input.slicerSeconds = slicerSeconds[k];
    input.carried = rim;
    input.carried.insert(input.carried.end(), earlier.begin(), earlier.end());
    std::vector<CarriedPoint> own;
    addCorners(step.region, modelToPlatform, CarriedPoint::Kind::ThisStep, own);
    addCorners(step.supports, modelToPlatform, CarriedPoint::Kind::ThisStep, own);
    input.carried.insert(input.carried.end(), own.begin(), own.end());
    for (auto& p : own) p.kind = CarriedPoint::Kind::EarlierStep;
    earlier.insert(earlier.end(), own.begin(), own.end());
    inputs.steps.push_back(std::move(input));
    inputs.regions.push_back(moved(std::move(step.region), modelToPlatform));
    inputs.supports.push_back(moved(std::move(step.supports), modelToPlatform));
  }
  return inputs;
}

}  // namespace multidir::robot::detail

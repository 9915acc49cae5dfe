// auditJob: the G-code of a sliced job replayed through the audit's kinematics and checked (audit.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <unordered_map>

#include "gcode_replay.h"
#include "multidir/slicing/audit.h"
#include "program_auditor.h"
#include "triangle_grid.h"

namespace multidir::slicing {

namespace {

using core::Error;
using core::ErrorCode;
using core::Vec3;

constexpr double kPoseTolerance = 1e-6;  // print-job.json's modelToFile against the kinematics

std::string fixed(double value, int digits = 3) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

std::string pointText(const Vec3& p) {
  return "(" + fixed(p.x(), 2) + ", " + fixed(p.y(), 2) + ", " + fixed(p.z(), 2) + ")";
}

double poseDifference(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.matrix().topRows<3>() - b.matrix().topRows<3>()).cwiseAbs().maxCoeff();
}

// A grid cell of a few triangles for the step's region and supports.
double solidCell(const AuditStep& step) {
  double area = 0.0;
  std::size_t count = 0;
  for (const core::TriangleMesh* mesh : {&step.region, &step.supports}) {
    for (std::size_t f = 0; f < mesh->faceCount(); ++f) area += mesh->faceArea(f);
    count += mesh->faceCount();
  }
  if (count == 0) return 1.0;
  return std::clamp(2.0 * std::sqrt(2.0 * area / static_cast<double>(count)), std::max(0.5, step.bead.widthMm), 20.0);
}

// The pose a step prints at: on two firmware axes, the rest pose (the first step's from its plan angles) turned
// by the axes to the step's recorded coordinates; otherwise the pose of the step's plan angles.
Eigen::Isometry3d stepPose(const AuditJob& job, const AuditStep& step) {
  if (job.platform == AuditPlatform::FirmwareTwoAxis && step.axisDegrees)
    return twoAxisModelToFile(job.twoAxes, auditModelToFile(job.machine, job.steps.front().angles), *step.axisDegrees);
  return auditModelToFile(job.machine, step.angles);
}

// Two firmware axes: a step's recorded coordinates must lie within the axes' limits.
void checkAxisLimits(const AuditJob& job, const AuditStep& step, AuditReport& report) {
  if (job.platform != AuditPlatform::FirmwareTwoAxis || !step.axisDegrees) return;
  for (const auto& [axis, degrees] : {std::pair{&job.twoAxes.tilt, step.axisDegrees->tiltDegrees},
                                      std::pair{&job.twoAxes.rotation, step.axisDegrees->rotationDegrees}}) {
    if (degrees >= axis->minDegrees - 1e-9 && degrees <= axis->maxDegrees + 1e-9) continue;
    ++report.poseMismatches;
    report.findings.push_back("print-job.json: step " + std::to_string(step.index) + ": " + axis->letter + " " +
                              fixed(degrees) + " degrees (slicing.steps[].axisDegrees) is outside the axis' limits " +
                              fixed(axis->minDegrees) + " to " + fixed(axis->maxDegrees));
  }
}

void checkPoses(const AuditJob& job, AuditReport& report) {
  const bool twoAxis = job.platform == AuditPlatform::FirmwareTwoAxis;
  for (const AuditStep& step : job.steps) {
    const Eigen::Isometry3d pose = stepPose(job, step);
    const double difference = poseDifference(pose, step.recordedModelToFile);
    if (difference > kPoseTolerance) {
      ++report.poseMismatches;
      report.findings.push_back(
          "print-job.json: step " + std::to_string(step.index) + ": modelToFile differs from the kinematics of its " +
          (twoAxis ? "axis coordinates (slicing.steps[].axisDegrees)" : "angles") + " by " + fixed(difference, 9) +
          " (largest entry): the step's mesh and G-code are posed otherwise than the machine will hold the part");
    }
    checkAxisLimits(job, step, report);
    const Vec3 direction = pose.linear().transpose() * Vec3::UnitZ();
    const double angle = std::acos(std::clamp(direction.dot(step.printingDirection.normalized()), -1.0, 1.0));
    if (angle > kPoseTolerance) {
      ++report.poseMismatches;
      report.findings.push_back("print-job.json: step " + std::to_string(step.index) + ": its " +
                                (twoAxis ? "axis coordinates" : "angles") + " print along " +
                                pointText(direction) + ", not along printingDirection " +
                                pointText(step.printingDirection));
    }
  }
  if (job.platform == AuditPlatform::FirmwareAxis && job.machine.kind == core::MachineKind::RotaryPlatform) {
    const Vec3 axis = firmwareAxisModelToFile(job.machine, 0.0).linear() * job.machine.rotationAxis;
    if (std::abs(std::abs(axis.x()) - 1.0) > kPoseTolerance) {
      ++report.poseMismatches;
      report.findings.push_back("print-job.json: the rotation axis maps to " + pointText(axis) +
                                " in the files' frame, but the firmware axis runs along X");
    }
  }
}

}  // namespace

bool AuditReport::failed() const {
  if (poseMismatches > 0) return true;
  for (const ProgramAudit& p : programs)
    if (p.total.outsideMm > 0.0 || p.total.firstLayerViolation || p.total.retractViolations > 0 ||
        p.total.turnViolation)
      return true;
  return sequenceViolations > 0;
}

bool AuditReport::hasUnsupported() const {
  for (const ProgramAudit& p : programs)
    if (p.total.unsupportedMm > 0.0) return true;
  return false;
}

core::Result<AuditReport> auditJob(const AuditJob& job, const AuditOptions& options, core::JobContext& context) {
  if (job.steps.empty()) return Error{ErrorCode::InvalidParameter, "the job has no steps", job.directory};
  AuditReport report;
  report.alphaMaxDegrees = options.alphaMaxDegrees.value_or(job.alphaMaxDegrees);
  checkPoses(job, report);

  std::vector<std::unique_ptr<audit::TriangleGrid>> solids;
  for (const AuditStep& step : job.steps)
    solids.push_back(std::make_unique<audit::TriangleGrid>(
        std::vector<const core::TriangleMesh*>{&step.region, &step.supports}, solidCell(step)));

  const bool firmware =
      (job.platform == AuditPlatform::FirmwareAxis || job.platform == AuditPlatform::FirmwareTwoAxis) &&
      !job.stitchedFile.empty();
  const double shares = firmware ? 2.0 : 1.0;

  // The step programs: one after another on one machine (Modbus), or each on its own (the parts of
  // job.gcode, which is what a firmware-axis printer runs).
  {
    context.setProgress(0.0, "auditing the step programs");
    ProgramAudit program;
    program.name = firmware ? "step programs (each on its own)" : "step programs";
    audit::ProgramAuditor auditor(job, options, report.alphaMaxDegrees, solids, program, report);
    audit::MachineState state;
    for (std::size_t k = 0; k < job.steps.size(); ++k) {
      if (firmware) state = audit::MachineState{};
      const Eigen::Isometry3d pose = stepPose(job, job.steps[k]);
      if (core::Status s = auditor.replay(job.steps[k].gcode, job.steps[k].gcodeFile, k, &pose, state, context); !s)
        return s.error();
      if (!firmware) auditor.modbusTurn(k, state);
    }
    auditor.finish();
    report.programs.push_back(std::move(program));
  }
  if (firmware) {
    context.setProgress(1.0 / shares, "auditing " + job.stitchedFile);
    ProgramAudit program;
    program.name = job.stitchedFile;
    program.stitched = true;
    program.followedAxes = job.platform == AuditPlatform::FirmwareTwoAxis
                               ? job.twoAxes.tilt.letter + " and " + job.twoAxes.rotation.letter + " axes"
                               : job.rotaryAxis + " axis";
    audit::ProgramAuditor auditor(job, options, report.alphaMaxDegrees, solids, program, report);
    audit::MachineState state;
    if (core::Status s = auditor.replay(job.stitchedGcode, job.stitchedFile, 0, nullptr, state, context); !s)
      return s.error();
    auditor.finish();
    report.programs.push_back(std::move(program));
  }
  context.setProgress(1.0, "audited");
  return report;
}

}  // namespace multidir::slicing

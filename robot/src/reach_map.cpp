// The reach map: nozzle positions scored by the share of the plan's needed platform poses reachable with margin.
#include "multidir/robot/reach_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <thread>

#include "multidir/core/common/atomic_file.h"
#include "multidir/core/plan/print_job.h"
#include "multidir/slicing/audit.h"
#include "step_converter.h"

namespace multidir::robot {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

}  // namespace

core::Result<std::vector<ReachStep>> reachStepsOfPlan(const core::LoadedPlan& plan) {
  core::PrintJobOptions options;
  auto job = core::buildPrintJob(plan, options);
  if (!job) return job.error();
  slicing::AuditMachine rest;
  rest.kind = core::MachineKind::ThreeAxis;
  rest.up = job->machine.up;
  rest.pivot = job->platform.center;
  const Eigen::Isometry3d platformToModel = slicing::auditModelToFile(rest, {}).inverse();
  std::vector<ReachStep> steps;
  for (const auto& step : job->steps) {
    ReachStep s;
    s.platformToFile = step.modelToFile * platformToModel;
    Eigen::AlignedBox3d box;
    for (const auto& v : step.region.vertices) box.extend(v);
    for (const auto& v : step.supports.vertices) box.extend(v);
    for (int c = 0; c < 8; ++c) s.neededFileMm.push_back(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
    s.neededFileMm.push_back(box.center());
    steps.push_back(s);
  }
  return steps;
}

ReachPoint reachScore(const std::vector<ReachStep>& steps, const Cell& at, const Eigen::Vector3d& nozzleTipMm,
                      const ReachMapOptions& options) {
  Cell cell = at;
  cell.nozzleTipMm = nozzleTipMm;
  const Eigen::Isometry3d platformToFlange = cell.flangeToPlatform.inverse();
  const double minWrist = cell.margins.minWristDegrees;
  ReachPoint point;
  point.nozzleTipMm = nozzleTipMm;
  point.leastMarginMm = std::numeric_limits<double>::infinity();
  int needed = 0, reached = 0;
  const int rotations = std::max(1, static_cast<int>(std::lround(360.0 / options.rotationStepDegrees)));
  for (const ReachStep& step : steps) {
    needed += static_cast<int>(step.neededFileMm.size());
    int bestCount = -1;
    double bestMargin = -std::numeric_limits<double>::infinity();
    for (int r = 0; r < rotations; ++r) {
      const double rotation = r * options.rotationStepDegrees * kDeg;
      std::array<int, 8> count{};
      std::array<double, 8> margin;
      margin.fill(std::numeric_limits<double>::infinity());
      for (const Eigen::Vector3d& f : step.neededFileMm) {
        const Eigen::Isometry3d flange = detail::platformPoseFor(cell, step.platformToFile, rotation, f) * platformToFlange;
        std::array<IkSolution, 8> solutions{};
        const int n = inverseKinematics(cell.arm, flange, solutions);
        for (int i = 0; i < n; ++i) {
          const IkSolution& s = solutions[static_cast<std::size_t>(i)];
          if (!nearestWithinLimits(cell.arm, &s, 1, cell.home)) continue;
          if (!detail::armOnTable(cell, s.joints).empty()) continue;
          const double reach = detail::reachMarginMm(cell.arm, s.joints);
          const double wrist = std::asin(std::min(1.0, std::abs(std::sin(s.joints[4])))) / kDeg;
          if (reach < cell.margins.minReachMm || wrist < minWrist) continue;
          ++count[static_cast<std::size_t>(s.branch)];
          margin[static_cast<std::size_t>(s.branch)] = std::min(margin[static_cast<std::size_t>(s.branch)], reach);
        }
      }
      for (int b = 0; b < 8; ++b) {
        const int c = count[static_cast<std::size_t>(b)];
        const double m = margin[static_cast<std::size_t>(b)];
        if (c > bestCount || (c == bestCount && m > bestMargin)) {
          bestCount = c;
          bestMargin = m;
        }
      }
    }
    reached += std::max(bestCount, 0);
    if (bestCount > 0) point.leastMarginMm = std::min(point.leastMarginMm, bestMargin);
  }
  point.score = needed > 0 ? static_cast<double>(reached) / needed : 0.0;
  if (!std::isfinite(point.leastMarginMm)) point.leastMarginMm = 0.0;
  return point;
}

core::Result<ReachMap> reachMap(const std::vector<ReachStep>& steps, const Cell& cell, const ReachMapOptions& options,
                                core::JobContext context) {
  const ArmModel& arm = cell.arm;
  const double reach = std::abs(arm.a[1]) + std::abs(arm.a[2]) + arm.d[4] + arm.d[5];
  const Eigen::Vector3d shoulder(0.0, 0.0, arm.d[0]);
  std::vector<Eigen::Vector3d> positions;
  const int n = static_cast<int>(std::floor(reach / options.gridMm));
  for (int iz = -n; iz <= n; ++iz)
    for (int iy = -n; iy <= n; ++iy)
      for (int ix = -n; ix <= n; ++ix) {
        const Eigen::Vector3d p = shoulder + options.gridMm * Eigen::Vector3d(ix, iy, iz);
        if ((p - shoulder).norm() > reach) continue;
        if (p.z() < cell.tableZMm + cell.platformRadiusMm + cell.margins.tableClearanceMm) continue;
        positions.push_back(p);
      }
  ReachMap map;
  map.points.resize(positions.size());
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t) {
    workers.emplace_back([&, t] {
      for (std::size_t i = t; i < positions.size(); i += threads) {
        if (context.isCancelled()) return;
        map.points[i] = reachScore(steps, cell, positions[i], options);
      }
    });
  }
  for (auto& w : workers) w.join();
  if (context.isCancelled()) return core::Error{core::ErrorCode::Cancelled, "cancelled", "reach map"};
  for (const auto& p : map.points) {
    if (p.score > map.best.score || (p.score == map.best.score && p.leastMarginMm > map.best.leastMarginMm)) map.best = p;
  }
  return map;
}

core::Status writeReachPly(const ReachMap& map, const std::filesystem::path& path) {
  std::string text = "ply\nformat ascii 1.0\ncomment MultiDir reach map: nozzle positions (mm, robot base frame) and "
                     "the share of the plan's platform poses reachable with margin\nelement vertex " +
                     std::to_string(map.points.size()) +
                     "\nproperty float x\nproperty float y\nproperty float z\nproperty float score\n"
                     "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  char line[160];
  for (const auto& p : map.points) {
    const auto colour = reachColour(p.score);
    std::snprintf(line, sizeof line, "%.1f %.1f %.1f %.4f %d %d %d\n", p.nozzleTipMm.x(), p.nozzleTipMm.y(),
                  p.nozzleTipMm.z(), p.score, colour[0], colour[1], colour[2]);
    text += line;
  }
  return core::writeTextFileAtomically(path.string(), text);
}

}  // namespace multidir::robot

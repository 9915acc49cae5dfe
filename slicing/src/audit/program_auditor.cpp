// The replay of one program and its checks (a) to (e), for auditJob.
#include "program_auditor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <tuple>

#include "gcode_replay.h"
#include "material_grid.h"
#include "swept_top.h"
#include "triangle_grid.h"

namespace multidir::slicing::audit {

namespace {

using core::Error;
using core::ErrorCode;
using core::Vec3;

constexpr double kClusterMm = 5.0;        // side of the cubes extrusion problems are grouped by
constexpr double kOutsideReportMm = 5.0;  // distances outside are measured up to this
constexpr int kLinesKept = 10;            // (d): lines named per step

std::string fixed(double value, int digits = 3) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

struct Cluster {
  double lengthMm = 0.0;
  Vec3 sum = Vec3::Zero();
  int samples = 0;
  int line = 0;
  double worstMm = 0.0;
};

struct ClusterKey {
  int step;
  int i, j, k;
  bool operator<(const ClusterKey& o) const { return std::tie(step, i, j, k) < std::tie(o.step, o.i, o.j, o.k); }
};

// One printing direction (and bead) material was laid down with, for the support check.
struct Direction {
  Vec3 d = Vec3::UnitZ();  // model frame
  double widthMm = 0.45;
  double heightMm = 0.2;
};

}  // namespace

// The replay of one program (the step programs in order, or job.gcode) and its checks.
class ProgramAuditor::Impl {
 public:
  Impl(const AuditJob& job, const AuditOptions& options, double alphaDegrees,
       const std::vector<std::unique_ptr<TriangleGrid>>& solids, ProgramAudit& out, AuditReport& report)
      : m_job(job),
        m_options(options),
        m_tanAlpha(std::tan(alphaDegrees * M_PI / 180.0)),
        m_solids(solids),
        m_out(out),
        m_report(report),
        m_material(materialCell(job, alphaDegrees)),
        m_twoAxis(job.platform == AuditPlatform::FirmwareTwoAxis),
        m_rest(auditModelToFile(job.machine, job.steps.front().angles)) {
    for (const AuditStep& s : job.steps) {
      StepAudit row;
      row.step = s.index;
      row.file = out.stitched ? out.name : s.gcodeFile;
      row.expectedGapMm = s.index == job.steps.front().index ? s.bead.firstLayerHeightMm : s.bead.layerHeightMm;
      out.steps.push_back(row);
    }
  }

  // Replays one program. `fixedPose` (step programs): the pose every move of the program prints at;
  // none (job.gcode): the pose follows the A axis as replayed.
  core::Status replay(const std::string& text, const std::string& name, std::size_t fileStep,
                      const Eigen::Isometry3d* fixedPose, MachineState& state, core::JobContext& context) {
    core::Result<Replay> replayed = replayGcode(text, name, replayAxes(), m_options.retractToleranceMm, state);
    if (!replayed) return replayed.error();
    m_lastLine = replayed->lineCount;
    std::size_t stepSlot = fileStep;
    std::size_t counter = 0;
    for (const ReplayMove& move : replayed->moves) {
      if (++counter % 4096 == 0 && context.isCancelled())
        return Error{ErrorCode::Cancelled, "the audit was cancelled", name};
      if (!fixedPose && move.step >= 1) stepSlot = slotOf(move.step, stepSlot);
      StepAudit& row = m_out.steps[stepSlot];
      if (move.retractedAtStart) {
        ++row.retractViolations;
        if (static_cast<int>(row.retractLines.size()) < kLinesKept) row.retractLines.push_back(move.line);
      }
      if (move.turns()) {
        turn(move, stepSlot, name);
        continue;
      }
      if (!move.extrudes()) continue;
      if (move.step < 1) continue;  // the start and end sequences: purge lines beside the part
      if (move.inTransition) {
        sequenceViolation(name + ": line " + std::to_string(move.line) +
                          ": an extrusion inside the transition after step " + std::to_string(move.step) +
                          " (the platform turns there: nothing may be printed)");
        continue;
      }
      const Eigen::Isometry3d pose = fixedPose ? *fixedPose : stitchedPose(move.axesFrom);
      if (!fixedPose) checkStitchedAngle(move, stepSlot, name);
      extrusion(move, stepSlot, pose);
    }
    return core::Done{};
  }

  // (e) for a Modbus platform: the turn from step slot k's pose to the next step's, the nozzle where step k's
  // program left it.
  void modbusTurn(std::size_t slot, const MachineState& state) {
    if (slot + 1 >= m_job.steps.size()) return;
    const Eigen::Isometry3d from = auditModelToFile(m_job.machine, m_job.steps[slot].angles);
    const Eigen::Isometry3d to = auditModelToFile(m_job.machine, m_job.steps[slot + 1].angles);
    // Both poses keep the pivot at the origin: to = Q from, Q a turn about a fixed axis (the geodesic).
    const Eigen::AngleAxisd q(Eigen::Matrix3d(to.linear() * from.linear().transpose()));
    std::vector<Vec3> points;
    points.reserve(m_ends.size());
    for (const Vec3& m : m_ends) points.push_back(from * m);
    const double top = sweptTop(points, q.axis(), q.angle()) + m_job.printerOffset.z();
    recordTurn(slot, state.position.z(), top, m_lastLine);
  }

  void finish() {
    StepAudit& total = m_out.total;
    total.step = 0;
    total.file = m_out.stitched ? m_out.name : "all files";
    total.turnClearanceMm = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t k = 0; k < m_out.steps.size(); ++k) {
      StepAudit& row = m_out.steps[k];
      std::sort(row.unsupportedLines.begin(), row.unsupportedLines.end());
      row.unsupportedLines.erase(std::unique(row.unsupportedLines.begin(), row.unsupportedLines.end()),
                                 row.unsupportedLines.end());
      if (m_lowest[k] < std::numeric_limits<double>::infinity()) {
        row.firstLayerGapMm = m_lowest[k] - row.baseZMm;
        row.firstLayerViolation = std::abs(row.firstLayerGapMm - row.expectedGapMm) > m_options.firstLayerToleranceMm;
      }
      total.extrusionMm += row.extrusionMm;
      total.skirtMm += row.skirtMm;
      total.outsideMm += row.outsideMm;
      total.worstOutsideMm = std::max(total.worstOutsideMm, row.worstOutsideMm);
      total.unsupportedMm += row.unsupportedMm;
      for (const auto& [feature, mm] : row.unsupportedByFeatureMm) total.unsupportedByFeatureMm[feature] += mm;
      total.retractViolations += row.retractViolations;
      for (int line : row.retractLines)
        if (static_cast<int>(total.retractLines.size()) < kLinesKept) total.retractLines.push_back(line);
      total.firstLayerViolation = total.firstLayerViolation || row.firstLayerViolation;
      total.turnViolation = total.turnViolation || row.turnViolation;
      if (!std::isnan(row.turnClearanceMm) &&
          (std::isnan(total.turnClearanceMm) || row.turnClearanceMm < total.turnClearanceMm)) {
        total.turnClearanceMm = row.turnClearanceMm;
        total.turnNozzleZMm = row.turnNozzleZMm;
        total.turnSweptTopZMm = row.turnSweptTopZMm;
        total.turnLine = row.turnLine;
      }
      if (!std::isnan(row.firstLayerGapMm) &&
          (std::isnan(total.firstLayerGapMm) ||
           std::abs(row.firstLayerGapMm - row.expectedGapMm) > std::abs(total.firstLayerGapMm - total.expectedGapMm))) {
        total.firstLayerGapMm = row.firstLayerGapMm;
        total.expectedGapMm = row.expectedGapMm;
      }
    }
    m_out.outsidePlaces = worst(m_outside);
    m_out.unsupportedPlaces = worst(m_unsupported);
  }

 private:
  static double materialCell(const AuditJob& job, double alphaDegrees) {
    double reach = 0.5;
    for (const AuditStep& s : job.steps) {
      const double h = std::max(s.bead.layerHeightMm, s.bead.firstLayerHeightMm);
      const double along = 1.5 * h + 0.5 * s.bead.widthMm + h;
      const double side = 0.5 * s.bead.widthMm + h * std::tan(alphaDegrees * M_PI / 180.0);
      reach = std::max(reach, std::hypot(along, side));
    }
    return reach;
  }

  std::size_t slotOf(int stepIndex, std::size_t fallback) const {
    for (std::size_t k = 0; k < m_job.steps.size(); ++k)
      if (m_job.steps[k].index == stepIndex) return k;
    return fallback;
  }

  // The axes the replay follows: the tilt and rotation axes (letters and Klipper steppers), or the one
  // firmware axis by its letter (any manual_stepper).
  std::vector<ReplayAxis> replayAxes() const {
    if (m_twoAxis)
      return {{m_job.twoAxes.tilt.letter.empty() ? 'U' : m_job.twoAxes.tilt.letter[0], m_job.twoAxes.tilt.stepper},
              {m_job.twoAxes.rotation.letter.empty() ? 'V' : m_job.twoAxes.rotation.letter[0],
               m_job.twoAxes.rotation.stepper}};
    return {{m_job.rotaryAxis.empty() ? 'A' : m_job.rotaryAxis[0], std::string()}};
  }

  // job.gcode: the pose the axes hold as replayed.
  Eigen::Isometry3d stitchedPose(const std::array<double, kMaxRotaryAxes>& axes) {
    return m_twoAxis ? twoAxisPose(axes) : firmwarePose(axes[0]);
  }

  const Eigen::Isometry3d& twoAxisPose(const std::array<double, kMaxRotaryAxes>& axes) {
    const auto found = m_twoAxisPoses.find(axes);
    if (found != m_twoAxisPoses.end()) return found->second;
    return m_twoAxisPoses.emplace(axes, twoAxisModelToFile(m_job.twoAxes, m_rest, {axes[0], axes[1]})).first->second;
  }

  const Eigen::Isometry3d& firmwarePose(double aDegrees) {
    const auto found = m_firmwarePoses.find(aDegrees);
    if (found != m_firmwarePoses.end()) return found->second;
    return m_firmwarePoses.emplace(aDegrees, firmwareAxisModelToFile(m_job.machine, aDegrees)).first->second;
  }

  double axisSign() const {
    const Eigen::Isometry3d rest = firmwareAxisModelToFile(m_job.machine, 0.0);
    return (rest.linear() * m_job.machine.rotationAxis).x() < 0.0 ? -1.0 : 1.0;
  }

  void sequenceViolation(const std::string& what) {
    ++m_report.sequenceViolations;
    m_report.findings.push_back(what);
  }

  // job.gcode: a step printed at another A than its plan's angle (rotaryDegrees, negated when r maps to -X in
  // the files' frame) is printed in another pose than its mesh was sliced in.
  void checkStitchedAngle(const ReplayMove& move, std::size_t slot, const std::string& name) {
    if (m_angleChecked.count(slot)) return;
    m_angleChecked[slot] = true;
    if (m_twoAxis) {
      checkStitchedCoordinates(move, slot, name);
      return;
    }
    const double expected = axisSign() * m_job.steps[slot].angles.rotaryDegrees;
    if (std::abs(move.axesFrom[0] - expected) > 1e-3) {
      ++m_report.poseMismatches;
      m_report.findings.push_back(name + ": line " + std::to_string(move.line) + ": step " +
                                  std::to_string(m_job.steps[slot].index) + " prints at A " + fixed(move.axesFrom[0]) +
                                  " degrees, but its plan angle gives A " + fixed(expected) +
                                  " (print-job.json angles.rotaryDegrees)");
    }
  }

  // job.gcode on two axes: a step printed at other coordinates than print-job.json's axisDegrees for it.
  void checkStitchedCoordinates(const ReplayMove& move, std::size_t slot, const std::string& name) {
    const AuditStep& step = m_job.steps[slot];
    if (!step.axisDegrees) return;  // the reader requires them for a firmware-2axis job
    const std::array<std::pair<const AuditRotaryAxis*, double>, kMaxRotaryAxes> expected = {
        std::pair{&m_job.twoAxes.tilt, step.axisDegrees->tiltDegrees},
        std::pair{&m_job.twoAxes.rotation, step.axisDegrees->rotationDegrees}};
    for (std::size_t k = 0; k < kMaxRotaryAxes; ++k) {
      if (std::abs(move.axesFrom[k] - expected[k].second) <= 1e-3) continue;
      ++m_report.poseMismatches;
      m_report.findings.push_back(name + ": line " + std::to_string(move.line) + ": step " +
                                  std::to_string(step.index) + " prints at " + expected[k].first->letter + " " +
                                  fixed(move.axesFrom[k]) + " degrees, but print-job.json gives " +
                                  expected[k].first->letter + " " + fixed(expected[k].second) +
                                  " (slicing.steps[].axisDegrees): the step was sliced in another pose");
    }
  }

  std::uint16_t directionIndex(const Vec3& d, double width, double height) {
    for (std::size_t i = 0; i < m_directions.size(); ++i)
      if ((m_directions[i].d - d).norm() < 1e-9 && m_directions[i].widthMm == width &&
          m_directions[i].heightMm == height)
        return static_cast<std::uint16_t>(i);
    m_directions.push_back({d, width, height});
    return static_cast<std::uint16_t>(m_directions.size() - 1);
  }

  void extrusion(const ReplayMove& move, std::size_t slot, const Eigen::Isometry3d& pose) {
    const AuditStep& step = m_job.steps[slot];
    StepAudit& row = m_out.steps[slot];
    const Eigen::Isometry3d toModel = pose.inverse();
    const Vec3 d = toModel.linear() * Vec3::UnitZ();
    if (!m_baseKnown[slot]) {
      // (c): the base plane's printer z under the pose the step is really printed at.
      double low = std::numeric_limits<double>::infinity();
      for (const Vec3& v : step.region.vertices) low = std::min(low, (pose * v).z());
      row.baseZMm = low + m_job.printerOffset.z();
      m_baseKnown[slot] = true;
    }
    m_lowest[slot] = std::min(m_lowest[slot], std::min(move.from.z(), move.to.z()));

    const double length = (move.to - move.from).norm();
    row.extrusionMm += length;
    if (move.skirt) row.skirtMm += length;
    const BeadGeometry& bead = step.bead;
    const double w = bead.widthMm;
    const bool firstLayer = move.to.z() - row.baseZMm <= bead.firstLayerHeightMm + 0.5 * bead.layerHeightMm;
    const double h = firstLayer ? bead.firstLayerHeightMm : bead.layerHeightMm;
    const std::uint16_t dirIndex = directionIndex(d, w, h);
    const int n = std::max(1, static_cast<int>(std::ceil(length / (0.5 * w))));
    const double piece = length / n;
    const TriangleGrid& solid = *m_solids[slot];
    const double lateral = 0.5 * w + h * m_tanAlpha;
    const double radius = m_material.size() ? materialRadius(w, h) : 0.0;
    const Vec3 up = m_job.machine.up;
    const double upAlongD = up.dot(d);

    std::vector<Vec3> samples;
    samples.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const Vec3 printer = move.from + (i + 0.5) / n * (move.to - move.from);
      const Vec3 m = toModel * (printer - m_job.printerOffset);
      samples.push_back(m);
      // (a) inside the region or its supports, or within w/2 of their surface.
      if (!move.skirt && !(solid.distanceWithin(m, 0.5 * w) < std::numeric_limits<double>::infinity()) &&
          solid.winding(m) <= 0) {
        const double distance = std::min(solid.distanceWithin(m, kOutsideReportMm), kOutsideReportMm);
        row.outsideMm += piece;
        row.worstOutsideMm = std::max(row.worstOutsideMm, distance);
        add(m_outside, step.index, m, piece, move.line, distance);
      }
      // (b) resting on the platform or on material printed before, within the printable angle.
      const Vec3 bottom = m - h * d;
      const double aboveThePlatform = up.dot(bottom - m_job.machine.pivot);
      bool supported = upAlongD > 1e-6 && std::abs(aboveThePlatform) <= 0.5 * h;
      if (!supported) {
        const double bottomAlongD = m.dot(d) - h;
        supported = m_material.any(m, radius, [&](const BeadSample& s) {
          const Direction& below = m_directions[s.direction];
          const Vec3 q = s.point.cast<double>();
          const double c = d.dot(below.d);
          // The lower bead's highest point along d: its centre, half its height along its own direction and
          // half its width sideways (bounded by the sine of the angle between the directions).
          const double top = q.dot(d) - 0.5 * below.heightMm * c + 0.5 * below.heightMm * std::abs(c) +
                             0.5 * below.widthMm * std::sqrt(std::max(0.0, 1.0 - c * c));
          const double gap = bottomAlongD - top;
          if (gap <= -0.5 * h || gap > 0.5 * h) return false;
          const Vec3 v = m - q;
          return (v - v.dot(d) * d).norm() <= lateral;
        });
      }
      if (!supported) {
        if (row.unsupportedLines.empty() || row.unsupportedLines.back() != move.line)
          row.unsupportedLines.push_back(move.line);
        row.unsupportedMm += piece;
        row.unsupportedByFeatureMm[move.feature.empty() ? "unlabelled" : move.feature] += piece;
        add(m_unsupported, step.index, m, piece, move.line, 0.0);
      }
    }
    for (const Vec3& m : samples) m_material.add({m.cast<float>(), dirIndex});
    m_ends.push_back(toModel * (move.from - m_job.printerOffset));
    m_ends.push_back(toModel * (move.to - m_job.printerOffset));
  }

  double materialRadius(double w, double h) const {
    double widest = w, tallest = h;
    for (const Direction& dir : m_directions) {
      widest = std::max(widest, dir.widthMm);
      tallest = std::max(tallest, dir.heightMm);
    }
    return std::hypot(1.5 * h + 0.5 * widest + tallest, 0.5 * w + h * m_tanAlpha);
  }

  // (e) job.gcode: the material turned over the arc about the files' X axis while the nozzle waits.
  void turn(const ReplayMove& move, std::size_t slot, const std::string& name) {
    if (!move.inTransition)
      sequenceViolation(name + ": line " + std::to_string(move.line) +
                        ": the platform turns outside a transition section");
    if (move.movesXy() || std::abs(move.to.z() - move.from.z()) > 1e-9)
      sequenceViolation(name + ": line " + std::to_string(move.line) +
                        ": the platform turns in a move that also moves the nozzle");
    if (m_twoAxis) {
      twoAxisTurn(move, slot, name);
      return;
    }
    const Eigen::Isometry3d& from = firmwarePose(move.axesFrom[0]);
    std::vector<Vec3> points;
    points.reserve(m_ends.size());
    for (const Vec3& m : m_ends) points.push_back(from * m);
    const double radians = -(move.axesTo[0] - move.axesFrom[0]) * M_PI / 180.0;
    const double top = sweptTop(points, Vec3::UnitX(), radians) + m_job.printerOffset.z();
    recordTurn(slot, std::min(move.from.z(), move.to.z()), top, move.line);
  }

  // (e) job.gcode on two axes: each axis' move swept exactly about its line (the tilt axis, fixed; the rotation
  // axis, the platform's normal through the rotation centre as the tilt holds it). A move turning both axes at
  // once has no such arc: it is a sequence violation, and its clearance is the worse of the two orders.
  void twoAxisTurn(const ReplayMove& move, std::size_t slot, const std::string& name) {
    checkLimits(move, name);
    const double nozzleZ = std::min(move.from.z(), move.to.z());
    if (move.turns(0) && move.turns(1)) {
      sequenceViolation(name + ": line " + std::to_string(move.line) + ": " + m_job.twoAxes.tilt.letter + " and " +
                        m_job.twoAxes.rotation.letter +
                        " turn in one move: their path is the firmware's blend, not an arc about either axis");
      double top = -std::numeric_limits<double>::infinity();
      for (std::size_t first : {std::size_t{0}, std::size_t{1}}) {
        std::array<double, kMaxRotaryAxes> middle = move.axesFrom;
        middle[first] = move.axesTo[first];
        top = std::max({top, singleAxisSweptTop(move.axesFrom, first, move.axesTo[first]),
                        singleAxisSweptTop(middle, 1 - first, move.axesTo[1 - first])});
      }
      recordTurn(slot, nozzleZ, top + m_job.printerOffset.z(), move.line);
      return;
    }
    const std::size_t axis = move.turns(0) ? 0 : 1;
    const double top = singleAxisSweptTop(move.axesFrom, axis, move.axesTo[axis]);
    recordTurn(slot, nozzleZ, top + m_job.printerOffset.z(), move.line);
  }

  // The highest z (files' frame) of the material so far while axis `axis` turns from `from` to `toDegrees`.
  double singleAxisSweptTop(const std::array<double, kMaxRotaryAxes>& from, std::size_t axis, double toDegrees) {
    const Eigen::Isometry3d pose = twoAxisPose(from);
    const AuditAxisLines lines = auditAxisLines(m_job.twoAxes);
    Vec3 through = lines.tiltPoint;
    Vec3 direction = lines.tiltDirection;
    double radians = 0.0;
    if (axis == 0) {
      const AuditRotaryAxis& tilt = m_job.twoAxes.tilt;
      radians = -(tilt.conventionRadians(toDegrees) - tilt.conventionRadians(from[0]));
    } else {
      // The rotation axis as the tilt holds it: the rest normal and centre turned by -t about the tilt line.
      const AuditRotaryAxis& rotation = m_job.twoAxes.rotation;
      const Eigen::AngleAxisd tilt(-m_job.twoAxes.tilt.conventionRadians(from[0]), lines.tiltDirection);
      direction = tilt * Vec3::UnitZ();
      through = lines.tiltPoint + tilt * (lines.rotationPoint - lines.tiltPoint);
      radians = rotation.conventionRadians(toDegrees) - rotation.conventionRadians(from[1]);
    }
    std::vector<Vec3> points;
    points.reserve(m_ends.size());
    for (const Vec3& m : m_ends) points.push_back(pose * m - through);
    return sweptTop(points, direction, radians) + through.z();
  }

  // job.gcode on two axes: a coordinate beyond an axis' limits is one the firmware refuses or crashes into.
  void checkLimits(const ReplayMove& move, const std::string& name) {
    const std::array<const AuditRotaryAxis*, kMaxRotaryAxes> axes = {&m_job.twoAxes.tilt, &m_job.twoAxes.rotation};
    for (std::size_t k = 0; k < kMaxRotaryAxes; ++k) {
      const AuditRotaryAxis& a = *axes[k];
      if (!move.turns(k) || (move.axesTo[k] >= a.minDegrees - 1e-9 && move.axesTo[k] <= a.maxDegrees + 1e-9)) continue;
      ++m_report.poseMismatches;
      m_report.findings.push_back(name + ": line " + std::to_string(move.line) + ": " + a.letter + " " +
                                  fixed(move.axesTo[k]) + " degrees is outside the axis' limits " +
                                  fixed(a.minDegrees) + " to " + fixed(a.maxDegrees) +
                                  " (print-job.json slicing.printer.axes)");
    }
  }

  void recordTurn(std::size_t slot, double nozzleZ, double sweptTopZ, int line) {
    StepAudit& row = m_out.steps[slot];
    const double clearance = m_ends.empty() ? std::numeric_limits<double>::infinity() : nozzleZ - sweptTopZ;
    if (!std::isnan(row.turnClearanceMm) && row.turnClearanceMm <= clearance) return;
    row.turnClearanceMm = clearance;
    row.turnNozzleZMm = nozzleZ;
    row.turnSweptTopZMm = sweptTopZ;
    row.turnLine = line;
    row.turnViolation = clearance < 0.0;
  }

  static void add(std::map<ClusterKey, Cluster>& clusters, int step, const Vec3& m, double length, int line,
                  double distance) {
    const ClusterKey key{step, static_cast<int>(std::floor(m.x() / kClusterMm)),
                         static_cast<int>(std::floor(m.y() / kClusterMm)),
                         static_cast<int>(std::floor(m.z() / kClusterMm))};
    Cluster& c = clusters[key];
    if (c.samples == 0) c.line = line;
    c.lengthMm += length;
    c.sum += m;
    ++c.samples;
    c.worstMm = std::max(c.worstMm, distance);
  }

  std::vector<AuditPlace> worst(const std::map<ClusterKey, Cluster>& clusters) const {
    std::vector<AuditPlace> places;
    for (const auto& [key, c] : clusters) {
      AuditPlace p;
      p.step = key.step;
      p.file = m_out.stitched ? m_out.name : m_job.steps[slotOf(key.step, 0)].gcodeFile;
      p.line = c.line;
      p.modelPoint = c.sum / c.samples;
      p.lengthMm = c.lengthMm;
      p.worstMm = c.worstMm;
      places.push_back(p);
    }
    std::sort(places.begin(), places.end(),
              [](const AuditPlace& a, const AuditPlace& b) { return a.lengthMm > b.lengthMm; });
    if (places.size() > static_cast<std::size_t>(std::max(0, m_options.worstClusters)))
      places.resize(static_cast<std::size_t>(std::max(0, m_options.worstClusters)));
    return places;
  }

  const AuditJob& m_job;
  const AuditOptions& m_options;
  double m_tanAlpha;
  const std::vector<std::unique_ptr<TriangleGrid>>& m_solids;
  ProgramAudit& m_out;
  AuditReport& m_report;
  MaterialGrid m_material;
  std::vector<Direction> m_directions;
  std::vector<Vec3> m_ends;  // extrusion end points, model frame: what a turn sweeps
  bool m_twoAxis;             // firmware-2axis: the pose follows both axes
  Eigen::Isometry3d m_rest;   // the first step's pose from its plan angles: both axes at zero
  std::map<double, Eigen::Isometry3d> m_firmwarePoses;
  std::map<std::array<double, kMaxRotaryAxes>, Eigen::Isometry3d> m_twoAxisPoses;
  std::map<std::size_t, bool> m_angleChecked;
  std::map<ClusterKey, Cluster> m_outside, m_unsupported;
  std::vector<double> m_lowest = std::vector<double>(m_job.steps.size(), std::numeric_limits<double>::infinity());
  std::vector<bool> m_baseKnown = std::vector<bool>(m_job.steps.size(), false);
  int m_lastLine = 0;
};

ProgramAuditor::ProgramAuditor(const AuditJob& job, const AuditOptions& options, double alphaDegrees,
                               const std::vector<std::unique_ptr<TriangleGrid>>& solids, ProgramAudit& out,
                               AuditReport& report)
    : m_impl(std::make_unique<Impl>(job, options, alphaDegrees, solids, out, report)) {}

ProgramAuditor::~ProgramAuditor() = default;

core::Status ProgramAuditor::replay(const std::string& text, const std::string& name, std::size_t fileStep,
                                    const Eigen::Isometry3d* fixedPose, MachineState& state,
                                    core::JobContext& context) {
  return m_impl->replay(text, name, fileStep, fixedPose, state, context);
}

void ProgramAuditor::modbusTurn(std::size_t slot, const MachineState& state) { m_impl->modbusTurn(slot, state); }

void ProgramAuditor::finish() { m_impl->finish(); }

}  // namespace multidir::slicing::audit

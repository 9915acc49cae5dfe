#include "multidir/slicing/two_axis_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "multidir/core/common/units.h"
#include "multidir/slicing/clearance.h"

namespace multidir::slicing {

namespace {

using core::Vec3;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The disc is bounded by a prism of this many sides around it (a polygon circumscribed about the circle
// contains the disc whatever the rotation, and a convex body's highest point over a turn is a corner's).
constexpr int kDiscSides = 64;
// Two swept tops this close are the same: the fewer moves win.
constexpr double kTieMm = 1e-6;

// The highest z of `points` turned about the line through `through` along `direction` by every angle between 0
// and `radians` (clearance.h's exact arc maximum, about a line that need not pass through the origin).
double sweptAbout(const std::vector<Vec3>& points, const Vec3& through, const Vec3& direction, double radians) {
  if (points.empty()) return -kInfinity;
  std::vector<Vec3> local;
  local.reserve(points.size());
  for (const Vec3& p : points) local.push_back(p - through);
  return sweptTopZ(local, direction.normalized(), radians) + through.z();
}

double highest(const std::vector<Vec3>& points, const Eigen::Isometry3d& motion) {
  double top = -kInfinity;
  for (const Vec3& p : points) top = std::max(top, (motion * p).z());
  return top;
}

Eigen::Isometry3d turnAbout(const Vec3& through, const Vec3& direction, double radians) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(through);
  t.rotate(Eigen::AngleAxisd(radians, direction.normalized()));
  t.translate(-through);
  return t;
}

}  // namespace

TwoAxisMachine::TwoAxisMachine(const PrinterProfile& profile, double planPlatformRadiusMm)
    : m_axes(profile.twoAxis) {
  const Vec3 printerOrigin(profile.platformCenter.x(), profile.platformCenter.y(), profile.platformZMm);
  const Eigen::Vector2d centre = m_axes.rotationCenter - profile.platformCenter;
  m_rotationPoint = Vec3(centre.x(), centre.y(), 0.0);
  const double tiltZ = m_axes.tiltHeightMm - profile.platformZMm;
  m_tiltDirection = m_axes.tiltAlong == TiltAlong::X ? Vec3::UnitX() : Vec3::UnitY();
  m_tiltPoint = Vec3(centre.x(), centre.y(), tiltZ);

  m_radiusMm = m_axes.platformRadiusMm > 0.0 ? m_axes.platformRadiusMm : std::max(0.0, planPlatformRadiusMm);
  if (m_radiusMm > 0.0) {
    const double corner = m_radiusMm / std::cos(M_PI / kDiscSides);
    for (int i = 0; i < kDiscSides; ++i) {
      const double a = 2.0 * M_PI * i / kDiscSides;
      const Vec3 rim = m_rotationPoint + corner * Vec3(std::cos(a), std::sin(a), 0.0);
      m_disc.push_back(rim);
      m_disc.push_back(rim - Vec3(0.0, 0.0, m_axes.platformThicknessMm));
    }
  }
  if (m_axes.cradle) {
    const Eigen::AlignedBox3d& box = *m_axes.cradle;
    for (int i = 0; i < 8; ++i)
      m_cradle.push_back(Vec3(i & 1 ? box.max().x() : box.min().x(), i & 2 ? box.max().y() : box.min().y(),
                              i & 4 ? box.max().z() : box.min().z()) -
                         printerOrigin);
  }
}

double TwoAxisMachine::tiltRadians(double tiltDegrees) const {
  return core::degToRad((tiltDegrees - m_axes.tilt.zeroDegrees) / m_axes.tilt.direction);
}

double TwoAxisMachine::rotationRadians(double rotationDegrees) const {
  return core::degToRad((rotationDegrees - m_axes.rotation.zeroDegrees) / m_axes.rotation.direction);
}

Eigen::Isometry3d TwoAxisMachine::tiltPose(double tiltDegrees) const {
  // The one-axis convention: a positive tilt turns the cradle by minus the angle about the axis' direction.
  return turnAbout(m_tiltPoint, m_tiltDirection, -tiltRadians(tiltDegrees));
}

Eigen::Isometry3d TwoAxisMachine::pose(const TwoAxisAngles& at) const {
  return tiltPose(at.tiltDegrees) * turnAbout(m_rotationPoint, Vec3::UnitZ(), rotationRadians(at.rotationDegrees));
}

core::Result<std::vector<TwoAxisAngles>> TwoAxisMachine::stepAngles(const core::PrintJob& job) const {
  std::vector<TwoAxisAngles> angles;
  TwoAxisAngles previous = restAngles(m_axes);
  if (job.steps.empty()) return angles;
  const Eigen::Matrix3d rest = job.steps.front().modelToFile.linear();
  for (const core::PrintJobStep& step : job.steps) {
    core::Result<TwoAxisAngles> at = twoAxisAngles(rest * step.printingDirection, m_axes, previous, step.index);
    if (!at) return at.error();
    angles.push_back(*at);
    previous = *at;
  }
  return angles;
}

core::PrintJob TwoAxisMachine::posed(const core::PrintJob& job, const std::vector<TwoAxisAngles>& angles) const {
  core::PrintJob out = job;
  if (job.steps.empty()) return out;
  const Eigen::Isometry3d rest = job.steps.front().modelToFile;
  for (std::size_t k = 0; k < out.steps.size() && k < angles.size(); ++k) {
    core::PrintJobStep& step = out.steps[k];
    const Eigen::Isometry3d modelToFile = pose(angles[k]) * rest;
    const Eigen::Isometry3d move = modelToFile * step.modelToFile.inverse();
    step.modelToFile = modelToFile;
    double lowest = kInfinity;
    for (core::TriangleMesh* mesh : {&step.region, &step.supports})
      for (Vec3& v : mesh->vertices) v = move * v;
    for (const Vec3& v : step.region.vertices) lowest = std::min(lowest, v.z());
    if (std::isfinite(lowest)) step.lowestHeightMm = lowest;
  }
  return out;
}

double TwoAxisMachine::bodyTopZ(const TwoAxisAngles& at) const {
  // The disc itself (not its bounding prism): a circle of radius R about centre c in a plane of normal n
  // reaches c.z + R sqrt(1 - n.z^2); its top and bottom faces bound it.
  const Eigen::Isometry3d p = pose(at);
  const Vec3 normal = p.linear() * Vec3::UnitZ();
  const double rise = m_radiusMm * std::sqrt(std::max(0.0, 1.0 - normal.z() * normal.z()));
  double top = -kInfinity;
  if (m_radiusMm > 0.0)
    for (const Vec3& centre : {m_rotationPoint, Vec3(m_rotationPoint - m_axes.platformThicknessMm * Vec3::UnitZ())})
      top = std::max(top, (p * centre).z() + rise);
  return std::max(top, highest(m_cradle, tiltPose(at.tiltDegrees)));
}

double TwoAxisMachine::sweptTop(const std::vector<Vec3>& part, const TwoAxisAngles& from,
                                const std::vector<AxisMove>& moves) const {
  std::vector<Vec3> moving = part;
  moving.insert(moving.end(), m_disc.begin(), m_disc.end());
  TwoAxisAngles at = from;
  double top = std::max(highest(moving, pose(at)), highest(m_cradle, tiltPose(at.tiltDegrees)));
  for (const AxisMove& move : moves) {
    std::vector<Vec3> posed;
    posed.reserve(moving.size());
    const Eigen::Isometry3d now = pose(at);
    for (const Vec3& p : moving) posed.push_back(now * p);
    if (move.axis == AxisMove::Axis::Tilt) {
      const double radians = -(tiltRadians(move.toDegrees) - tiltRadians(move.fromDegrees));
      top = std::max(top, sweptAbout(posed, m_tiltPoint, m_tiltDirection, radians));
      std::vector<Vec3> cradle;
      const Eigen::Isometry3d cradlePose = tiltPose(at.tiltDegrees);
      for (const Vec3& c : m_cradle) cradle.push_back(cradlePose * c);
      top = std::max(top, sweptAbout(cradle, m_tiltPoint, m_tiltDirection, radians));
      at.tiltDegrees = move.toDegrees;
    } else {
      // The rotation axis is the platform's normal through its centre, tilted with the cradle.
      const Eigen::Isometry3d cradlePose = tiltPose(at.tiltDegrees);
      const double radians = rotationRadians(move.toDegrees) - rotationRadians(move.fromDegrees);
      top = std::max(top, sweptAbout(posed, cradlePose * m_rotationPoint, cradlePose.linear() * Vec3::UnitZ(), radians));
      at.rotationDegrees = move.toDegrees;
    }
  }
  return top;
}

TwoAxisTurn TwoAxisMachine::planTurn(const std::vector<Vec3>& printed, const TwoAxisAngles& from,
                                     const TwoAxisAngles& to) const {
  const auto tilt = [](double a, double b) { return AxisMove{AxisMove::Axis::Tilt, a, b}; };
  const auto rotation = [](double a, double b) { return AxisMove{AxisMove::Axis::Rotation, a, b}; };
  const bool tilts = std::abs(to.tiltDegrees - from.tiltDegrees) > 1e-9;
  const bool rotates = std::abs(to.rotationDegrees - from.rotationDegrees) > 1e-9;
  std::vector<std::vector<AxisMove>> paths;
  if (!tilts && !rotates) {
    paths.push_back({});
  } else if (!rotates) {
    paths.push_back({tilt(from.tiltDegrees, to.tiltDegrees)});
  } else if (!tilts) {
    paths.push_back({rotation(from.rotationDegrees, to.rotationDegrees)});
  } else {
    paths.push_back({rotation(from.rotationDegrees, to.rotationDegrees), tilt(from.tiltDegrees, to.tiltDegrees)});
    paths.push_back({tilt(from.tiltDegrees, to.tiltDegrees), rotation(from.rotationDegrees, to.rotationDegrees)});
  }
  // Through level: the rotation then turns a platform lying flat, which sweeps nothing upwards.
  const double level = m_axes.tilt.zeroDegrees;
  if (rotates && std::abs(from.tiltDegrees - level) > 1e-9 && std::abs(to.tiltDegrees - level) > 1e-9)
    paths.push_back({tilt(from.tiltDegrees, level), rotation(from.rotationDegrees, to.rotationDegrees),
                     tilt(level, to.tiltDegrees)});

  TwoAxisTurn best;
  best.from = from;
  best.to = to;
  best.sweptTopZ = kInfinity;
  for (const std::vector<AxisMove>& path : paths) {
    const double top = sweptTop(printed, from, path);
    if (top < best.sweptTopZ - kTieMm) {
      best.moves = path;
      best.sweptTopZ = top;
    }
  }
  return best;
}

}  // namespace multidir::slicing

#include "sim/two_axis_kinematics.h"

#include <cmath>

namespace multidir::hardware::sim {

namespace {

constexpr double kRadiansPerDegree = M_PI / 180.0;

}  // namespace

Eigen::Isometry3d twoAxisPlatformPose(const TwoAxisMachine& machine, double tiltCoordinate, double rotationCoordinate) {
  const double t = (tiltCoordinate - machine.tiltZeroDegrees) / machine.tiltDirection * kRadiansPerDegree;
  const double r = (rotationCoordinate - machine.rotationZeroDegrees) / machine.rotationDirection * kRadiansPerDegree;
  const Eigen::Vector3d centre(machine.rotationCenterMm.x(), machine.rotationCenterMm.y(), 0.0);
  const Eigen::Vector3d tiltPivot(machine.rotationCenterMm.x(), machine.rotationCenterMm.y(), machine.tiltHeightMm);
  const Eigen::Vector3d tiltAxis = machine.tiltAlongX ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  // Each turn about a line through a point c: p -> c + R (p - c).
  const Eigen::Isometry3d rotation =
      Eigen::Translation3d(centre) * Eigen::AngleAxisd(r, Eigen::Vector3d::UnitZ()) * Eigen::Translation3d(-centre);
  const Eigen::Isometry3d tilt =
      Eigen::Translation3d(tiltPivot) * Eigen::AngleAxisd(-t, tiltAxis) * Eigen::Translation3d(-tiltPivot);
  return tilt * rotation;
}

}  // namespace multidir::hardware::sim

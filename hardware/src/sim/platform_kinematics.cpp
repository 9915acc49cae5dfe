#include "sim/platform_kinematics.h"

#include <algorithm>
#include <cmath>

namespace multidir::hardware::sim {

namespace {

constexpr double kRadiansPerDegree = M_PI / 180.0;

}  // namespace

Eigen::Matrix3d urscriptTargetOrientation(double tiltDegrees, double azimuthDegrees) {
  const double t = tiltDegrees * kRadiansPerDegree;
  const double a = azimuthDegrees * kRadiansPerDegree;
  const Eigen::Vector3d rotationVector(t * std::sin(a), -t * std::cos(a), 0.0);
  const double angle = rotationVector.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, rotationVector / angle).toRotationMatrix();
}

ReportedTilt urscriptReportedTilt(const Eigen::Matrix3d& orientation) {
  const Eigen::Vector3d up = orientation.transpose() * Eigen::Vector3d::UnitZ();
  ReportedTilt reported;
  reported.tiltDegrees = std::acos(std::clamp(up.z(), -1.0, 1.0)) / kRadiansPerDegree;
  if (reported.tiltDegrees > 0.01) reported.azimuthDegrees = std::atan2(up.y(), up.x()) / kRadiansPerDegree;
  return reported;
}

double angleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

Eigen::Matrix3d turnedTowards(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to, double maxRadians) {
  const Eigen::Quaterniond q0(from);
  const Eigen::Quaterniond q1(to);
  const double remaining = q0.angularDistance(q1);
  if (remaining <= maxRadians) return to;
  return q0.slerp(maxRadians / remaining, q1).normalized().toRotationMatrix();
}

Eigen::Matrix3d rotaryShaftOrientation(double angleDegrees, const Eigen::Vector3d& shaftAxis) {
  return Eigen::AngleAxisd(-angleDegrees * kRadiansPerDegree, shaftAxis.normalized()).toRotationMatrix();
}

}  // namespace multidir::hardware::sim

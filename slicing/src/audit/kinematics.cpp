// The audit's own kinematics, written from the convention in docs/slicing.md ("Audit"), not from
// core::machinePose: the audit is only worth something if it does not share the code it checks.
#include <cmath>

#include "multidir/slicing/audit.h"

namespace multidir::slicing {

namespace {

using core::Vec3;

double radians(double degrees) { return degrees * M_PI / 180.0; }

// Columns x, y, z of the platform frame in model coordinates: z = up, x = the model's x made perpendicular to
// up (y when up is along x), y = up x x.
Eigen::Matrix3d platformFrame(const Vec3& upIn) {
  const Vec3 up = upIn.normalized();
  Vec3 x = Vec3::UnitX() - up.x() * up;
  if (x.norm() < 1e-6) x = Vec3::UnitY() - up.y() * up;
  x.normalize();
  Eigen::Matrix3d frame;
  frame.col(0) = x;
  frame.col(1) = up.cross(x);
  frame.col(2) = up;
  return frame;
}

// The rest pose: model to files' frame with the platform frame's axes as +X, +Y, +Z and the pivot at 0.
Eigen::Isometry3d restPose(const AuditMachine& machine) {
  const Eigen::Matrix3d toFrame = platformFrame(machine.up).transpose();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = toFrame;
  pose.translation() = -(toFrame * machine.pivot);
  return pose;
}

// A turn by `radiansAbout` about `axis` (model frame) through the pivot, then the rest pose.
Eigen::Isometry3d turnedAboutPivot(const AuditMachine& machine, const Vec3& axis, double radiansAbout) {
  Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
  turn.linear() = Eigen::AngleAxisd(radiansAbout, axis.normalized()).toRotationMatrix();
  turn.translation() = machine.pivot - turn.linear() * machine.pivot;
  return restPose(machine) * turn;
}

}  // namespace

Eigen::Isometry3d auditModelToFile(const AuditMachine& machine, const core::MachineAngles& angles) {
  switch (machine.kind) {
    case core::MachineKind::ThreeAxis:
      return restPose(machine);
    case core::MachineKind::RotaryPlatform:
      return turnedAboutPivot(machine, machine.rotationAxis, -radians(angles.rotaryDegrees));
    case core::MachineKind::TiltRotate:
    case core::MachineKind::Apart: {
      const double a = radians(angles.azimuthDegrees);
      const Vec3 axisInFrame(std::sin(a), -std::cos(a), 0.0);
      return turnedAboutPivot(machine, platformFrame(machine.up) * axisInFrame, radians(angles.tiltDegrees));
    }
  }
  return restPose(machine);
}

Eigen::Isometry3d firmwareAxisModelToFile(const AuditMachine& machine, double aDegrees) {
  Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
  turn.linear() = Eigen::AngleAxisd(-radians(aDegrees), Vec3::UnitX()).toRotationMatrix();
  return turn * restPose(machine);
}

double AuditRotaryAxis::conventionRadians(double degrees) const { return radians((degrees - zeroDegrees) / direction); }

AuditAxisLines auditAxisLines(const AuditTwoAxes& axes) {
  // The files' frame is the printer's moved by (platform centre, platform z).
  const Eigen::Vector2d centre = axes.rotationCenterMm - axes.platformCenterMm;
  AuditAxisLines lines;
  lines.rotationPoint = Vec3(centre.x(), centre.y(), 0.0);
  lines.tiltPoint = Vec3(centre.x(), centre.y(), axes.tiltHeightMm - axes.platformZMm);
  lines.tiltDirection = axes.tiltAlongX ? Vec3::UnitX() : Vec3::UnitY();
  return lines;
}

Eigen::Isometry3d twoAxisModelToFile(const AuditTwoAxes& axes, const Eigen::Isometry3d& rest,
                                     const AuditAxisCoordinates& at) {
  const AuditAxisLines lines = auditAxisLines(axes);
  const auto about = [](const Vec3& through, const Vec3& direction, double angle) {
    Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
    turn.linear() = Eigen::AngleAxisd(angle, direction).toRotationMatrix();
    turn.translation() = through - turn.linear() * through;
    return turn;
  };
  return about(lines.tiltPoint, lines.tiltDirection, -axes.tilt.conventionRadians(at.tiltDegrees)) *
         about(lines.rotationPoint, Vec3::UnitZ(), axes.rotation.conventionRadians(at.rotationDegrees)) * rest;
}

}  // namespace multidir::slicing

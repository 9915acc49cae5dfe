#include "multidir/core/search/machine.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "multidir/core/common/units.h"

namespace multidir::core {
namespace {

Error outOfRange(const std::string& field, const std::string& rule) {
  return Error{ErrorCode::InvalidParameter, field + " " + rule, field};
}

bool isUnit(const Vec3& v) { return v.allFinite() && std::abs(v.norm() - 1.0) < 1e-9; }

}  // namespace

const char* machineKindName(MachineKind kind) {
  switch (kind) {
    case MachineKind::ThreeAxis: return "3dof";
    case MachineKind::RotaryPlatform: return "4dof";
    case MachineKind::TiltRotate: return "5dof";
    case MachineKind::Apart: return "apart";
  }
  return "?";
}

Result<MachineKind> parseMachineKind(const std::string& text) {
  if (text == "3dof") return MachineKind::ThreeAxis;
  if (text == "4dof") return MachineKind::RotaryPlatform;
  if (text == "5dof") return MachineKind::TiltRotate;
  if (text == "apart") return MachineKind::Apart;
  return Error{ErrorCode::InvalidParameter, "'" + text + "' is not a machine: use 3dof, 4dof, 5dof or apart",
               "machine"};
}

Status validate(const MachineSpec& spec) {
  if (!isUnit(spec.up)) return outOfRange("up", "must be a unit vector");
  if (!(std::isfinite(spec.platformRadiusMm) && spec.platformRadiusMm < 1e6))
    return outOfRange("platform radius", "must be a finite length in mm (0 = the model's footprint)");
  if (!(spec.platformMarginMm >= 0 && spec.platformMarginMm < 1e4))
    return outOfRange("platform margin", "must be between 0 and 10000 mm");
  if (spec.kind == MachineKind::RotaryPlatform) {
    if (!isUnit(spec.rotationAxis) || std::abs(spec.rotationAxis.dot(spec.up)) > 1e-6)
      return outOfRange("rotation axis", "must be a unit vector lying in the platform plane (perpendicular to up)");
    if (!(spec.minAngleDegrees >= -180 && spec.maxAngleDegrees <= 180 && spec.minAngleDegrees <= spec.maxAngleDegrees))
      return outOfRange("angle range", "must satisfy -180 <= min <= max <= 180 degrees");
    if (!(spec.angleStepDegrees > 0 && spec.angleStepDegrees <= 90))
      return outOfRange("angle step", "must be above 0 and at most 90 degrees");
  }
  if (spec.kind == MachineKind::TiltRotate) {
    if (!(spec.maxTiltDegrees >= 0 && spec.maxTiltDegrees <= 180))
      return outOfRange("maximal tilt", "must be between 0 and 180 degrees");
    for (const ForbiddenCone& cone : spec.forbiddenCones) {
      if (!isUnit(cone.axis)) return outOfRange("forbidden cone axis", "must be a unit vector");
      if (!(cone.halfAngleDegrees > 0 && cone.halfAngleDegrees < 180))
        return outOfRange("forbidden cone half-angle", "must be above 0 and below 180 degrees");
    }
  }
  return Done{};
}

PlatformRegion platformRegionFor(const TriangleMesh& model, const MachineSpec& spec, double toleranceMm) {
  PlatformRegion region;
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& v : model.vertices) lowest = std::min(lowest, spec.up.dot(v));
  if (!std::isfinite(lowest)) lowest = 0.0;
  region.heightMm = lowest;

  Vec3 sum = Vec3::Zero();
  std::size_t count = 0;
  for (const Vec3& v : model.vertices)
    if (spec.up.dot(v) - lowest <= toleranceMm) {
      sum += v;
      ++count;
    }
  const Vec3 centroid = count ? Vec3(sum / static_cast<double>(count)) : Vec3::Zero();
  region.center = centroid - (spec.up.dot(centroid) - lowest) * spec.up;
  double footprint = 0.0;
  for (const Vec3& v : model.vertices)
    if (spec.up.dot(v) - lowest <= toleranceMm) {
      const Vec3 d = v - region.center;
      footprint = std::max(footprint, (d - spec.up.dot(d) * spec.up).norm());
    }
  region.radiusMm = spec.platformRadiusMm > 0 ? spec.platformRadiusMm : footprint + spec.platformMarginMm;
  return region;
}

Vec3 platformFrameX(const Vec3& up) {
  Vec3 x = Vec3::UnitX() - up.x() * up;
  if (x.norm() < 1e-6) x = Vec3::UnitY() - up.y() * up;
  return x.normalized();
}

Vec3 rotaryDirection(const MachineSpec& spec, double angleDegrees) {
  return Eigen::AngleAxisd(degToRad(angleDegrees), spec.rotationAxis) * spec.up;
}

MachineAngles machineAnglesFor(const MachineSpec& spec, const Vec3& direction) {
  MachineAngles angles;
  const Vec3 d = direction.normalized();
  angles.tiltDegrees = radToDeg(std::acos(std::clamp(d.dot(spec.up), -1.0, 1.0)));
  const Vec3 x = platformFrameX(spec.up);
  const Vec3 y = spec.up.cross(x);
  if (angles.tiltDegrees > 1e-9) angles.azimuthDegrees = radToDeg(std::atan2(d.dot(y), d.dot(x)));
  // Signed angle about r that turns up into d (meaningful when d is perpendicular to r).
  angles.rotaryDegrees = radToDeg(std::atan2(spec.rotationAxis.dot(spec.up.cross(d)), spec.up.dot(d)));
  return angles;
}

Eigen::Matrix3d platformRotation(const MachineSpec& spec, const MachineAngles& angles) {
  switch (spec.kind) {
    case MachineKind::ThreeAxis:
      return Eigen::Matrix3d::Identity();
    case MachineKind::RotaryPlatform:
      return Eigen::AngleAxisd(-degToRad(angles.rotaryDegrees), spec.rotationAxis.normalized()).toRotationMatrix();
    case MachineKind::TiltRotate:
    case MachineKind::Apart: {
      const Vec3 x = platformFrameX(spec.up);
      const Vec3 y = spec.up.cross(x);
      const double azimuth = degToRad(angles.azimuthDegrees);
      const Vec3 axis = std::sin(azimuth) * x - std::cos(azimuth) * y;
      return Eigen::AngleAxisd(degToRad(angles.tiltDegrees), axis).toRotationMatrix();
    }
  }
  return Eigen::Matrix3d::Identity();
}

bool isRealizable(const MachineSpec& spec, const Vec3& direction, double toleranceRadians) {
  const Vec3 d = direction.normalized();
  const double tolDeg = radToDeg(toleranceRadians);
  switch (spec.kind) {
    case MachineKind::ThreeAxis:
      return d.dot(spec.up) >= std::cos(toleranceRadians);
    case MachineKind::RotaryPlatform: {
      if (std::abs(d.dot(spec.rotationAxis)) > std::sin(toleranceRadians)) return false;
      const double angle = machineAnglesFor(spec, d).rotaryDegrees;
      if (angle < spec.minAngleDegrees - tolDeg || angle > spec.maxAngleDegrees + tolDeg) return false;
      const double steps = (angle - spec.minAngleDegrees) / spec.angleStepDegrees;
      return std::abs(steps - std::round(steps)) * spec.angleStepDegrees <= tolDeg;
    }
    case MachineKind::TiltRotate: {
      if (machineAnglesFor(spec, d).tiltDegrees > spec.maxTiltDegrees + tolDeg) return false;
      for (const ForbiddenCone& cone : spec.forbiddenCones)
        if (radToDeg(std::acos(std::clamp(d.dot(cone.axis), -1.0, 1.0))) < cone.halfAngleDegrees) return false;
      return true;
    }
    case MachineKind::Apart:
      return true;  // a part can be laid on the bed any way up
  }
  return false;
}

}  // namespace multidir::core

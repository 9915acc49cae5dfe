#include "multidir/hardware/motion_limits.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "degrees_text.h"
#include "multidir/core/common/units.h"

namespace multidir::hardware {
namespace {

core::Error refused(const std::string& where, const std::string& message) {
  return core::Error{core::ErrorCode::InvalidParameter, message, where};
}

}  // namespace

core::Status checkRotaryTarget(const core::MachineSpec& machine, double angleDegrees, double toleranceDegrees) {
  if (machine.kind != core::MachineKind::RotaryPlatform)
    return refused("machine profile", std::string("the profile is a ") + core::machineKindName(machine.kind) +
                                          " machine, not a rotary platform (4dof): load the platform's profile");
  if (!std::isfinite(angleDegrees)) return refused("target angle", "the target angle is not a number");
  if (angleDegrees < machine.minAngleDegrees - toleranceDegrees ||
      angleDegrees > machine.maxAngleDegrees + toleranceDegrees)
    return refused("target angle", "the target angle " + degreesText(angleDegrees) +
                                       " degrees is outside the platform's range [" +
                                       degreesText(machine.minAngleDegrees) + ", " +
                                       degreesText(machine.maxAngleDegrees) + "] degrees of the machine profile");
  const double steps = (angleDegrees - machine.minAngleDegrees) / machine.angleStepDegrees;
  const double off = std::abs(steps - std::round(steps)) * machine.angleStepDegrees;
  if (off > toleranceDegrees) {
    const double below = machine.minAngleDegrees + std::floor(steps) * machine.angleStepDegrees;
    const double above = below + machine.angleStepDegrees;
    return refused("target angle", "the target angle " + degreesText(angleDegrees) +
                                       " degrees is not a whole number of stepper steps (" +
                                       degreesText(machine.angleStepDegrees) + " degrees from " +
                                       degreesText(machine.minAngleDegrees) + "): the nearest realizable angles are " +
                                       degreesText(below) + " and " + degreesText(above) + " degrees");
  }
  return core::Done{};
}

core::Vec3 tiltAzimuthDirection(const core::MachineSpec& machine, double tiltDegrees, double azimuthDegrees) {
  const core::Vec3 x = core::platformFrameX(machine.up);
  const core::Vec3 y = machine.up.cross(x);
  const double tilt = core::degToRad(tiltDegrees);
  const double azimuth = core::degToRad(azimuthDegrees);
  return std::cos(tilt) * machine.up + std::sin(tilt) * (std::cos(azimuth) * x + std::sin(azimuth) * y);
}

core::Status checkTiltTarget(const core::MachineSpec& machine, double tiltDegrees, double azimuthDegrees) {
  if (machine.kind != core::MachineKind::TiltRotate)
    return refused("machine profile", std::string("the profile is a ") + core::machineKindName(machine.kind) +
                                          " machine, not a tilting arm (5dof): load the robot's profile");
  if (!std::isfinite(tiltDegrees) || !std::isfinite(azimuthDegrees))
    return refused("target orientation", "the tilt or azimuth is not a number");
  if (tiltDegrees < 0.0)
    return refused("tilt", "the tilt " + degreesText(tiltDegrees) +
                               " degrees is negative: give a tilt of 0 or more and turn the azimuth instead");
  if (tiltDegrees > machine.maxTiltDegrees)
    return refused("tilt", "the tilt " + degreesText(tiltDegrees) + " degrees exceeds the machine's maximal tilt of " +
                               degreesText(machine.maxTiltDegrees) + " degrees");
  const core::Vec3 direction = tiltAzimuthDirection(machine, tiltDegrees, azimuthDegrees);
  for (std::size_t i = 0; i < machine.forbiddenCones.size(); ++i) {
    const core::ForbiddenCone& cone = machine.forbiddenCones[i];
    const double angle = core::radToDeg(std::acos(std::clamp(direction.dot(cone.axis), -1.0, 1.0)));
    if (angle < cone.halfAngleDegrees)
      return refused("target orientation", "tilt " + degreesText(tiltDegrees) + ", azimuth " +
                                               degreesText(azimuthDegrees) + " degrees lies inside forbidden cone " +
                                               std::to_string(i + 1) + " of the machine profile (" +
                                               degreesText(angle) + " degrees from its axis, half-angle " +
                                               degreesText(cone.halfAngleDegrees) + "): the arm would collide there");
  }
  return core::Done{};
}

}  // namespace multidir::hardware

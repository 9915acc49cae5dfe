#include "ui/device/plan_steps.h"

#include <cmath>
#include <cstdio>

#include "multidir/hardware/motion_limits.h"

namespace multidir::ui {

std::string regionFileName(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "region-%02zu.stl", index + 1);
  return name;
}

std::vector<core::MachineAngles> regionAngles(const core::Decomposition& plan) {
  std::vector<core::MachineAngles> angles;
  angles.reserve(plan.regions.size());
  for (const core::Region& region : plan.regions) angles.push_back(region.angles);
  return angles;
}

core::Result<std::vector<hardware::PrintStep>> printSteps(const std::vector<core::MachineAngles>& regions,
                                                          DeviceKind kind, const core::MachineSpec& machine,
                                                          double snapToleranceDegrees) {
  if (regions.empty())
    return core::Error{core::ErrorCode::InvalidParameter, "the plan has no regions: run a search first", "plan"};
  std::vector<hardware::PrintStep> steps;
  steps.reserve(regions.size());
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const core::MachineAngles& angles = regions[i];
    hardware::PrintStep step;
    step.regionFile = regionFileName(i);
    core::Status reachable = core::Done{};
    if (kind == DeviceKind::RotaryPlatform) {
      double angle = angles.rotaryDegrees;
      if (machine.angleStepDegrees > 0.0 && std::isfinite(angle)) {
        const double stepCount = (angle - machine.minAngleDegrees) / machine.angleStepDegrees;
        const double snapped = machine.minAngleDegrees + std::round(stepCount) * machine.angleStepDegrees;
        if (std::abs(snapped - angle) <= snapToleranceDegrees) angle = snapped;
      }
      step.orientation = hardware::PlatformOrientation::rotary(angle);
      reachable = hardware::checkRotaryTarget(machine, angle);
    } else {
      step.orientation = hardware::PlatformOrientation::tiltAzimuth(angles.tiltDegrees, angles.azimuthDegrees);
      reachable = hardware::checkTiltTarget(machine, angles.tiltDegrees, angles.azimuthDegrees);
    }
    if (!reachable.ok())
      return core::Error{core::ErrorCode::InvalidParameter,
                         "region " + std::to_string(i + 1) + " (" + step.regionFile +
                             "): " + reachable.error().message + "; search again with this machine's profile",
                         "plan"};
    steps.push_back(std::move(step));
  }
  return steps;
}

}  // namespace multidir::ui

#include "ui/device/plan_steps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "multidir/core/common/units.h"
#include "multidir/hardware/motion_limits.h"

namespace multidir::ui {

std::string regionFileName(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "region-%02zu.stl", index + 1);
  return name;
}

std::vector<RegionTarget> regionTargets(const core::Decomposition& plan) {
  std::vector<RegionTarget> targets;
  targets.reserve(plan.regions.size());
  for (const core::Region& region : plan.regions)
    targets.push_back(RegionTarget{region.angles, region.printingDirection.normalized()});
  return targets;
}

namespace {

std::string degreesText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", value);
  return text;
}

// "region 2 by 65.0 degrees and region 3 by 71.0 degrees" for the (index, degrees) pairs.
std::string regionList(const std::vector<std::pair<std::size_t, double>>& regions) {
  std::string text;
  for (std::size_t k = 0; k < regions.size(); ++k) {
    if (k > 0) text += k + 1 == regions.size() ? " and " : ", ";
    text += "region " + std::to_string(regions[k].first + 1) + " by " + degreesText(regions[k].second) + " degrees";
  }
  return text;
}

// Whether the rotary platform can print along each region's direction at all, before any stepper detail:
// it tilts the model only about its axis, and no further than its angle range.
core::Status checkRotaryDirections(const std::vector<RegionTarget>& regions, const core::MachineSpec& machine) {
  constexpr double kToleranceDegrees = 1e-4;
  const double reach = std::max(std::abs(machine.minAngleDegrees), std::abs(machine.maxAngleDegrees));
  std::vector<std::pair<std::size_t, double>> beyond;
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const double tilt = core::radToDeg(std::acos(std::clamp(regions[i].direction.dot(machine.up), -1.0, 1.0)));
    if (tilt > reach + kToleranceDegrees) beyond.emplace_back(i, tilt);
  }
  const std::string advice =
      ": the plan was made for another machine; choose this platform on the Machine tab and search again";
  if (!beyond.empty())
    return core::Error{core::ErrorCode::InvalidParameter,
                       "the plan tilts " + regionList(beyond) + ", beyond the rotary platform's range of " +
                           degreesText(machine.minAngleDegrees) + " to " + degreesText(machine.maxAngleDegrees) +
                           " degrees" + advice,
                       "plan"};
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const double lean =
        core::radToDeg(std::asin(std::clamp(std::abs(regions[i].direction.dot(machine.rotationAxis)), 0.0, 1.0)));
    if (lean > kToleranceDegrees)
      return core::Error{core::ErrorCode::InvalidParameter,
                         "region " + std::to_string(i + 1) + " is printed along a direction " + degreesText(lean) +
                             " degrees off the plane the rotary platform turns in (it turns about its axis only)" +
                             advice,
                         "plan"};
  }
  return core::Done{};
}

}  // namespace

core::Result<std::vector<hardware::PrintStep>> printSteps(const std::vector<RegionTarget>& regions,
                                                          DeviceKind kind, const core::MachineSpec& machine,
                                                          double snapToleranceDegrees) {
  if (regions.empty())
    return core::Error{core::ErrorCode::InvalidParameter, "the plan has no regions: run a search first", "plan"};
  if (kind == DeviceKind::RotaryPlatform && machine.kind == core::MachineKind::RotaryPlatform) {
    if (core::Status reachable = checkRotaryDirections(regions, machine); !reachable.ok()) return reachable.error();
  }
  std::vector<hardware::PrintStep> steps;
  steps.reserve(regions.size());
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const core::MachineAngles& angles = regions[i].angles;
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

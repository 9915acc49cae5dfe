#include "ui/edit/plane_edit_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "multidir/core/common/units.h"
#include "ui/viewer/plan_geometry.h"

namespace multidir::ui {
namespace {

bool validIndex(const core::Decomposition& plan, int planeIndex) {
  return planeIndex >= 0 && static_cast<std::size_t>(planeIndex) < plan.clippingPlanes.size();
}

// Regions still part of the model when plane `planeIndex` cuts (cut off by it or later, or never cut).
template <typename Visit>
void forEachVertexLeftBefore(const core::Decomposition& plan, int planeIndex, Visit visit) {
  for (const core::Region& region : plan.regions) {
    if (region.clippingIndex >= 0 && region.clippingIndex < planeIndex) continue;
    for (const core::Vec3& v : region.mesh.vertices) visit(v);
  }
}

OffsetRange rangeAlong(const core::Decomposition& plan, int planeIndex, const core::Vec3& normal) {
  OffsetRange range{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  forEachVertexLeftBefore(plan, planeIndex, [&](const core::Vec3& v) {
    const double d = normal.dot(v);
    range.minMm = std::min(range.minMm, d);
    range.maxMm = std::max(range.maxMm, d);
  });
  if (range.empty()) return OffsetRange{};
  return range;
}

}  // namespace

OffsetRange offsetRangeBefore(const core::Decomposition& plan, int planeIndex, const core::Vec3& normal) {
  if (!validIndex(plan, planeIndex)) return OffsetRange{};
  return rangeAlong(plan, planeIndex, normal);
}

core::Vec3 planePivot(const core::Decomposition& plan, int planeIndex) {
  if (!validIndex(plan, planeIndex)) return core::Vec3::Zero();
  const core::Plane& plane = plan.clippingPlanes[static_cast<std::size_t>(planeIndex)];
  const std::vector<PlaneDisc> discs = planeDiscs(plan);
  const PlaneDisc& disc = discs[static_cast<std::size_t>(planeIndex)];
  if (disc.radiusMm > 0.0) return disc.center;
  core::Vec3 sum = core::Vec3::Zero();
  std::size_t count = 0;
  forEachVertexLeftBefore(plan, planeIndex, [&](const core::Vec3& v) {
    sum += v;
    ++count;
  });
  return count > 0 ? plane.project(sum / static_cast<double>(count)) : plane.project(core::Vec3::Zero());
}

core::Vec3 tiltedDirection(const core::Vec3& up, double tiltDegrees, double azimuthDegrees) {
  const core::Vec3 z = up.normalized();
  const core::Vec3 x = core::platformFrameX(z);
  const core::Vec3 y = z.cross(x);
  const double tilt = core::degToRad(tiltDegrees);
  const double azimuth = core::degToRad(azimuthDegrees);
  return (std::cos(tilt) * z + std::sin(tilt) * (std::cos(azimuth) * x + std::sin(azimuth) * y)).normalized();
}

double snapRotaryDegrees(const core::MachineSpec& machine, double angleDegrees) {
  const double step = machine.angleStepDegrees > 0.0 ? machine.angleStepDegrees : 1.0;
  const double lastStep = std::floor((machine.maxAngleDegrees - machine.minAngleDegrees) / step + 1e-9);
  const double steps =
      std::clamp(std::round((angleDegrees - machine.minAngleDegrees) / step), 0.0, std::max(0.0, lastStep));
  return machine.minAngleDegrees + steps * step;
}

NewPlanePlacement suggestNewPlane(const core::Decomposition& plan, int selectedPlane, const core::Vec3& up) {
  NewPlanePlacement placement;
  if (validIndex(plan, selectedPlane)) {
    const core::Plane& selected = plan.clippingPlanes[static_cast<std::size_t>(selectedPlane)];
    const OffsetRange range = rangeAlong(plan, selectedPlane, selected.normal);
    const double top = range.empty() ? selected.offset : range.maxMm;
    placement.index = selectedPlane;
    placement.plane = core::Plane{selected.normal, 0.5 * (selected.offset + top)};
    return placement;
  }
  const core::Vec3 level = up.normalized();
  const auto planes = static_cast<int>(plan.clippingPlanes.size());
  const OffsetRange range = rangeAlong(plan, planes, level);
  placement.index = planes;
  placement.plane = core::Plane{level, range.empty() ? 0.0 : 0.5 * (range.minMm + range.maxMm)};
  return placement;
}

}  // namespace multidir::ui

#include "ui/viewer/platform_picker.h"

#include <cmath>

namespace multidir::ui {

PlatformHit hitPlatform(const PlatformDisc& disc, const core::Vec3& origin, const core::Vec3& direction) {
  PlatformHit hit;
  const double length = direction.norm();
  if (!std::isfinite(length) || length == 0.0 || !origin.allFinite()) return hit;
  const core::Vec3 unit = direction / length;
  // sin of the angle between the ray and the plane.
  const double along = unit.dot(disc.normal);
  if (std::abs(along) < 1e-6) return hit;
  const double t = (disc.center - origin).dot(disc.normal) / along;
  if (t < 0.0) {
    hit.kind = PlatformHitKind::Behind;
    return hit;
  }
  hit.point = origin + t * unit;
  hit.kind = (hit.point - disc.center).norm() <= disc.radiusMm ? PlatformHitKind::Hit : PlatformHitKind::OutsideDisc;
  return hit;
}

std::optional<core::Vec3> axisThroughPoints(const core::Vec3& normal, const core::Vec3& first,
                                            const core::Vec3& second, double minDistanceMm) {
  const core::Vec3 difference = second - first;
  const core::Vec3 inPlane = difference - difference.dot(normal) * normal;
  const double length = inPlane.norm();
  if (!std::isfinite(length) || length < minDistanceMm || length == 0.0) return std::nullopt;
  return inPlane / length;
}

}  // namespace multidir::ui

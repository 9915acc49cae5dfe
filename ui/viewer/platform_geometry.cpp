#include "ui/viewer/platform_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace multidir::ui {
namespace {

core::Vec3 unitOrZ(const core::Vec3& v) {
  const double length = v.norm();
  if (!std::isfinite(length) || length == 0.0) return core::Vec3::UnitZ();
  return v / length;
}

// Any unit vector perpendicular to `n`.
core::Vec3 perpendicular(const core::Vec3& n) {
  const core::Vec3 helper = std::abs(n.x()) < 0.9 ? core::Vec3::UnitX() : core::Vec3::UnitY();
  return n.cross(helper).normalized();
}

}  // namespace

PlatformDisc platformUnder(const core::TriangleMesh& mesh, const core::Vec3& up) {
  PlatformDisc disc;
  disc.normal = unitOrZ(up);
  if (mesh.vertices.empty()) {
    disc.radiusMm = 50.0;
    return disc;
  }
  // Footprint in the plane's own 2D frame (u, w): its bounding-box centre, then the farthest vertex.
  const core::Vec3 u = perpendicular(disc.normal);
  const core::Vec3 w = disc.normal.cross(u);
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  double uMin = lowest, wMin = lowest;
  double uMax = -lowest, wMax = -lowest;
  for (const core::Vec3& p : mesh.vertices) {
    lowest = std::min(lowest, p.dot(disc.normal));
    highest = std::max(highest, p.dot(disc.normal));
    uMin = std::min(uMin, p.dot(u));
    uMax = std::max(uMax, p.dot(u));
    wMin = std::min(wMin, p.dot(w));
    wMax = std::max(wMax, p.dot(w));
  }
  const double uMid = 0.5 * (uMin + uMax);
  const double wMid = 0.5 * (wMin + wMax);
  double radiusSquared = 0.0;
  for (const core::Vec3& p : mesh.vertices) {
    const double du = p.dot(u) - uMid;
    const double dw = p.dot(w) - wMid;
    radiusSquared = std::max(radiusSquared, du * du + dw * dw);
  }
  disc.center = uMid * u + wMid * w + lowest * disc.normal;
  // A needle standing along `up` still gets a platform one can see; a single point gets 1 mm.
  disc.radiusMm = kPlatformMargin * std::max(std::sqrt(radiusSquared), 0.25 * (highest - lowest));
  if (!(disc.radiusMm > 0.0) || !std::isfinite(disc.radiusMm)) disc.radiusMm = 1.0;
  return disc;
}

}  // namespace multidir::ui

#pragma once
// Picking points on the build platform with the mouse, and the 4-DOF rotation axis through two of them.
// Pure geometry (no VTK, no Qt), so it can be tested: the viewer turns a click into a ray and asks here
// where, if anywhere, the ray meets the platform disc.
#include <optional>

#include "multidir/core/mesh/triangle_mesh.h"
#include "ui/viewer/platform_geometry.h"

namespace multidir::ui {

// What became of a ray aimed at the platform.
enum class PlatformHitKind {
  Hit,          // `point` is on the disc
  Parallel,     // the ray runs along the platform plane (the view looks at it edge-on)
  Behind,       // the plane lies behind the ray's origin
  OutsideDisc,  // the ray meets the plane, but off the disc (`point` is where)
  NoPlatform,   // nothing is shown, so there is no platform to hit
};

struct PlatformHit {
  PlatformHitKind kind = PlatformHitKind::Parallel;
  core::Vec3 point = core::Vec3::Zero();  // mm, on the platform plane (Hit, OutsideDisc)
};

// Where the ray from `origin` along `direction` (any length > 0) meets the plane of `disc`, and whether that
// is on the disc. A ray within 1e-6 rad of the plane, or a zero or non-finite direction, is Parallel.
[[nodiscard]] PlatformHit hitPlatform(const PlatformDisc& disc, const core::Vec3& origin, const core::Vec3& direction);

// Two picked points closer than this (mm) give no axis: the direction between them would be noise.
constexpr double kMinAxisPointDistanceMm = 1.0;

// The rotation axis through `first` and `second`: their difference with its part along `normal` (the
// platform's, unit length) removed, normalised. nullopt when the points are closer than `minDistanceMm`
// within the platform plane.
[[nodiscard]] std::optional<core::Vec3> axisThroughPoints(const core::Vec3& normal, const core::Vec3& first,
                                                          const core::Vec3& second,
                                                          double minDistanceMm = kMinAxisPointDistanceMm);

}  // namespace multidir::ui

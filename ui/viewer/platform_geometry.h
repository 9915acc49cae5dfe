#pragma once
// Where the viewer draws the build platform under a model. Pure geometry (no VTK), so it can be tested.
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::ui {

// A disc in the plane through the model's lowest point along the up direction, centred under the
// model's footprint and a little larger than it.
struct PlatformDisc {
  core::Vec3 center = core::Vec3::Zero();   // mm, on the platform plane
  core::Vec3 normal = core::Vec3::UnitZ();  // unit length, the up direction
  double radiusMm = 0.0;                    // > 0
};

// How much larger than the footprint's enclosing circle the platform is drawn.
constexpr double kPlatformMargin = 1.25;

// The platform under `mesh` printed along `up` (normalised here; a zero or non-finite `up` counts as +Z).
// An empty mesh gets a 50 mm disc at the origin.
PlatformDisc platformUnder(const core::TriangleMesh& mesh, const core::Vec3& up);

}  // namespace multidir::ui

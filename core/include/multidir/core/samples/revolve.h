#pragma once
// Solids of revolution around the Z axis from a closed profile in the (r, z) half-plane.
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::samples {

using Vec2 = Eigen::Vector2d;

// Revolves `profile`, points (r, z) in mm, around +Z in `segments` equal steps. The profile runs from a
// point on the axis (r = 0) to another point on the axis, counter-clockwise in the (r, z) plane (for a
// solid standing on its base: out along the bottom, up the side, back in over the top); every point in
// between has r > 0 and the polyline, closed along the axis, must not cross itself. The two axis points
// become single pole vertices closed with triangle fans, so the mesh has no duplicate vertices and no
// degenerate faces. Errors: InvalidParameter (fewer than 3 points or segments, a non-finite point, ends
// off the axis, an inner point with r <= 0, two consecutive equal points, a self-crossing, clockwise).
Result<TriangleMesh> revolveProfile(const std::vector<Vec2>& profile, int segments);

}  // namespace multidir::core::samples

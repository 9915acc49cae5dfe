#pragma once
// Private to clipping: turns the cut edges of a clipped solid into the cap that closes it.
#include <array>
#include <cstdint>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/geometry/plane.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

// A directed edge of the cap's boundary, as indices into the clipper's vertex positions.
using CapEdge = std::array<std::int32_t, 2>;

// Chains the cap's boundary edges into closed loops in the plane, nests holes (and islands in holes) inside
// their outer loops, and triangulates each region with only the loops' vertices. The edges must leave the cap
// on their left seen from +plane.normal (outer loops counter-clockwise); each is used once, in its direction,
// by the returned triangles, which face +plane.normal. `meshEdges` are edges in the plane that faces of either
// side already have: the cap avoids them as diagonals (a crease touching the plane would get four faces).
// Errors: Internal when the edges do not close into loops.
Result<std::vector<Triangle>> triangulateCap(const std::vector<CapEdge>& edges, const std::vector<CapEdge>& meshEdges,
                                             const std::vector<Vec3>& positions, const Plane& plane);

}  // namespace multidir::core::detail

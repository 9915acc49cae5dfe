#pragma once
// Triangulation of a planar polygon with holes: the caps that close a clipped solid are built with it.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

using Vec2 = Eigen::Vector2d;

// One region of a plane: an outer loop and the holes inside it, as indices into a point array.
// The region lies to the left of every loop edge: the outer loop runs counter-clockwise, holes clockwise.
// Loops may touch themselves or each other at a shared vertex index (weakly simple); they never cross.
struct PolygonWithHoles {
  std::vector<std::int32_t> outer;
  std::vector<std::vector<std::int32_t>> holes;
};

// Triangulates the region by ear clipping after joining each hole to the outer loop by a bridge.
//
// Guarantees, whatever the geometry (collinear runs, near-coincident points, slivers):
//  - only the loops' own vertex indices are used: no new points, none left out;
//  - every loop edge is used by exactly one triangle, in the loop's direction, and every other edge by two
//    triangles in opposite directions, so the triangles close a mesh whose boundary is these loops;
//  - triangles are counter-clockwise when the loops are oriented as above; a zero-area triangle is emitted
//    only when the remaining polygon leaves no other choice (for example a loop without area).
// `avoid` lists vertex pairs (either order) that must not become a diagonal unless nothing else is possible:
// edges the caller's mesh already has, which a diagonal would make shared by four faces.
// Cost: O(n^2) in the number n of loop vertices in the worst case, close to O(n) for typical cross-sections.
// Errors: InvalidParameter when an index is out of range, a loop has fewer than 3 vertices or repeats a vertex
// on consecutive corners, or a point used is not finite.
Result<std::vector<Triangle>> triangulatePolygon(const std::vector<Vec2>& points, const PolygonWithHoles& polygon,
                                                 const std::vector<std::array<std::int32_t, 2>>& avoid = {});

}  // namespace multidir::core

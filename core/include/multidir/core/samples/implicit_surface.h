#pragma once
// Turns a signed distance function into a closed, consistently oriented triangle mesh by marching
// tetrahedra on a regular grid. Every cube of the grid is split into the six tetrahedra around its main
// diagonal, so neighbouring cubes agree on every shared face and the surface is watertight; crossing
// vertices are shared by grid-edge id (never by position), so the result is a 2-manifold without
// duplicate vertices.
#include <functional>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::samples {

// Negative inside the solid, positive outside, about a distance in mm (Lipschitz constant near 1).
using SignedDistance = std::function<double(const Vec3&)>;

struct PolygonizeOptions {
  // A grid value closer to zero than this fraction of the cell size is pushed to +fraction * cell size
  // (outside). A crossing then never sits within about fraction / 2 of a grid vertex, which keeps
  // every triangle's area well above zero and no two crossings at the same point.
  double zeroGuardFraction = 1e-2;
  // The most grid points polygonize() will evaluate (memory: 8 bytes each), at most 2^28.
  long long maxGridPoints = 1LL << 24;
};

// Polygonizes the zero level set of `sdf` on the grid of points bounds.min + cellSizeMm * (i, j, k)
// that covers `bounds`. The solid must lie strictly inside the box (every value on the grid's outer
// layer positive); leave a cell or two of margin. Faces are counter-clockwise from outside, origins are
// {Surface, face index}. Deterministic: the same input gives the same mesh, vertex for vertex.
// Errors: InvalidParameter (cell size not positive and finite, box empty or not finite, too many grid
// points, a non-finite sdf value, the solid touching the box), EmptyMesh (the sdf is positive everywhere).
// Example: polygonize([](const Vec3& p) { return p.norm() - 10.0; }, {Vec3::Constant(-12), Vec3::Constant(12)}, 0.5)
Result<TriangleMesh> polygonize(const SignedDistance& sdf, const BoundingBox& bounds, double cellSizeMm,
                                const PolygonizeOptions& options = {});

}  // namespace multidir::core::samples

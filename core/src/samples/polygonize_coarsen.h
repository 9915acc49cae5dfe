#pragma once
// Private to the generated samples: how an implicit sample standing on the floor (z = 0) becomes a mesh.
#include "multidir/core/common/result.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/samples/implicit_surface.h"

namespace multidir::core::samples {

// Polygonizes `sdf` on a fine grid of cellSizeMm (so thin parts keep their shape), then coarsens it to edges
// of about 1.2..3 mm: marching tetrahedra alone would give several times more triangles. `extent` is the
// solid's box from the floor up; the grid gets two cells of margin around it, and its z levels sit half a cell
// off z = 0 so the floor's crossings land exactly on z = 0.
// Errors: those of polygonize() and collapseShortEdges().
Result<TriangleMesh> polygonizeStandingSample(const SignedDistance& sdf, const BoundingBox& extent, double cellSizeMm);

}  // namespace multidir::core::samples

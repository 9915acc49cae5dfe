#pragma once
// What a mesh becomes in a binary STL: corners rounded to float, corners that became equal merged, and the
// faces that this collapsed dropped. Clipping leaves vertices a few nanometres apart (a plane passing near a
// corner); float cannot keep them apart, so loading the STL would drop those slivers and the face origins
// stored beside the file would no longer line up. The plan saves this image instead, so what is saved is
// exactly what loads back.
#include "multidir/core/common/result.h"
#include "multidir/core/geometry/plane.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

struct StlImage {
  TriangleMesh mesh;  // float-exact vertices, origins of the faces kept
  std::size_t droppedFaces = 0;
  std::size_t mergedCorners = 0;  // vertices that fell onto another one when rounded to float
};

// How many vertices of `mesh` fall onto another vertex at a different position when rounded to float (0: the
// binary STL keeps every point apart, so a closed mesh stays closed). O(V).
std::size_t cornersMergedAtFloatPrecision(const TriangleMesh& mesh);

// The same for one side of a clip by `plane` (clipByPlane with `planeToleranceMm`), looking only at the vertices
// near the plane: the clip makes or moves vertices only there. Precondition: the solid that was clipped had no
// merged corners (cornersMergedAtFloatPrecision == 0); then the count equals cornersMergedAtFloatPrecision's,
// at the cost of a pass over the vertices and a sort of the cross-section's. O(V + C log C).
std::size_t cornersMergedAtFloatPrecisionNearPlane(const TriangleMesh& mesh, const Plane& plane,
                                                   double planeToleranceMm);

// Precondition: mesh.origins.size() == mesh.triangles.size().
StlImage stlImage(const TriangleMesh& mesh);

}  // namespace multidir::core::detail

#pragma once
// Coarsens a closed triangle mesh by collapsing short edges, as a clean-up after polygonize(): marching
// tetrahedra makes many small, thin triangles, and collapsing them gives a lighter mesh of the same shape.
#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::samples {

struct CoarsenOptions {
  double minEdgeMm = 1.0;              // edges shorter than this are collapsed, when the checks below allow it
  double maxEdgeMm = 3.0;              // a collapse may not create an edge longer than this (> minEdgeMm)
  double maxNormalTurnDegrees = 20.0;  // a collapse may turn no surviving face's normal further, in [0, 90]
  double minFaceQuality = 0.1;         // 4 sqrt(3) area / sum of squared edge lengths (1 = equilateral), in [0, 1)
  int maxPasses = 8;                   // sweeps over all edges; each sweep goes in edge order
};

// Collapses short edges of `mesh` one end into the other (halfedge collapses), so every vertex of the
// result is a vertex of the input: no new positions, no duplicates, nothing below the input. A
// collapse is done only when it keeps the surface a 2-manifold of the same genus (the link condition),
// makes no edge longer than maxEdgeMm, turns no face by more than maxNormalTurnDegrees and leaves every
// changed face at least as good as min(minFaceQuality, its quality before). Deterministic. The result's
// origins are {Surface, face index}.
// Errors: InvalidParameter (options out of range, a vertex index out of range), NotManifold (the input
// is not a closed, consistently oriented 2-manifold).
Result<TriangleMesh> collapseShortEdges(const TriangleMesh& mesh, const CoarsenOptions& options = {});

}  // namespace multidir::core::samples

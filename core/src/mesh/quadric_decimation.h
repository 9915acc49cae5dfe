#pragma once
// Quadric-error edge collapse (Garland & Heckbert 1997) for the proxy search's decimated model, written for
// speed on a closed mesh of a million faces: flat arrays instead of a half-edge structure, and the collapses
// taken in passes rather than through a priority queue. Each pass scores every edge once, sorts them, and
// collapses the cheapest ones whose neighbourhoods no other collapse of the pass touched (an independent set),
// so no score is ever stale. About one vertex in eight goes per pass; the cost is a few passes over the mesh.
//
// A collapse keeps the surface a closed, consistently oriented 2-manifold: it is taken only when the link
// condition holds (the edge's two endpoints share exactly the two neighbours opposite it), no face around it
// turns over (its normal turns by at most 60 degrees) and no face becomes a sliver thinner than it was or
// than kMinQuality (slivers would make the search's clips refuse cuts through them).
#include <cstddef>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

// `mesh` must be a closed, consistently oriented 2-manifold (not checked here). Returns the decimated mesh
// (origins reset) with at most targetFaces faces, or as few as the rules above allow; below targetFaces it
// goes on with the collapses that move the surface by at most freeToleranceMm (root mean square over the
// faces around the edge), down to 100 faces.
TriangleMesh quadricDecimation(const TriangleMesh& mesh, std::size_t targetFaces, double freeToleranceMm);

}  // namespace multidir::core::detail

#pragma once
// Quadric-error edge collapse (Garland & Heckbert 1997) for the proxy search's decimated model, written for
// speed on a closed mesh of a million faces: flat arrays instead of a half-edge structure, and the collapses
// taken in passes rather than through a priority queue. Each pass sorts the cheapest quarter of the edges
// and collapses them in that order, skipping edges at a vertex an earlier collapse of the pass moved (their
// scores are stale until the next pass scores them again); every other edge keeps its score from pass to
// pass. The checks below read the live faces, so they are exact however many collapses a pass takes.
//
// A collapse keeps the surface a closed, consistently oriented 2-manifold: it is taken only when the link
// condition holds (the edge's two endpoints share exactly the two neighbours opposite it), no face around it
// turns over (its normal turns by at most 60 degrees) and no face becomes a sliver thinner than it was or
// than kMinQuality (slivers would make the search's clips refuse cuts through them).
#include <cstddef>
#include <optional>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

// Returns the decimated mesh (origins reset) with at most targetFaces faces, or as few as the rules above
// allow; below targetFaces it goes on with the collapses that move the surface by at most freeToleranceMm
// (root mean square over the faces around the edge), down to 100 faces. Returns nothing when `mesh` is not a
// closed, consistently oriented 2-manifold with every index in range: that is checked first, from each
// vertex's faces (the decimation needs those lists anyway), with the same verdict as
// edgeCensus(mesh).closedOriented().
//
// The scoring of the edges, the vertex quadrics and the check run on `threads` threads
// (0: all); each item writes its own slot and every sum keeps its order, so the result is the same, bit for
// bit, for any thread count. So do the collapses above targetFaces: a mesh of 65,536 vertices or more is cut
// into slabs across its longest axis (one per 32,768 vertices, a number the mesh alone sets), and each slab
// takes, in order on its own thread, the pass's edges whose faces lie inside it (a collapse touches nothing
// else), then the same in slabs shifted by half a slab; the few edges still across a border go after, in
// order on one thread, as do the collapses that would bring the faces to targetFaces or below.
// Below fineBelowFaces faces, only collapses within fineToleranceMm (when smaller than freeToleranceMm).
std::optional<TriangleMesh> quadricDecimation(const TriangleMesh& mesh, std::size_t targetFaces, double freeToleranceMm,
                                              int threads, std::size_t fineBelowFaces = 0, double fineToleranceMm = 0.0);

}  // namespace multidir::core::detail

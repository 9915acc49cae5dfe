#pragma once
// The same solid with more or fewer triangles.
//
// subdivided: every triangle split into four at its edge midpoints, `levels` times (4^levels as many faces);
// the surface, volume and every overhang stay exactly the same. The bench uses it to make million-triangle
// versions of the shared models.
// decimated: quadric-error edge collapses (Garland & Heckbert) down to `targetFaces` faces, and further while
// a collapse moves the surface by at most `freeToleranceMm`, refusing collapses that break the manifold, turn
// a face over or make a sliver; the search runs on such a proxy of a huge model and applies its planes to the
// full mesh. A subdivided model (flat splits) goes back to about its original faces at any tolerance.
#include <cstddef>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

// Errors: InvalidParameter (levels outside [0, 6], or more than 2^31 faces would result).
Result<TriangleMesh> subdivided(const TriangleMesh& mesh, int levels);

struct DecimationResult {
  TriangleMesh mesh;
  double volumeChangePercent = 0.0;  // |V_decimated - V| / V, in percent
};

// `mesh` should be a checked mesh (loadMesh's); any other is checked to be a closed, consistently oriented
// 2-manifold first, from the vertex lists the decimation builds anyway (cheaper than edgeCensus, same verdict).
// Runs on `threads` threads (0: all hardware threads); the result is the same, bit for bit, for any count.
// Errors: InvalidParameter (targetFaces < 100, threads < 0, a face naming a vertex that does not exist),
// NotManifold (not a closed oriented 2-manifold; the message has edgeCensus's counts), CheckFailed when the
// result is not closed any more or its volume differs by more than maxVolumeChangePercent: then the model is
// not one to decimate, and the caller uses the full mesh.
// Below `fineBelowFaces` faces, only collapses that move the surface by at most `fineToleranceMm` (when smaller
// than freeToleranceMm) are taken: the proxy's floor (core/src/search/proxy_search.cpp).
Result<DecimationResult> decimated(const TriangleMesh& mesh, std::size_t targetFaces, double freeToleranceMm = 0.0,
                                   double maxVolumeChangePercent = 0.5, int threads = 0, std::size_t fineBelowFaces = 0,
                                   double fineToleranceMm = 0.0);

}  // namespace multidir::core

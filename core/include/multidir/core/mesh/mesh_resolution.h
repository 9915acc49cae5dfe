#pragma once
// The same solid with more triangles.
//
// subdivided: every triangle split into four at its edge midpoints, `levels` times (4^levels as many faces);
// the surface, volume and every overhang stay exactly the same. The bench uses it to make million-triangle
// versions of the shared models.
#include <cstddef>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

// Errors: InvalidParameter (levels outside [0, 6], or more than 2^31 faces would result).
Result<TriangleMesh> subdivided(const TriangleMesh& mesh, int levels);

}  // namespace multidir::core

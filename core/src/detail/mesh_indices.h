#pragma once
// The index checks every operation on a TriangleMesh makes before it follows any index.
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

// One origin per face, and every corner names an existing vertex. `what` names the mesh in the message and
// in `where` ("solid", "mesh"): "the solid has 3 face origins for 4 faces...", where "solid.origins".
Status checkFaceIndices(const TriangleMesh& mesh, const std::string& what);

}  // namespace multidir::core::detail

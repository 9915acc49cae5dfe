#pragma once
// Private to mesh checks and statistics: shells (connected components) as separate meshes.
#include <vector>

#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core::detail {

// The faces of each component, in face order.
std::vector<std::vector<std::int32_t>> facesOfComponents(const FaceComponents& components);

// A mesh made of the given faces of `mesh`, with only the vertices they use (renumbered in order of use).
TriangleMesh extractFaces(const TriangleMesh& mesh, const std::vector<std::int32_t>& faces);

// Generalised winding number of a closed shell around `point`: +-1 inside, 0 outside (sum of the
// solid angles of its triangles over 4 pi).
double windingNumber(const TriangleMesh& shell, const Vec3& point);

}  // namespace multidir::core::detail

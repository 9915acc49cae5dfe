#pragma once
// Private to mesh checks and statistics: shells (connected components) as separate meshes.
#include <vector>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core::detail {

// computeStatistics (mesh_io.h) when whether the mesh is closed and oriented is already known (as after
// checkAndRepair, which made it so).
MeshStatistics computeStatistics(const TriangleMesh& mesh, bool closedOriented);

// The faces of each component, in face order.
std::vector<std::vector<std::int32_t>> facesOfComponents(const FaceComponents& components);

// A mesh made of the given faces of `mesh`, with only the vertices they use (renumbered in order of use).
TriangleMesh extractFaces(const TriangleMesh& mesh, const std::vector<std::int32_t>& faces);

// Generalised winding number of a closed shell around `point`: +-1 inside, 0 outside (sum of the
// solid angles of its triangles over 4 pi).
double windingNumber(const TriangleMesh& shell, const Vec3& point);

// Where one closed shell lies against another: wholly outside it, wholly inside it (a cavity or a part in
// a cavity), or crossing its surface (the two overlap, so neither is a cavity of the other).
enum class Containment { Outside, Inside, Crossing };
// Every vertex of `shell` is tested against `other`'s bounding box, and up to kContainmentProbes of those
// within it, spread over the shell, by winding number; a probe on `other`'s surface (winding number
// near 1/2, as where shells touch) decides nothing. Cost: shell's vertices + probes x other's faces.
constexpr std::size_t kContainmentProbes = 16;
Containment containment(const TriangleMesh& shell, const TriangleMesh& other, const BoundingBox& otherBox);

}  // namespace multidir::core::detail

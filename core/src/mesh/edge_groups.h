#pragma once
// The undirected edges of a triangle mesh, found by sorting its half-edges instead of hashing them: a
// counting sort on the lower vertex, then the higher one, so a million faces cost two linear passes and no
// allocation per edge. Every check of a loaded mesh (edge census, orientation, open or non-manifold edges)
// reads this one table.
#include <cstdint>
#include <vector>

#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

// Half-edge h = 3 * face + k runs from corner k of the face to corner (k + 1) % 3.
struct EdgeGroups {
  std::vector<std::uint32_t> halfEdges;       // every half-edge, grouped by undirected edge, ascending in a group
  std::vector<std::uint32_t> groupStart;      // group g is halfEdges[groupStart[g] .. groupStart[g + 1])
  std::vector<std::uint32_t> groupOfHalfEdge;  // the group of each half-edge

  [[nodiscard]] std::size_t groupCount() const { return groupStart.empty() ? 0 : groupStart.size() - 1; }
  [[nodiscard]] std::uint32_t useCount(std::uint32_t group) const { return groupStart[group + 1] - groupStart[group]; }
};

// Indices must be in range (checked by the caller).
EdgeGroups edgeGroups(const TriangleMesh& mesh);

// edgeCensus (mesh_measure.h) from groups already built.
EdgeCensus edgeCensus(const TriangleMesh& mesh, const EdgeGroups& groups);

inline std::int32_t halfEdgeFrom(const TriangleMesh& mesh, std::uint32_t h) { return mesh.triangles[h / 3][h % 3]; }
inline std::int32_t halfEdgeTo(const TriangleMesh& mesh, std::uint32_t h) { return mesh.triangles[h / 3][(h % 3 + 1) % 3]; }

}  // namespace multidir::core::detail

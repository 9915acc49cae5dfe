#include "mesh/edge_groups.h"

#include <algorithm>

#include "detail/huge_pages.h"

namespace multidir::core::detail {

EdgeGroups edgeGroups(const TriangleMesh& mesh) {
  const std::size_t halfEdgeCount = mesh.triangles.size() * 3;
  const std::size_t vertexCount = mesh.vertices.size();
  auto lower = [&](std::uint32_t h) { return std::min(halfEdgeFrom(mesh, h), halfEdgeTo(mesh, h)); };
  auto higher = [&](std::uint32_t h) { return std::max(halfEdgeFrom(mesh, h), halfEdgeTo(mesh, h)); };

  // Counting sort on the lower vertex: half-edges stay in ascending order inside each bucket.
  std::vector<std::uint32_t> bucketStart(vertexCount + 1, 0);
  for (std::uint32_t h = 0; h < halfEdgeCount; ++h) ++bucketStart[static_cast<std::size_t>(lower(h)) + 1];
  for (std::size_t v = 0; v < vertexCount; ++v) bucketStart[v + 1] += bucketStart[v];
  EdgeGroups out;
  reserveInHugePages(out.halfEdges, halfEdgeCount);
  out.halfEdges.resize(halfEdgeCount);
  {
    std::vector<std::uint32_t> next(bucketStart.begin(), bucketStart.end() - 1);
    for (std::uint32_t h = 0; h < halfEdgeCount; ++h) out.halfEdges[next[static_cast<std::size_t>(lower(h))]++] = h;
  }
  // Inside a bucket (a vertex's edges to higher vertices, a handful), by the higher vertex.
  reserveInHugePages(out.groupOfHalfEdge, halfEdgeCount);
  out.groupOfHalfEdge.resize(halfEdgeCount);
  reserveInHugePages(out.groupStart, halfEdgeCount / 2 + 1);
  for (std::size_t v = 0; v < vertexCount; ++v) {
    const auto first = out.halfEdges.begin() + bucketStart[v], last = out.halfEdges.begin() + bucketStart[v + 1];
    std::sort(first, last, [&](std::uint32_t x, std::uint32_t y) {
      const std::int32_t hx = higher(x), hy = higher(y);
      return hx != hy ? hx < hy : x < y;
    });
    for (auto it = first; it != last; ++it) {
      if (it == first || higher(*it) != higher(*(it - 1)))
        out.groupStart.push_back(static_cast<std::uint32_t>(it - out.halfEdges.begin()));
      out.groupOfHalfEdge[*it] = static_cast<std::uint32_t>(out.groupStart.size() - 1);
    }
  }
  out.groupStart.push_back(static_cast<std::uint32_t>(halfEdgeCount));
  return out;
}

}  // namespace multidir::core::detail

#include "multidir/core/mesh/mesh_measure.h"

#include <algorithm>
#include <vector>

#include "detail/union_find.h"
#include "mesh/edge_groups.h"

namespace multidir::core {
namespace {

using detail::UnionFind;

}  // namespace

double signedVolume(const TriangleMesh& mesh) {
  double sixTimes = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    sixTimes += a.dot((mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a));
  }
  // a.((b-a)x(c-a)) == a.(b x c): the translation-robust form of the same triple product.
  return sixTimes / 6.0;
}

double surfaceArea(const TriangleMesh& mesh) {
  double area = 0.0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) area += mesh.faceArea(f);
  return area;
}

BoundingBox boundingBox(const TriangleMesh& mesh) {
  BoundingBox box;
  bool first = true;
  for (const Triangle& t : mesh.triangles) {
    for (std::int32_t v : t) {
      const Vec3& p = mesh.vertices[v];
      if (first) {
        box.min = box.max = p;
        first = false;
      } else {
        box.min = box.min.cwiseMin(p);
        box.max = box.max.cwiseMax(p);
      }
    }
  }
  return box;
}

EdgeCensus edgeCensus(const TriangleMesh& mesh) { return detail::edgeCensus(mesh, detail::edgeGroups(mesh)); }

EdgeCensus detail::edgeCensus(const TriangleMesh& mesh, const EdgeGroups& groups) {
  EdgeCensus census;
  census.edges = groups.groupCount();
  // A manifold vertex's faces form one fan: its corners, joined across each edge at it, make one set.
  // Corner 3f + k is face f's corner at triangles[f][k]; half-edge h starts at corner h.
  UnionFind corners(mesh.triangles.size() * 3);
  auto cornerAt = [&](std::uint32_t h, std::int32_t vertex) {
    return static_cast<std::int32_t>(detail::halfEdgeFrom(mesh, h) == vertex ? h : 3 * (h / 3) + (h % 3 + 1) % 3);
  };
  for (std::uint32_t g = 0; g < groups.groupCount(); ++g) {
    const std::uint32_t first = groups.groupStart[g], uses = groups.useCount(g);
    if (uses == 1) ++census.boundary;
    else if (uses > 2) ++census.nonManifold;
    else {
      const std::uint32_t h0 = groups.halfEdges[first], h1 = groups.halfEdges[first + 1];
      if (detail::halfEdgeFrom(mesh, h0) == detail::halfEdgeFrom(mesh, h1)) ++census.misoriented;
    }
    const std::uint32_t h0 = groups.halfEdges[first];
    for (const std::int32_t end : {detail::halfEdgeFrom(mesh, h0), detail::halfEdgeTo(mesh, h0)})
      for (std::uint32_t i = first + 1; i < first + uses; ++i)
        corners.unite(cornerAt(h0, end), cornerAt(groups.halfEdges[i], end));
  }
  std::vector<std::uint8_t> fans(mesh.vertices.size(), 0);
  for (std::size_t c = 0; c < mesh.triangles.size() * 3; ++c)
    if (corners.find(static_cast<std::int32_t>(c)) == static_cast<std::int32_t>(c)) {
      std::uint8_t& n = fans[static_cast<std::size_t>(mesh.triangles[c / 3][c % 3])];
      if (n < 2 && ++n == 2) ++census.nonManifoldVertices;
    }
  return census;
}

FaceComponents faceComponents(const TriangleMesh& mesh) {
  UnionFind vertexSets(mesh.vertices.size());
  for (const Triangle& t : mesh.triangles) {
    vertexSets.unite(t[0], t[1]);
    vertexSets.unite(t[0], t[2]);
  }
  FaceComponents out;
  // Ids in order of the components' first faces. Roots are vertices, so an array over them finds a root's id
  // (a hash map was a lookup per face on every cut's part below: docs/architecture.md, "Million-triangle
  // models"); the faces' ids are written, not value-initialised first.
  std::vector<std::int32_t> idOfRoot(mesh.vertices.size(), -1);
  detail::reserveInHugePages(out.componentOfFace, mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    std::int32_t& id = idOfRoot[static_cast<std::size_t>(vertexSets.find(t[0]))];
    if (id < 0) id = out.count++;
    out.componentOfFace.push_back(id);
  }
  return out;
}

long long eulerCharacteristic(const TriangleMesh& mesh) {
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t) used[static_cast<std::size_t>(v)] = 1;
  const long long v = std::count(used.begin(), used.end(), 1);
  const auto edges = static_cast<long long>(detail::edgeGroups(mesh).groupCount());
  return v - edges + static_cast<long long>(mesh.triangles.size());
}

}  // namespace multidir::core

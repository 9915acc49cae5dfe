#include "multidir/core/mesh/mesh_measure.h"
#include "detail/edge_key.h"

#include <algorithm>
#include <unordered_map>

#include "detail/union_find.h"

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

EdgeCensus edgeCensus(const TriangleMesh& mesh) {
  struct EdgeUse {
    int count = 0;
    int forward = 0;  // uses from lower to higher vertex index
  };
  std::unordered_map<std::uint64_t, EdgeUse> uses;
  uses.reserve(mesh.triangles.size() * 2);
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = t[k], b = t[(k + 1) % 3];
      EdgeUse& use = uses[detail::undirectedEdgeKey(a, b)];
      ++use.count;
      if (a < b) ++use.forward;
    }
  }
  EdgeCensus census;
  census.edges = uses.size();
  for (const auto& [key, use] : uses) {
    if (use.count == 1) ++census.boundary;
    else if (use.count > 2) ++census.nonManifold;
    else if (use.forward != 1) ++census.misoriented;
  }

  // A manifold vertex's faces form one fan: faces around it, joined through edges at it, are one group.
  std::vector<std::vector<std::int32_t>> facesOfVertex(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (std::int32_t v : mesh.triangles[f]) facesOfVertex[v].push_back(static_cast<std::int32_t>(f));
  for (std::size_t v = 0; v < facesOfVertex.size(); ++v) {
    const auto& faces = facesOfVertex[v];
    if (faces.size() < 2) continue;
    UnionFind groups(faces.size());
    std::unordered_map<std::int32_t, std::size_t> firstFaceWithOther;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      for (std::int32_t w : mesh.triangles[faces[i]]) {
        if (w == static_cast<std::int32_t>(v)) continue;
        auto [it, inserted] = firstFaceWithOther.emplace(w, i);
        if (!inserted) groups.unite(static_cast<std::int32_t>(it->second), static_cast<std::int32_t>(i));
      }
    }
    std::int32_t root = groups.find(0);
    for (std::size_t i = 1; i < faces.size(); ++i) {
      if (groups.find(static_cast<std::int32_t>(i)) != root) {
        ++census.nonManifoldVertices;
        break;
      }
    }
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
  out.componentOfFace.resize(mesh.triangles.size());
  std::unordered_map<std::int32_t, std::int32_t> idOfRoot;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const std::int32_t root = vertexSets.find(mesh.triangles[f][0]);
    auto [it, inserted] = idOfRoot.emplace(root, out.count);
    if (inserted) ++out.count;
    out.componentOfFace[f] = it->second;
  }
  return out;
}

long long eulerCharacteristic(const TriangleMesh& mesh) {
  std::vector<char> used(mesh.vertices.size(), 0);
  std::unordered_map<std::uint64_t, char> edges;
  edges.reserve(mesh.triangles.size() * 2);
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = 1;
      edges.emplace(detail::undirectedEdgeKey(t[k], t[(k + 1) % 3]), 0);
    }
  const long long v = std::count(used.begin(), used.end(), 1);
  return v - static_cast<long long>(edges.size()) + static_cast<long long>(mesh.triangles.size());
}

}  // namespace multidir::core

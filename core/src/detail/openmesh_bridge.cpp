// OpenMesh's VectorT has a deliberately empty default constructor, and its property vectors push such
// values; GCC then warns about a copy of uninitialised memory deep inside std::vector. The values are
// always overwritten before use, so the warning is silenced for this file only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "detail/openmesh_bridge.h"

#include <string>
#include <vector>

#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core::detail {

Status toHalfEdgeMesh(const TriangleMesh& input, HalfEdgeMesh& mesh, const std::string& what) {
  for (std::size_t f = 0; f < input.triangles.size(); ++f)
    for (std::int32_t v : input.triangles[f])
      if (v < 0 || static_cast<std::size_t>(v) >= input.vertices.size())
        return Error{ErrorCode::InvalidParameter, "a vertex index is out of range", "face " + std::to_string(f)};
  // OpenMesh would refuse such faces one by one and complain on stderr; say what is wrong up front.
  const EdgeCensus census = edgeCensus(input);
  if (!census.closedOriented())
    return Error{ErrorCode::NotManifold,
                 "only a closed, consistently oriented 2-manifold can be " + what + " (" +
                     std::to_string(census.boundary) + " open, " + std::to_string(census.nonManifold) +
                     " non-manifold, " + std::to_string(census.misoriented) + " misoriented edges, " +
                     std::to_string(census.nonManifoldVertices) + " non-manifold vertices); repair the mesh first",
                 what};
  mesh.request_vertex_status();
  mesh.request_edge_status();
  mesh.request_face_status();
  mesh.reserve(input.vertices.size(), input.triangles.size() * 3 / 2, input.triangles.size());
  std::vector<HalfEdgeMesh::VertexHandle> handles;
  handles.reserve(input.vertices.size());
  for (const Vec3& v : input.vertices) handles.push_back(mesh.add_vertex(OpenMesh::Vec3d(v.x(), v.y(), v.z())));
  for (std::size_t f = 0; f < input.triangles.size(); ++f) {
    const Triangle& t = input.triangles[f];
    if (!mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid())
      return Error{ErrorCode::NotManifold,
                   "the face makes an edge or vertex non-manifold or flips orientation; repair the mesh first",
                   "face " + std::to_string(f)};
  }
  return Done{};
}

TriangleMesh fromHalfEdgeMesh(HalfEdgeMesh& mesh) {
  mesh.garbage_collection();
  TriangleMesh out;
  out.vertices.reserve(mesh.n_vertices());
  for (HalfEdgeMesh::VertexHandle v : mesh.vertices()) out.vertices.push_back(toEigen(mesh.point(v)));
  out.triangles.reserve(mesh.n_faces());
  for (HalfEdgeMesh::FaceHandle f : mesh.faces()) {
    Triangle t{};
    int k = 0;
    for (HalfEdgeMesh::VertexHandle v : mesh.fv_range(f)) t[k++] = v.idx();
    out.triangles.push_back(t);
  }
  out.resetOrigins();
  return out;
}

}  // namespace multidir::core::detail

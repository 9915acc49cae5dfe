#pragma once
// MultiDir's meshes to CGAL's Surface_mesh and back, for the booleans of cgal_*.cpp only (CGAL compiles slowly
// and stays out of every other file).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <map>

#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::assembly {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using core::TriangleMesh;
using core::Vec3;

inline SurfaceMesh toSurfaceMesh(const TriangleMesh& mesh) {
  SurfaceMesh out;
  std::vector<SurfaceMesh::Vertex_index> vertices;
  vertices.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) vertices.push_back(out.add_vertex(Kernel::Point_3(v.x(), v.y(), v.z())));
  for (const core::Triangle& t : mesh.triangles)
    out.add_face(vertices[static_cast<std::size_t>(t[0])], vertices[static_cast<std::size_t>(t[1])],
                 vertices[static_cast<std::size_t>(t[2])]);
  return out;
}

// Back to a TriangleMesh. Faces that lie on a face of `original` (same plane, checked at the centroid) keep
// its origin, so cut faces still say which joint they belong to; the holes' faces are surface faces.
inline TriangleMesh toTriangleMesh(const SurfaceMesh& mesh, const TriangleMesh& original) {
  TriangleMesh out;
  std::map<SurfaceMesh::Vertex_index, std::int32_t> index;
  for (SurfaceMesh::Vertex_index v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    index[v] = static_cast<std::int32_t>(out.vertices.size());
    out.vertices.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  for (SurfaceMesh::Face_index f : mesh.faces()) {
    core::Triangle t{};
    int k = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k < 3) t[static_cast<std::size_t>(k)] = index[v];
      ++k;
    }
    if (k == 3) out.triangles.push_back(t);
  }
  out.resetOrigins();
  // Cut faces: a face in the plane of one of the original's cap planes keeps that cap's origin.
  std::map<std::int32_t, std::pair<Vec3, double>> capPlanes;  // id -> (unit normal, offset)
  for (std::size_t f = 0; f < original.triangles.size(); ++f)
    if (original.origins[f].isCap() && !capPlanes.count(original.origins[f].index)) {
      const Vec3 n = original.areaNormal(f).normalized();
      capPlanes[original.origins[f].index] = {n, n.dot(original.corner(f, 0))};
    }
  for (std::size_t f = 0; f < out.triangles.size(); ++f) {
    const Vec3 n = out.areaNormal(f);
    if (n.norm() <= 0) continue;
    const Vec3 unit = n.normalized();
    const Vec3 centroid = (out.corner(f, 0) + out.corner(f, 1) + out.corner(f, 2)) / 3.0;
    for (const auto& [id, plane] : capPlanes)
      if (unit.dot(plane.first) > 1 - 1e-9 && std::abs(plane.first.dot(centroid) - plane.second) < 1e-6)
        out.origins[f] = core::FaceOrigin::cap(id);
  }
  return out;
}

inline bool closedOrientedSolid(const TriangleMesh& mesh) {
  return !mesh.empty() && core::edgeCensus(mesh).closedOriented() && core::signedVolume(mesh) > 0;
}

}  // namespace multidir::assembly

// The holes drilled into the parts with CGAL's corefinement (Polygon Mesh Processing). The only file that
// includes CGAL's booleans: they take most of this library's compile time.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>

#include <map>

#include "multidir/assembly/dowels.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::assembly {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using core::TriangleMesh;

namespace {

SurfaceMesh toSurfaceMesh(const TriangleMesh& mesh) {
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
TriangleMesh toTriangleMesh(const SurfaceMesh& mesh, const TriangleMesh& original) {
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

bool closedOrientedSolid(const TriangleMesh& mesh) {
  return !mesh.empty() && core::edgeCensus(mesh).closedOriented() && core::signedVolume(mesh) > 0;
}

}  // namespace

core::Result<DrilledParts> drillParts(const core::ApartPlan& plan, const DowelLayout& layout,
                                      const DowelOptions& options) {
  if (core::Status valid = validate(options); !valid) return valid.error();
  DrilledParts drilled;
  for (std::size_t p = 0; p < plan.parts.size(); ++p) {
    const TriangleMesh& part = plan.parts[p].mesh;
    // Every hole of this part in one tool (the holes keep a wall between them, so its shells are disjoint).
    TriangleMesh tools;
    for (const Dowel& dowel : layout.dowels) {
      const core::ApartJoint& joint = plan.joints[static_cast<std::size_t>(dowel.joint)];
      if (joint.upper != static_cast<int>(p) && joint.lower != static_cast<int>(p)) continue;
      const TriangleMesh tool = holeTool(dowel, joint.upper == static_cast<int>(p), options);
      const auto base = static_cast<std::int32_t>(tools.vertices.size());
      tools.vertices.insert(tools.vertices.end(), tool.vertices.begin(), tool.vertices.end());
      for (const core::Triangle& t : tool.triangles) tools.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    tools.resetOrigins();
    const std::string where = "part " + std::to_string(p + 1);
    if (tools.empty()) {
      drilled.parts.push_back(part);
      continue;
    }
    SurfaceMesh solid = toSurfaceMesh(part), tool = toSurfaceMesh(tools), result;
    bool done = false;
    try {
      done = PMP::corefine_and_compute_difference(solid, tool, result);
    } catch (const std::exception& e) {
      return core::Error{core::ErrorCode::Internal, std::string("drilling the dowel holes failed: ") + e.what(), where};
    }
    if (!done)
      return core::Error{core::ErrorCode::Internal,
                         "drilling the dowel holes failed (CGAL corefinement could not make a closed solid): please "
                         "report the model",
                         where};
    TriangleMesh out = toTriangleMesh(result, part);
    if (!closedOrientedSolid(out))
      return core::Error{core::ErrorCode::Internal,
                         "the part with its dowel holes is not a closed, oriented solid: please report the model",
                         where};
    drilled.parts.push_back(std::move(out));
  }
  for (const Dowel& dowel : layout.dowels) {
    drilled.dowels.push_back(dowelSolid(dowel, options));
    drilled.clearanceVolumeMm3 +=
        2.0 * holeVolumeMm3(dowel, options) - core::signedVolume(drilled.dowels.back());
  }
  return drilled;
}

}  // namespace multidir::assembly

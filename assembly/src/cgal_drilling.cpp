// The holes drilled into the parts with CGAL's corefinement (Polygon Mesh Processing). CGAL's booleans are
// included only by cgal_*.cpp: they take most of this library's compile time.
#include <CGAL/Polygon_mesh_processing/corefinement.h>

#include "cgal_mesh.h"
#include "multidir/assembly/dowels.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::assembly {

namespace PMP = CGAL::Polygon_mesh_processing;
using core::TriangleMesh;

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

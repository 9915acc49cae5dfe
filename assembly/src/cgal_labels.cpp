// The part numbers sunk into the parts with CGAL's corefinement (docs/apart.md, "Part numbers").
#include <CGAL/Polygon_mesh_processing/corefinement.h>

#include "cgal_mesh.h"
#include "multidir/assembly/part_labels.h"

namespace multidir::assembly {

namespace PMP = CGAL::Polygon_mesh_processing;

core::Result<std::vector<TriangleMesh>> debossLabels(const std::vector<TriangleMesh>& parts,
                                                     const std::vector<PartLabel>& labels,
                                                     const LabelOptions& options) {
  if (core::Status valid = validate(options); !valid) return valid.error();
  std::vector<TriangleMesh> out = parts;
  for (const PartLabel& label : labels) {
    if (!label.placed) continue;
    if (label.part < 0 || label.part >= static_cast<int>(parts.size()))
      return core::Error{core::ErrorCode::InvalidParameter, "the label names a part the plan does not have",
                         "label " + label.text};
    const auto p = static_cast<std::size_t>(label.part);
    // Every stroke in one tool: the strokes keep a gap between them, so its shells are disjoint.
    TriangleMesh tools;
    for (const TriangleMesh& box : labelTools(label, options)) {
      const auto base = static_cast<std::int32_t>(tools.vertices.size());
      tools.vertices.insert(tools.vertices.end(), box.vertices.begin(), box.vertices.end());
      for (const core::Triangle& t : box.triangles) tools.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    tools.resetOrigins();
    const std::string where = "part " + std::to_string(label.part + 1);
    SurfaceMesh solid = toSurfaceMesh(out[p]), tool = toSurfaceMesh(tools), result;
    bool done = false;
    try {
      done = PMP::corefine_and_compute_difference(solid, tool, result);
    } catch (const std::exception& e) {
      return core::Error{core::ErrorCode::Internal, std::string("sinking the part number failed: ") + e.what(), where};
    }
    if (!done)
      return core::Error{core::ErrorCode::Internal,
                         "sinking the part number failed (CGAL corefinement could not make a closed solid): please "
                         "report the model",
                         where};
    TriangleMesh numbered = toTriangleMesh(result, out[p]);
    if (!closedOrientedSolid(numbered))
      return core::Error{core::ErrorCode::Internal,
                         "the part with its number is not a closed, oriented solid: please report the model", where};
    out[p] = std::move(numbered);
  }
  return out;
}

}  // namespace multidir::assembly

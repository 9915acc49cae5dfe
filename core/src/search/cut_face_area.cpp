#include "search/cut_face_area.h"

namespace multidir::core::detail {

double cutFaceAreaMm2(const SearchNode& node) {
  double area = 0.0;
  for (const SearchNode* n = &node; n && n->parent; n = n->parent.get()) {
    if (!n->region) continue;
    // The engine clips a node's part with the plane id of its level (SearchEngine::cut): the region keeps
    // that cap on its underside, facing against the plane's normal.
    const auto planeId = static_cast<std::int32_t>(n->level - 1);
    const TriangleMesh& region = *n->region;
    for (std::size_t f = 0; f < region.triangles.size(); ++f) {
      if (!region.origins[f].isCap() || region.origins[f].index != planeId) continue;
      const Vec3 doubled = region.areaNormal(f);
      if (doubled.dot(n->plane.normal) < 0) area += 0.5 * doubled.norm();
    }
  }
  return area;
}

}  // namespace multidir::core::detail

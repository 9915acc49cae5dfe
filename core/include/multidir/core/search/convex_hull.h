#pragma once
// The convex hull of a point set in 3-D (quickhull), and the merged faces a solid can rest on.
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

// A closed convex polyhedron: triangles counter-clockwise seen from outside (normals point out).
struct ConvexHull {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
};

// Hull of the points. Points within a relative tolerance of a face count as on it (no sliver faces).
// Errors: EmptyMesh (fewer than 4 points), InvalidParameter (the points are coplanar or non-finite).
Result<ConvexHull> convexHull(const std::vector<Vec3>& points);

// Hull faces whose normals lie within `mergeDegrees` of each other, grouped over shared edges: the flat
// patches of a hull (a box's side is two triangles; a faceted cylinder's end is many).
struct HullFacet {
  Vec3 normal = Vec3::UnitZ();      // unit, outward: area-weighted mean of its triangles
  std::vector<Vec3> polygon;        // its outline, convex, counter-clockwise seen from outside
  double areaMm2 = 0.0;
};
std::vector<HullFacet> mergedFacets(const ConvexHull& hull, double mergeDegrees);

}  // namespace multidir::core

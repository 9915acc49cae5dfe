#pragma once
// The convex hull of a point set in 3-D (quickhull) and in the plane.
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

// Convex hull of points in the plane (Andrew's monotone chain), counter-clockwise, collinear points left out;
// fewer than three points come back as they are, sorted.
std::vector<Eigen::Vector2d> convexHull2d(std::vector<Eigen::Vector2d> points);

}  // namespace multidir::core

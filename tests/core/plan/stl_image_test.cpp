#include <gtest/gtest.h>

#include "plan/stl_image.h"

using namespace multidir::core;

namespace {

// A tetrahedron whose corner (10, 0, 0) is stored twice, the second copy a nanometre off: float cannot tell
// them apart. The faces use either copy.
TriangleMesh tetrahedronWithANearDuplicateCorner() {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, 0), Vec3(0, 0, 10), Vec3(10 + 1e-9, 0, 0)};
  mesh.triangles = {{0, 2, 1}, {0, 4, 3}, {0, 3, 2}, {1, 2, 3}};
  mesh.resetOrigins();
  return mesh;
}

}  // namespace

TEST(StlImage, CornersFloatCannotTellApartCountAsMerged) {
  EXPECT_EQ(detail::cornersMergedAtFloatPrecision(tetrahedronWithANearDuplicateCorner()), 1u);
}

TEST(StlImage, VerticesAtTheSamePointAreNotCountedAsMerged) {
  TriangleMesh mesh = tetrahedronWithANearDuplicateCorner();
  mesh.vertices[4] = Vec3(10, -0.0, 0);  // the same point as vertex 1 (-0 is 0)
  EXPECT_EQ(detail::cornersMergedAtFloatPrecision(mesh), 0u);
}

TEST(StlImage, AMergedCornerBecomesTheFirstVertexWithItsFloatPosition) {
  const detail::StlImage image = detail::stlImage(tetrahedronWithANearDuplicateCorner());
  EXPECT_EQ(image.mergedCorners, 1u);
  EXPECT_EQ(image.droppedFaces, 0u);
  ASSERT_EQ(image.mesh.vertices.size(), 4u);
  EXPECT_EQ(image.mesh.vertices[1], Vec3(10, 0, 0));
  const std::vector<Triangle> expected{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  EXPECT_EQ(image.mesh.triangles, expected);
}

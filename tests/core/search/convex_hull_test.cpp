#include <gtest/gtest.h>

#include <cmath>

#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/search/convex_hull.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

TriangleMesh asMesh(const ConvexHull& hull) {
  TriangleMesh mesh;
  mesh.vertices = hull.vertices;
  mesh.triangles = hull.triangles;
  mesh.resetOrigins();
  return mesh;
}

// Every point lies on or below every hull face's plane, up to the hull's relative tolerance (slivers, whose
// normals rounding decides, aside).
void expectContains(const ConvexHull& hull, const std::vector<Vec3>& points) {
  double scale = 1.0;
  for (const Vec3& p : points) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  for (const Triangle& t : hull.triangles) {
    const Vec3 an = (hull.vertices[t[1]] - hull.vertices[t[0]]).cross(hull.vertices[t[2]] - hull.vertices[t[0]]);
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, (hull.vertices[t[(k + 1) % 3]] - hull.vertices[t[k]]).norm());
    // A sliver (coplanar corners of a flat side, split thinly): its normal is what rounding makes it.
    if (an.norm() / longest < 1e-3 * scale) continue;
    const Vec3 n = an.normalized();
    for (const Vec3& p : points) ASSERT_LE(n.dot(p - hull.vertices[t[0]]), 1e-5 * scale) << "area " << an.norm() / 2 << " corners " << hull.vertices[t[0]].transpose() << " / " << hull.vertices[t[1]].transpose() << " / " << hull.vertices[t[2]].transpose();
  }
}

}  // namespace

TEST(ConvexHull, OfABoxIsTheBoxWithItsInnerPointsLeftOut) {
  TriangleMesh box = multidir::test::makeBox(Vec3(0, 0, 0), Vec3(10, 20, 30));
  std::vector<Vec3> points = box.vertices;
  points.emplace_back(5, 5, 5);   // inside
  points.emplace_back(10, 10, 15);  // on a face
  auto hull = convexHull(points);
  ASSERT_TRUE(hull.ok()) << hull.error().describe();
  EXPECT_EQ(hull->vertices.size(), 8u);
  EXPECT_EQ(hull->triangles.size(), 12u);
  const TriangleMesh mesh = asMesh(*hull);
  EXPECT_TRUE(edgeCensus(mesh).closedOriented());
  EXPECT_NEAR(signedVolume(mesh), 6000.0, 1e-9);
  expectContains(*hull, points);
}

TEST(ConvexHull, OfAnIcosphereKeepsEveryVertexAndItsVolume) {
  const TriangleMesh sphere = multidir::test::makeIcosphere(Vec3(1, 2, 3), 10.0, 2);
  auto hull = convexHull(sphere.vertices);
  ASSERT_TRUE(hull.ok()) << hull.error().describe();
  EXPECT_EQ(hull->vertices.size(), sphere.vertices.size());
  const TriangleMesh mesh = asMesh(*hull);
  EXPECT_TRUE(edgeCensus(mesh).closedOriented());
  EXPECT_NEAR(signedVolume(mesh), signedVolume(sphere), 1e-6 * signedVolume(sphere));
}

TEST(ConvexHull, OfSharedModelsIsClosedAndContainsEveryVertex) {
  for (const char* name : {"fandisk.off", "bunny.off"}) {
    const TriangleMesh model = multidir::test::loadSharedModel(name);
    auto hull = convexHull(model.vertices);
    ASSERT_TRUE(hull.ok()) << name << ": " << hull.error().describe();
    const TriangleMesh mesh = asMesh(*hull);
    EXPECT_TRUE(edgeCensus(mesh).closedOriented()) << name;
    EXPECT_GE(signedVolume(mesh), signedVolume(model)) << name;
    expectContains(*hull, model.vertices);
  }
}

TEST(ConvexHull, RefusesFlatPointSetsWithAClearError) {
  std::vector<Vec3> square = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 0.5, 0)};
  auto hull = convexHull(square);
  ASSERT_FALSE(hull.ok());
  EXPECT_EQ(hull.error().code, ErrorCode::InvalidParameter);
  EXPECT_NE(hull.error().message.find("plane"), std::string::npos);
  EXPECT_FALSE(convexHull({Vec3(0, 0, 0), Vec3(1, 0, 0)}).ok());
}

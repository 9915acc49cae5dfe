#include <gtest/gtest.h>

#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/mesh/mesh_resolution.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

// Every vertex moved a few micrometres along z by a fixed pattern: no collapse of such a surface is free.
TriangleMesh roughened(TriangleMesh mesh, double amplitudeMm) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    mesh.vertices[v].z() += amplitudeMm * (static_cast<double>((v * 7919) % 11) / 5.0 - 1.0);
  return mesh;
}

// Two boxes that touch at one corner, welded there: every edge has its two faces, but the shared vertex has
// two fans.
TriangleMesh boxesTouchingAtACorner() {
  TriangleMesh mesh = multidir::test::makeBox(Vec3::Zero(), Vec3(10, 10, 10));
  const TriangleMesh second = multidir::test::makeBox(Vec3(10, 10, 10), Vec3(20, 20, 20));
  const auto offset = static_cast<std::int32_t>(mesh.vertices.size());
  std::int32_t cornerOfFirst = -1;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (mesh.vertices[v] == Vec3(10, 10, 10)) cornerOfFirst = static_cast<std::int32_t>(v);
  mesh.vertices.insert(mesh.vertices.end(), second.vertices.begin(), second.vertices.end());
  for (Triangle t : second.triangles) {
    for (std::int32_t& v : t) v = second.vertices[v] == Vec3(10, 10, 10) ? cornerOfFirst : v + offset;
    mesh.triangles.push_back(t);
  }
  mesh.resetOrigins();
  return mesh;
}

}  // namespace

TEST(Decimated, ASubdividedModelGoesBackToAboutItsOwnFacesWithinTheTolerance) {
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  const auto fine = subdivided(kitten, 2);
  ASSERT_TRUE(fine.ok());
  const auto proxy = decimated(*fine, 50000, 0.01);
  ASSERT_TRUE(proxy.ok()) << proxy.error().describe();
  EXPECT_LE(proxy->mesh.faceCount(), kitten.faceCount() * 11 / 10);
  EXPECT_TRUE(edgeCensus(proxy->mesh).closedOriented());
  EXPECT_LT(proxy->volumeChangePercent, 0.01);
}

TEST(Decimated, ARoughSurfaceStopsAtTheFaceCapClosedAndWithItsVolume) {
  const auto fine = subdivided(multidir::test::loadSharedModel("bunny.off"), 1);
  ASSERT_TRUE(fine.ok());
  const TriangleMesh rough = roughened(*fine, 0.02);
  const auto proxy = decimated(rough, 8000, 0.001);
  ASSERT_TRUE(proxy.ok()) << proxy.error().describe();
  EXPECT_LE(proxy->mesh.faceCount(), 8000u);
  EXPECT_GE(proxy->mesh.faceCount(), 7000u);  // the cap, not the tolerance, stopped it
  EXPECT_TRUE(edgeCensus(proxy->mesh).closedOriented());
  EXPECT_LE(proxy->volumeChangePercent, 0.5);
}

TEST(Decimated, TheSameMeshGivesTheSameProxy) {
  const auto fine = subdivided(multidir::test::loadSharedModel("fertility.off"), 1);
  ASSERT_TRUE(fine.ok());
  const auto first = decimated(*fine, 5000, 0.0);
  const auto second = decimated(*fine, 5000, 0.0);
  ASSERT_TRUE(first.ok() && second.ok());
  EXPECT_EQ(first->mesh.triangles, second->mesh.triangles);
  EXPECT_EQ(first->mesh.vertices, second->mesh.vertices);
}

TEST(Decimated, TheProxyIsTheSameBitForBitForAnyThreadCount) {
  // 40,000 faces: several blocks of the parallel loops, and passes both above and below the face cap.
  const auto fine = subdivided(multidir::test::loadSharedModel("kitten.off"), 1);
  ASSERT_TRUE(fine.ok());
  const auto one = decimated(*fine, 8000, 0.01, 0.5, 1);
  ASSERT_TRUE(one.ok()) << one.error().describe();
  for (const int threads : {2, 3}) {
    const auto many = decimated(*fine, 8000, 0.01, 0.5, threads);
    ASSERT_TRUE(many.ok()) << many.error().describe();
    EXPECT_EQ(many->mesh.vertices, one->mesh.vertices) << threads << " threads";
    EXPECT_EQ(many->mesh.triangles, one->mesh.triangles) << threads << " threads";
    EXPECT_EQ(many->volumeChangePercent, one->volumeChangePercent) << threads << " threads";
  }
}

TEST(Decimated, AMeshWithAFlippedFaceIsRefusedAsMisoriented) {
  TriangleMesh flipped = multidir::test::makeBox(Vec3::Zero(), Vec3(10, 10, 10));
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  const auto refused = decimated(flipped, 100, 0.0);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::NotManifold);
  EXPECT_NE(refused.error().message.find("3 misoriented"), std::string::npos) << refused.error().message;
}

TEST(Decimated, TwoSolidsTouchingAtAVertexAreRefusedAsNonManifold) {
  const auto refused = decimated(boxesTouchingAtACorner(), 100, 0.0);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::NotManifold);
  EXPECT_NE(refused.error().message.find("1 non-manifold vertices"), std::string::npos) << refused.error().message;
}

TEST(Decimated, AFaceNamingAMissingVertexIsRefused) {
  TriangleMesh broken = multidir::test::makeBox(Vec3::Zero(), Vec3(10, 10, 10));
  broken.triangles[5][0] = 99;
  const auto refused = decimated(broken, 100, 0.0);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::InvalidParameter);
  EXPECT_NE(refused.error().message.find("face 5 names vertex 99"), std::string::npos) << refused.error().message;
}

TEST(Decimated, AnOpenMeshIsRefusedWithWhatIsWrong) {
  TriangleMesh open = multidir::test::makeBox(Vec3::Zero(), Vec3(10, 10, 10));
  open.triangles.pop_back();
  open.resetOrigins();
  const auto refused = decimated(open, 100, 0.0);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::NotManifold);
  EXPECT_NE(refused.error().message.find("open"), std::string::npos) << refused.error().message;
}

TEST(Decimated, AbsurdTargetsAndTolerancesAreRefused) {
  const TriangleMesh box = multidir::test::makeBox(Vec3::Zero(), Vec3(10, 10, 10));
  EXPECT_EQ(decimated(box, 10, 0.0).error().code, ErrorCode::InvalidParameter);
  EXPECT_EQ(decimated(box, 1000, -1.0).error().code, ErrorCode::InvalidParameter);
  EXPECT_EQ(decimated(box, 1000, 0.0, 0.5, -1).error().code, ErrorCode::InvalidParameter);
}

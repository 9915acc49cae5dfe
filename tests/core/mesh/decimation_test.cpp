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
}

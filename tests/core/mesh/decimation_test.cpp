#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

// The distance from p to the triangle (a, b, c): to its plane when p projects inside it, else to the nearest
// of its edges.
double distanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto toSegment = [&](const Vec3& from, const Vec3& to) {
    const Vec3 d = to - from;
    const double t = d.squaredNorm() > 0 ? std::clamp((p - from).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    return (from + t * d - p).norm();
  };
  const Vec3 n = (b - a).cross(c - a);
  if (n.squaredNorm() > 0) {
    const bool inside = n.dot((b - a).cross(p - a)) >= 0 && n.dot((c - b).cross(p - b)) >= 0 &&
                        n.dot((a - c).cross(p - c)) >= 0;
    if (inside) return std::abs(n.normalized().dot(p - a));
  }
  return std::min({toSegment(a, b), toSegment(b, c), toSegment(c, a)});
}

// The largest distance from every step-th vertex of `mesh` to the surface of `model` (by brute force).
double largestDistanceOfVertices(const TriangleMesh& mesh, const TriangleMesh& model, std::size_t step) {
  double largest = 0.0;
  for (std::size_t v = 0; v < mesh.vertices.size(); v += step) {
    double nearest = INFINITY;
    for (std::size_t f = 0; f < model.triangles.size(); ++f)
      nearest = std::min(nearest, distanceToTriangle(mesh.vertices[v], model.corner(f, 0), model.corner(f, 1),
                                                     model.corner(f, 2)));
    largest = std::max(largest, nearest);
  }
  return largest;
}

}  // namespace

TEST(Decimated, ASubdividedModelGoesBackToAboutItsOwnFacesWithinTheTolerance) {
  // 160,000 faces and 80,000 vertices: the first passes collapse in slabs on threads.
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  const auto fine = subdivided(kitten, 2);
  ASSERT_TRUE(fine.ok());
  const auto proxy = decimated(*fine, 50000, 0.01);
  ASSERT_TRUE(proxy.ok()) << proxy.error().describe();
  EXPECT_LE(proxy->mesh.faceCount(), kitten.faceCount() * 11 / 10);
  EXPECT_TRUE(edgeCensus(proxy->mesh).closedOriented());
  EXPECT_LT(proxy->volumeChangePercent, 0.01);
  // The subdivision kept the kitten's surface, so the proxy's corners stay on it to within a few times the
  // tolerance (a root mean square over the faces around each collapse, not a bound on every point).
  EXPECT_LT(largestDistanceOfVertices(proxy->mesh, kitten, 7), 0.05);
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

TEST(Decimated, TheProxyOfAMeshCollapsedInSlabsIsTheSameBitForBitOnOneTwoAndFourThreads) {
  // 160,000 faces, 80,000 vertices: two slabs and three shifted ones, and none of the collapses free.
  const auto fine = subdivided(multidir::test::loadSharedModel("kitten.off"), 2);
  ASSERT_TRUE(fine.ok());
  const TriangleMesh rough = roughened(*fine, 0.02);
  const auto one = decimated(rough, 20000, 0.01, 0.5, 1);
  ASSERT_TRUE(one.ok()) << one.error().describe();
  for (const int threads : {2, 4}) {
    const auto many = decimated(rough, 20000, 0.01, 0.5, threads);
    ASSERT_TRUE(many.ok()) << many.error().describe();
    EXPECT_EQ(many->mesh.vertices, one->mesh.vertices) << threads << " threads";
    EXPECT_EQ(many->mesh.triangles, one->mesh.triangles) << threads << " threads";
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

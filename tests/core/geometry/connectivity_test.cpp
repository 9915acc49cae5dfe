#include "multidir/core/geometry/connectivity.h"

#include <gtest/gtest.h>

#include "core/geometry/support_clip_shapes.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "support/primitives.h"

namespace multidir::core {
namespace {

const Plane kFloor{Vec3::UnitZ(), 0.0};

TEST(Connectivity, OneShellIsOneSolid) {
  const TriangleMesh box = test::makeBox(Vec3(0, 0, 0), Vec3(1, 2, 3));
  const auto solids = connectedSolids(box).value();
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_EQ(solids[0].faceCount(), box.faceCount());
  EXPECT_NEAR(signedVolume(solids[0]), 6.0, 1e-12);
}

TEST(Connectivity, ClipThatSeparatesTheArmsGivesTwoSolidsAboveAndOneBelow) {
  const Plane cut = Plane::throughPoint(Vec3::UnitZ(), Vec3(0, 0, 25));
  const ClipResult clip = clipByPlane(test::makeU(), cut, 1).value();
  const ClipSolids solids = connectedSolids(clip).value();
  ASSERT_EQ(solids.above.size(), 2u);
  ASSERT_EQ(solids.below.size(), 1u);
  for (const TriangleMesh& arm : solids.above) {
    EXPECT_TRUE(edgeCensus(arm).closedOriented());
    EXPECT_NEAR(signedVolume(arm), 10.0 * 10.0 * 15.0, 1e-9);
    EXPECT_FALSE(touchesPlatform(arm, kFloor));
    EXPECT_TRUE(touchesPlatform(arm, cut));  // each arm rests on the cut
  }
  EXPECT_TRUE(touchesPlatform(solids.below[0], kFloor));
}

TEST(Connectivity, CuttingOffTheHooksArmLeavesItsDropFloating) {
  // The hook: a stem from z = 0 to 60, an arm on top (z 50..60) and a drop hanging from the arm's end down to
  // z = 20. Cut at z = 45, the stem still stands on the platform while the drop's stub floats (Criterion II).
  const TriangleMesh hook = test::makeHook(10.0);
  const ClipResult clip = clipByPlane(hook, Plane::throughPoint(Vec3::UnitZ(), Vec3(0, 0, 45)), 3).value();
  const auto below = connectedSolidsOnPlatform(clip.below, kFloor).value();
  ASSERT_EQ(below.size(), 2u);
  int standing = 0;
  for (const PlacedSolid& s : below) {
    standing += s.touchesPlatform ? 1 : 0;
    EXPECT_NEAR(signedVolume(s.mesh), s.touchesPlatform ? 10.0 * 45.0 * 10.0 : 10.0 * 25.0 * 10.0, 1e-9);
  }
  EXPECT_EQ(standing, 1);
  EXPECT_EQ(connectedSolids(clip.above).value().size(), 1u);
}

TEST(Connectivity, SolidsKeepTheirFacesOriginsAndOnlyTheirVertices) {
  const TriangleMesh twoBoxes =
      test::merge(test::makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)), test::makeBox(Vec3(3, 0, 0), Vec3(4, 1, 2)));
  const auto solids = connectedSolids(twoBoxes).value();
  ASSERT_EQ(solids.size(), 2u);
  EXPECT_EQ(solids[0].vertexCount(), 8u);
  EXPECT_EQ(solids[1].vertexCount(), 8u);
  EXPECT_EQ(solids[0].origins.front(), FaceOrigin::surface(0));
  EXPECT_EQ(solids[1].origins.front(), FaceOrigin::surface(12));
  EXPECT_NEAR(signedVolume(solids[1]), 2.0, 1e-12);
}

TEST(Connectivity, ACavityStaysWithTheSolidAroundIt) {
  TriangleMesh cavity = test::makeBox(Vec3(1, 1, 1), Vec3(2, 2, 2));
  for (Triangle& t : cavity.triangles) std::swap(t[1], t[2]);  // facing inwards: the wall of a void
  const TriangleMesh hollow = test::merge(test::makeBox(Vec3(0, 0, 0), Vec3(3, 3, 3)), cavity);
  const TriangleMesh withNeighbour = test::merge(hollow, test::makeBox(Vec3(5, 0, 0), Vec3(6, 1, 1)));
  const auto solids = connectedSolids(withNeighbour).value();
  ASSERT_EQ(solids.size(), 2u);
  EXPECT_NEAR(signedVolume(solids[0]), 27.0 - 1.0, 1e-12);
  EXPECT_EQ(solids[0].faceCount(), 24u);
}

TEST(Connectivity, TouchesPlatformWithinTheToleranceOnly) {
  const TriangleMesh box = test::makeBox(Vec3(0, 0, 0.0005), Vec3(1, 1, 1));
  EXPECT_TRUE(touchesPlatform(box, kFloor));         // 0.5 um above: within 1 um
  EXPECT_FALSE(touchesPlatform(box, kFloor, 1e-4));  // but not within 0.1 um
  EXPECT_FALSE(touchesPlatform(test::makeBox(Vec3(0, 0, 0.1), Vec3(1, 1, 1)), kFloor));
  EXPECT_FALSE(touchesPlatform(TriangleMesh{}, kFloor));
  EXPECT_NEAR(heightAbove(box, kFloor), 0.0005, 1e-15);
}

TEST(Connectivity, PlatformMayLookAnyWay) {
  // Up is +Y for the shared models: a platform under the box along +Y.
  const TriangleMesh box = test::makeBox(Vec3(0, 2, 0), Vec3(1, 3, 1));
  EXPECT_TRUE(touchesPlatform(box, Plane{Vec3::UnitY(), 2.0}));
  EXPECT_FALSE(touchesPlatform(box, Plane{Vec3::UnitY(), 0.0}));
}

TEST(Connectivity, RejectsOutOfRangeIndices) {
  TriangleMesh box = test::makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1));
  box.triangles[0][0] = -1;
  EXPECT_EQ(connectedSolids(box).error().code, ErrorCode::InvalidParameter);
  EXPECT_TRUE(connectedSolids(TriangleMesh{}).value().empty());
}

}  // namespace
}  // namespace multidir::core

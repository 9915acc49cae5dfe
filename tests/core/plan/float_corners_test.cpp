// Which corners a binary STL would merge: the search asks this of both sides of every clip, so it looks only
// near the cutting plane. These tests hold that shortcut to the full count on real clips, including clips
// whose cut points do fall onto each other in float.
#include <gtest/gtest.h>

#include <cstddef>

#include "multidir/core/geometry/clipping.h"
#include "plan/stl_image.h"
#include "support/test_models.h"

namespace multidir::core {
namespace {

struct Counts {
  std::size_t nearPlane = 0, everywhere = 0;
};

Counts mergedOnBothSides(const TriangleMesh& solid, const Plane& plane) {
  const Result<ClipResult> clipped = clipByPlane(solid, plane, 0);
  EXPECT_TRUE(clipped.ok()) << clipped.error().describe();
  if (!clipped.ok()) return {};
  Counts counts;
  for (const TriangleMesh* side : {&clipped->below, &clipped->above}) {
    counts.nearPlane += detail::cornersMergedAtFloatPrecisionNearPlane(*side, plane, kDefaultPlaneToleranceMm);
    counts.everywhere += detail::cornersMergedAtFloatPrecision(*side);
  }
  return counts;
}

// A tetrahedron with a sliver face: edges AB and AC leave A 4 um apart at their far ends, 20 mm from the
// origin, where float's step is 1.9 um. Its own corners stay apart in float; a plane across both edges near A
// cuts them at points closer than that step, which a binary STL would merge.
TriangleMesh sliverTetrahedron() {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 20, 0), Vec3(10, 20, 0), Vec3(10, 20 + 4e-6, 0), Vec3(5, 25, 10)};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  mesh.resetOrigins();
  return mesh;
}

TEST(FloatCorners, TheSliverTetrahedronKeepsItsCornersApartInFloat) {
  EXPECT_EQ(detail::cornersMergedAtFloatPrecision(sliverTetrahedron()), 0u);
}

TEST(FloatCorners, NearThePlaneCountsWhatTheWholeMeshCountsWhereCutPointsMerge) {
  std::size_t mergingCuts = 0;
  for (double x = 0.5; x < 10.0; x += 0.5) {
    const Counts counts = mergedOnBothSides(sliverTetrahedron(), Plane{Vec3::UnitX(), x});
    EXPECT_EQ(counts.nearPlane, counts.everywhere) << "plane x = " << x;
    if (counts.everywhere > 0) ++mergingCuts;
  }
  EXPECT_GT(mergingCuts, 0u) << "no cut merged corners: the test no longer exercises the count";
}

TEST(FloatCorners, NearThePlaneCountsWhatTheWholeMeshCountsOnCutsOfARealModel) {
  const TriangleMesh bunny = test::loadSharedModel("bunny.off");
  ASSERT_EQ(detail::cornersMergedAtFloatPrecision(bunny), 0u);
  for (const double offset : {-40.0, 0.0, 35.5, 80.25}) {
    const Vec3 normal = Vec3(0.3, 1.0, 0.2).normalized();
    const Counts counts = mergedOnBothSides(bunny, Plane{normal, normal.dot(Vec3(0, 100, 0)) + offset});
    EXPECT_EQ(counts.nearPlane, counts.everywhere) << "offset " << offset;
  }
}

TEST(FloatCorners, NearThePlaneCountsNothingForACutFarFromEveryVertex) {
  const TriangleMesh bunny = test::loadSharedModel("bunny.off");
  const Counts counts = mergedOnBothSides(bunny, Plane{Vec3::UnitY(), 40.00037});
  EXPECT_EQ(counts.everywhere, 0u);
  EXPECT_EQ(counts.nearPlane, 0u);
}

}  // namespace
}  // namespace multidir::core

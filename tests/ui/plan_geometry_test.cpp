// Where the plan view puts regions and planes: a box cut twice across its height, regions stacked.
#include <gtest/gtest.h>

#include <cmath>

#include "multidir/core/geometry/clipping.h"
#include "support/primitives.h"
#include "ui/common/region_palette.h"
#include "ui/viewer/plan_geometry.h"

namespace multidir::ui {
namespace {

// A 10 x 10 x 30 box cut at z = 20 (plane 0) and then z = 10 (plane 1): bottom, middle, top in printing
// order, each printed along +Z.
core::Decomposition stackedBox() {
  core::TriangleMesh box = test::makeBox({0, 0, 0}, {10, 10, 30});
  box.resetOrigins();
  const core::Plane upper{core::Vec3::UnitZ(), 20.0};
  const core::Plane lower{core::Vec3::UnitZ(), 10.0};
  const core::Result<core::ClipResult> first = core::clipByPlane(box, upper, 0);
  EXPECT_TRUE(first.ok());
  const core::Result<core::ClipResult> second = core::clipByPlane(first->below, lower, 1);
  EXPECT_TRUE(second.ok());
  core::Decomposition plan;
  plan.clippingPlanes = {upper, lower};
  core::Region bottom, middle, top;
  bottom.mesh = second->below;
  middle.mesh = second->above;
  middle.clippingIndex = 1;
  middle.basePlane = lower;
  top.mesh = first->above;
  top.clippingIndex = 0;
  top.basePlane = upper;
  plan.regions = {bottom, middle, top};
  return plan;
}

TEST(PlanGeometry, EachRegionStandsOnTheRegionThatCarriesItsBaseCap) {
  const std::vector<int> parents = supportingRegions(stackedBox());
  EXPECT_EQ(parents, (std::vector<int>{-1, 0, 1}));
}

TEST(PlanGeometry, ExplodedRegionsMoveWithTheRegionBelowThem) {
  const std::vector<core::Vec3> offsets = explodeOffsets(stackedBox(), 4.0);
  ASSERT_EQ(offsets.size(), 3u);
  EXPECT_TRUE(offsets[0].isZero());
  EXPECT_TRUE(offsets[1].isApprox(core::Vec3(0, 0, 4)));
  EXPECT_TRUE(offsets[2].isApprox(core::Vec3(0, 0, 8)));
}

TEST(PlanGeometry, ZeroExplodeDistanceMovesNothing) {
  for (const core::Vec3& offset : explodeOffsets(stackedBox(), 0.0)) EXPECT_TRUE(offset.isZero());
}

TEST(PlanGeometry, PlaneDiscIsCentredOnTheCutAndCoversIt) {
  const std::vector<PlaneDisc> discs = planeDiscs(stackedBox());
  ASSERT_EQ(discs.size(), 2u);
  EXPECT_TRUE(discs[0].center.isApprox(core::Vec3(5, 5, 20), 1e-9));
  EXPECT_TRUE(discs[1].center.isApprox(core::Vec3(5, 5, 10), 1e-9));
  EXPECT_NEAR(discs[0].radiusMm, kPlaneDiscMargin * std::sqrt(50.0), 1e-9);
  EXPECT_TRUE(discs[0].normal.isApprox(core::Vec3::UnitZ()));
}

TEST(RegionPalette, TwelveNeighbouringRegionsGetDistinctColours) {
  for (int i = 0; i < 12; ++i) {
    for (int j = i + 1; j < 12; ++j) EXPECT_NE(regionColor(i).rgb(), regionColor(j).rgb()) << i << " " << j;
  }
  EXPECT_GE(kRegionColorCount, 12);
}

}  // namespace
}  // namespace multidir::ui

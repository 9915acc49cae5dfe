// How a solid stands on the bed: the hull patch that touches it and the centre of mass's margin inside it
// (docs/search.md, "The pose search").
#include <gtest/gtest.h>

#include <cmath>

#include "multidir/core/common/units.h"
#include "multidir/core/search/contact_patch.h"
#include "support/primitives.h"

using namespace multidir::core;

namespace {

ConvexHull hullOf(const std::vector<Vec3>& points) {
  auto hull = convexHull(points);
  EXPECT_TRUE(hull.ok()) << hull.error().describe();
  return hull.ok() ? *hull : ConvexHull{};
}

// A convex solid is its own hull: its triangles, outward, make a closed mesh.
TriangleMesh solidOf(const ConvexHull& hull) {
  TriangleMesh mesh;
  mesh.vertices = hull.vertices;
  mesh.triangles = hull.triangles;
  return mesh;
}

// A 40 x 40 block, 10 high, whose underside is a pyramid 0.5 mm deep: its faces slope by 1.4 degrees, within
// the 3 degrees that once made them one "flat" patch, but the bed touches only the apex.
std::vector<Vec3> blockOnAShallowPyramid() {
  return {Vec3(-20, -20, 0.5), Vec3(20, -20, 0.5), Vec3(20, 20, 0.5), Vec3(-20, 20, 0.5), Vec3(0, 0, 0),
          Vec3(-20, -20, 10),  Vec3(20, -20, 10),  Vec3(20, 20, 10),  Vec3(-20, 20, 10)};
}

}  // namespace

TEST(ContactPatch, OfABoxOnItsBaseIsTheBaseWithTheCentreHalfItsShortSideInside) {
  const TriangleMesh box = multidir::test::makeBox(Vec3(0, 0, 0), Vec3(10, 20, 30));
  const ContactPatch patch = contactPatch(hullOf(box.vertices), Vec3(0, 0, 3), solidCentreOfMass(box));
  EXPECT_NEAR(patch.areaMm2, 200.0, 1e-9);
  EXPECT_NEAR(patch.stabilityMarginMm, 5.0, 1e-9);
  EXPECT_EQ(patch.outline.size(), 4u);
  for (const Vec3& corner : patch.outline) EXPECT_NEAR(corner.z(), 0.0, 1e-9);
  EXPECT_TRUE(patch.stands());
}

TEST(ContactPatch, OfABoxOnACornerIsAPointThatTipsOver) {
  const TriangleMesh box = multidir::test::makeBox(Vec3(0, 0, 0), Vec3(10, 20, 30));
  const ContactPatch patch = contactPatch(hullOf(box.vertices), Vec3(1, 1, 1), solidCentreOfMass(box));
  EXPECT_EQ(patch.outline.size(), 1u);
  EXPECT_EQ(patch.areaMm2, 0.0);
  EXPECT_LT(patch.stabilityMarginMm, 0.0);
  EXPECT_FALSE(patch.stands());
}

TEST(ContactPatch, OfABoxOnAnEdgeHasNoAreaEvenWithTheCentreAboveIt) {
  const TriangleMesh box = multidir::test::makeBox(Vec3(0, 0, 0), Vec3(10, 10, 30));
  // Up along the x-y diagonal: the box balances on its vertical edge at x = y = 0.
  const ContactPatch patch = contactPatch(hullOf(box.vertices), Vec3(1, 1, 0), solidCentreOfMass(box));
  EXPECT_EQ(patch.outline.size(), 2u);
  EXPECT_EQ(patch.areaMm2, 0.0);
  EXPECT_NEAR(patch.stabilityMarginMm, 0.0, 1e-9);  // the centre projects onto the edge itself
  EXPECT_FALSE(patch.stands());
}

TEST(ContactPatch, CornersWithinTheToleranceOfTheBedTouchIt) {
  // A 10 x 10 x 5 block whose underside rises towards +y; the far corners touch while they rise less than the
  // squashed first layer fills.
  auto block = [](double rise) {
    return std::vector<Vec3>{Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, rise), Vec3(10, 10, rise),
                             Vec3(0, 0, 5), Vec3(10, 0, 5), Vec3(0, 10, 5),    Vec3(10, 10, 5)};
  };
  const Vec3 centre(5, 5, 2.5);
  EXPECT_NEAR(contactPatch(hullOf(block(0.9 * kContactToleranceMm)), Vec3::UnitZ(), centre).areaMm2, 100.0, 1e-6);
  const ContactPatch onEdge = contactPatch(hullOf(block(1.1 * kContactToleranceMm)), Vec3::UnitZ(), centre);
  EXPECT_EQ(onEdge.areaMm2, 0.0);
  EXPECT_FALSE(onEdge.stands());
}

TEST(SolidCentreOfMass, OfABoxIsItsCentre) {
  const TriangleMesh box = multidir::test::makeBox(Vec3(2, 4, 6), Vec3(12, 24, 36));
  EXPECT_TRUE(solidCentreOfMass(box).isApprox(Vec3(7, 14, 21), 1e-12));
}

TEST(StandingPatches, NeverBalanceOnTheApexOfANearlyFlatUnderside) {
  const ConvexHull hull = hullOf(blockOnAShallowPyramid());
  const Vec3 centre = solidCentreOfMass(solidOf(hull));
  const ContactPatch onApex = contactPatch(hull, Vec3::UnitZ(), centre);
  EXPECT_EQ(onApex.areaMm2, 0.0);
  const std::vector<ContactPatch> patches = standingPatches(hull, centre, 3.0);
  ASSERT_FALSE(patches.empty());
  for (const ContactPatch& patch : patches) {
    EXPECT_TRUE(patch.stands());
    // Standing on the patch's plane, the bed touches exactly that patch.
    const ContactPatch again = contactPatch(hull, patch.up, centre);
    EXPECT_NEAR(again.areaMm2, patch.areaMm2, 1e-9);
    EXPECT_NEAR(again.stabilityMarginMm, patch.stabilityMarginMm, 1e-9);
    EXPECT_LT(patch.up.dot(Vec3::UnitZ()), std::cos(0.5 * kPi / 180)) << "balancing on the apex";
  }
}

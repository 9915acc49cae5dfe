// Picking on the platform: where a click's ray meets the platform disc, and the rotation axis through two
// picked points.
#include <gtest/gtest.h>

#include <cmath>

#include "multidir/core/common/units.h"
#include "ui/viewer/platform_picker.h"

namespace multidir::ui {
namespace {

// A 40 mm disc at height 5 under +Z, centred on (10, 0, 5).
PlatformDisc zUpDisc() {
  PlatformDisc disc;
  disc.center = core::Vec3(10, 0, 5);
  disc.normal = core::Vec3::UnitZ();
  disc.radiusMm = 40.0;
  return disc;
}

TEST(PlatformPicker, RayFromAboveHitsTheDiscWhereItCrossesThePlane) {
  // From (20, 10, 105) down and slightly sideways: reaches z = 5 after 100 mm of drop.
  const PlatformHit hit = hitPlatform(zUpDisc(), core::Vec3(20, 10, 105), core::Vec3(0.1, -0.05, -1.0));
  ASSERT_EQ(hit.kind, PlatformHitKind::Hit);
  EXPECT_TRUE(hit.point.isApprox(core::Vec3(30, 5, 5), 1e-12));
}

TEST(PlatformPicker, RayMeetingThePlaneBeyondTheRimMissesTheDisc) {
  const PlatformHit hit = hitPlatform(zUpDisc(), core::Vec3(100, 0, 50), core::Vec3(0, 0, -3));
  EXPECT_EQ(hit.kind, PlatformHitKind::OutsideDisc);
  EXPECT_TRUE(hit.point.isApprox(core::Vec3(100, 0, 5), 1e-12));
}

TEST(PlatformPicker, RayAlongThePlatformPlaneIsParallel) {
  EXPECT_EQ(hitPlatform(zUpDisc(), core::Vec3(0, 0, 20), core::Vec3(1, 1, 0)).kind, PlatformHitKind::Parallel);
  EXPECT_EQ(hitPlatform(zUpDisc(), core::Vec3(0, 0, 20), core::Vec3::Zero()).kind, PlatformHitKind::Parallel);
}

TEST(PlatformPicker, PlatformBehindTheRayIsNotHit) {
  // Looking up from above the platform.
  EXPECT_EQ(hitPlatform(zUpDisc(), core::Vec3(10, 0, 20), core::Vec3(0, 0, 1)).kind, PlatformHitKind::Behind);
}

TEST(PlatformPicker, TiltedPlatformIsHitInItsOwnPlane) {
  PlatformDisc disc;
  disc.normal = core::Vec3(0, 1, 1).normalized();
  disc.radiusMm = 10.0;
  const PlatformHit hit = hitPlatform(disc, core::Vec3(3, 20, 20), -disc.normal);
  ASSERT_EQ(hit.kind, PlatformHitKind::Hit);
  EXPECT_NEAR(hit.point.dot(disc.normal), 0.0, 1e-12);
  EXPECT_NEAR(hit.point.x(), 3.0, 1e-12);
}

TEST(PlatformPicker, AxisRunsFromTheFirstPointToTheSecondWithinThePlatformPlane) {
  // The second point lies 2 mm above the platform: that part of the difference is dropped.
  const std::optional<core::Vec3> axis =
      axisThroughPoints(core::Vec3::UnitZ(), core::Vec3(0, 0, 5), core::Vec3(-3, 4, 7));
  ASSERT_TRUE(axis.has_value());
  EXPECT_TRUE(axis->isApprox(core::Vec3(-0.6, 0.8, 0), 1e-12));
}

TEST(PlatformPicker, PointsLessThanAMillimetreApartGiveNoAxis) {
  EXPECT_FALSE(axisThroughPoints(core::Vec3::UnitZ(), core::Vec3(0, 0, 0), core::Vec3(0.6, 0.6, 0)).has_value());
  // Far apart, but only along the normal: no direction in the plane.
  EXPECT_FALSE(axisThroughPoints(core::Vec3::UnitZ(), core::Vec3(0, 0, 0), core::Vec3(0, 0, 30)).has_value());
  EXPECT_TRUE(axisThroughPoints(core::Vec3::UnitZ(), core::Vec3(0, 0, 0), core::Vec3(0.8, 0.8, 0)).has_value());
}

}  // namespace
}  // namespace multidir::ui

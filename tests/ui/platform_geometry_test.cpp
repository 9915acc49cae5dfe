// Where the build platform is drawn: under the model's lowest point along up, covering its footprint.
#include <gtest/gtest.h>

#include "multidir/core/mesh/triangle_mesh.h"
#include "ui/viewer/platform_geometry.h"

namespace multidir::ui {
namespace {

// An axis-aligned box from `low` to `high` (corners only: the platform needs nothing more).
core::TriangleMesh box(const core::Vec3& low, const core::Vec3& high) {
  core::TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back((i & 1) ? high.x() : low.x(), (i & 2) ? high.y() : low.y(),
                               (i & 4) ? high.z() : low.z());
  }
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  mesh.resetOrigins();
  return mesh;
}

TEST(PlatformGeometry, DiscLiesAtTheLowestPointUnderTheFootprintCentre) {
  const PlatformDisc disc = platformUnder(box({10, 20, 5}, {30, 60, 25}), core::Vec3::UnitZ());
  EXPECT_TRUE(disc.center.isApprox(core::Vec3(20, 40, 5)));
  EXPECT_TRUE(disc.normal.isApprox(core::Vec3::UnitZ()));
}

TEST(PlatformGeometry, DiscIsLargerThanTheFootprint) {
  const PlatformDisc disc = platformUnder(box({0, 0, 0}, {20, 40, 10}), core::Vec3::UnitZ());
  const double halfDiagonal = 0.5 * std::hypot(20.0, 40.0);
  EXPECT_NEAR(disc.radiusMm, kPlatformMargin * halfDiagonal, 1e-9);
}

TEST(PlatformGeometry, DownwardUpPutsThePlatformOnTheTop) {
  const PlatformDisc disc = platformUnder(box({0, 0, 0}, {10, 10, 30}), core::Vec3(0, 0, -2));
  EXPECT_TRUE(disc.normal.isApprox(-core::Vec3::UnitZ()));
  EXPECT_NEAR(disc.center.z(), 30.0, 1e-12);
}

TEST(PlatformGeometry, SideUpUsesTheFootprintAcrossThatAxis) {
  const PlatformDisc disc = platformUnder(box({0, 0, 0}, {10, 50, 30}), core::Vec3::UnitY());
  EXPECT_TRUE(disc.center.isApprox(core::Vec3(5, 0, 15)));
  EXPECT_NEAR(disc.radiusMm, kPlatformMargin * 0.5 * std::hypot(10.0, 30.0), 1e-9);
}

TEST(PlatformGeometry, ZeroUpCountsAsPlusZ) {
  const PlatformDisc disc = platformUnder(box({0, 0, 0}, {1, 1, 1}), core::Vec3::Zero());
  EXPECT_TRUE(disc.normal.isApprox(core::Vec3::UnitZ()));
}

TEST(PlatformGeometry, NeedleAlongUpStillGetsAVisiblePlatform) {
  const PlatformDisc disc = platformUnder(box({0, 0, 0}, {0.1, 0.1, 100}), core::Vec3::UnitZ());
  EXPECT_GE(disc.radiusMm, 25.0);
}

}  // namespace
}  // namespace multidir::ui

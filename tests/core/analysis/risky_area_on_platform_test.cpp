// The risky area of a solid standing alone on the platform: the J_G of a pose and of a part printed apart
// (rule 2 of docs/jg-definition.md), one definition for both.
#include <gtest/gtest.h>

#include "multidir/core/analysis/overhang.h"
#include "support/primitives.h"

namespace multidir::core {
namespace {

using multidir::test::makeBox;

// An L-shaped solid: a 10 mm cube with a 10 x 10 x 5 mm arm sticking out at its top, whose underside (100 mm^2)
// hangs 5 mm above the platform.
TriangleMesh overhangingArm() {
  TriangleMesh solid = makeBox(Vec3(0, 0, 0), Vec3(10, 10, 10));
  const TriangleMesh arm = makeBox(Vec3(10, 0, 5), Vec3(20, 10, 10));
  const auto offset = static_cast<std::int32_t>(solid.vertices.size());
  solid.vertices.insert(solid.vertices.end(), arm.vertices.begin(), arm.vertices.end());
  for (Triangle t : arm.triangles) {
    for (std::int32_t& v : t) v += offset;
    solid.triangles.push_back(t);
  }
  return solid;
}

TEST(RiskyAreaOnPlatform, IsTheOverhangAnalysisOfTheSolidStandingOnThePlatform) {
  const TriangleMesh solid = overhangingArm();
  const auto area = riskyAreaOnPlatform(solid, Vec3::UnitZ(), 45.0, 0.2);
  ASSERT_TRUE(area.ok()) << area.error().describe();
  EXPECT_NEAR(*area, 100.0, 1e-9);
  OverhangOptions options;
  options.alphaMaxDegrees = 45.0;
  options.supportedBandMm = 0.2;
  options.base = RegionBase::Platform;
  EXPECT_DOUBLE_EQ(*area, analyzeOverhang(solid, Vec3::UnitZ(), options)->riskyAreaMm2);
}

// A failed analysis must never count as "no risky area": an optimiser would pick exactly that pose or part.
TEST(RiskyAreaOnPlatform, AZeroDirectionIsAnErrorNotZeroRiskyArea) {
  const auto area = riskyAreaOnPlatform(overhangingArm(), Vec3::Zero(), 45.0, 0.2);
  ASSERT_FALSE(area.ok());
  EXPECT_EQ(area.error().code, ErrorCode::InvalidParameter);
}

TEST(RiskyAreaOnPlatform, AnAngleOutsideItsRangeIsAnErrorNotZeroRiskyArea) {
  EXPECT_FALSE(riskyAreaOnPlatform(overhangingArm(), Vec3::UnitZ(), 95.0, 0.2).ok());
  EXPECT_FALSE(riskyAreaOnPlatform(overhangingArm(), Vec3::UnitZ(), 45.0, -1.0).ok());
}

}  // namespace
}  // namespace multidir::core

// What the plan editor offers: how far a plane can move, what it turns about, the directions its angle
// controls stand for, and where a new plane goes. A 10 x 10 x 30 box cut level at z = 20, then z = 10.
#include "ui/edit/plane_edit_geometry.h"

#include <gtest/gtest.h>

#include "multidir/core/search/plan_from_planes.h"
#include "support/primitives.h"

namespace multidir::ui {
namespace {

core::Decomposition stackedBox() {
  const core::TriangleMesh box = test::makeBox({0, 0, 0}, {10, 10, 30});
  const std::vector<core::Plane> planes = {{core::Vec3::UnitZ(), 20.0}, {core::Vec3::UnitZ(), 10.0}};
  core::Result<core::Decomposition> plan =
      core::planFromClippingPlanes(box, core::MachineSpec{}, core::SearchOptions{}, planes);
  EXPECT_TRUE(plan.ok()) << plan.error().describe();
  return plan.ok() ? plan.value() : core::Decomposition{};
}

TEST(PlaneEditGeometry, APlaneMovesOverWhatIsLeftOfTheModelWhenItCuts) {
  const core::Decomposition plan = stackedBox();
  const OffsetRange first = offsetRangeBefore(plan, 0, core::Vec3::UnitZ());
  EXPECT_NEAR(first.minMm, 0.0, 1e-9);
  EXPECT_NEAR(first.maxMm, 30.0, 1e-9);
  // The second plane cuts what the first left: the box below z = 20.
  const OffsetRange second = offsetRangeBefore(plan, 1, core::Vec3::UnitZ());
  EXPECT_NEAR(second.minMm, 0.0, 1e-9);
  EXPECT_NEAR(second.maxMm, 20.0, 1e-9);
  EXPECT_TRUE(offsetRangeBefore(plan, 2, core::Vec3::UnitZ()).empty());
}

TEST(PlaneEditGeometry, APlaneTurnsAboutTheCentreOfItsCut) {
  const core::Vec3 pivot = planePivot(stackedBox(), 0);
  EXPECT_TRUE(pivot.isApprox(core::Vec3(5.0, 5.0, 20.0), 1e-9)) << pivot.transpose();
}

TEST(PlaneEditGeometry, TiltAndAzimuthGiveTheDirectionTheMachineMeasuresThemFor) {
  core::MachineSpec machine;
  machine.up = core::Vec3::UnitY();
  const core::Vec3 direction = tiltedDirection(machine.up, 30.0, 120.0);
  EXPECT_NEAR(direction.norm(), 1.0, 1e-12);
  const core::MachineAngles angles = core::machineAnglesFor(machine, direction);
  EXPECT_NEAR(angles.tiltDegrees, 30.0, 1e-9);
  EXPECT_NEAR(angles.azimuthDegrees, 120.0, 1e-9);
  EXPECT_TRUE(tiltedDirection(machine.up, 0.0, 77.0).isApprox(machine.up));
}

TEST(PlaneEditGeometry, RotaryAnglesSnapToWholeStepsWithinTheRange) {
  core::MachineSpec machine;
  machine.kind = core::MachineKind::RotaryPlatform;
  machine.minAngleDegrees = -60.0;
  machine.maxAngleDegrees = 60.0;
  machine.angleStepDegrees = 1.8;
  EXPECT_NEAR(snapRotaryDegrees(machine, 10.0), -60.0 + 39 * 1.8, 1e-9);
  EXPECT_NEAR(snapRotaryDegrees(machine, 100.0), -60.0 + 66 * 1.8, 1e-9);  // the last step within the range
  EXPECT_NEAR(snapRotaryDegrees(machine, -100.0), -60.0, 1e-9);
}

TEST(PlaneEditGeometry, ANewPlaneSplitsThePieceAboveTheSelectedPlane) {
  const NewPlanePlacement placement = suggestNewPlane(stackedBox(), 0, core::Vec3::UnitZ());
  EXPECT_EQ(placement.index, 0);  // cut first, so the new top piece is printed last
  EXPECT_EQ(placement.plane.normal, core::Vec3::UnitZ());
  EXPECT_NEAR(placement.plane.offset, 25.0, 1e-9);
}

TEST(PlaneEditGeometry, WithoutASelectionANewPlaneCutsWhatIsLeftOnThePlatformAtMidHeight) {
  const NewPlanePlacement placement = suggestNewPlane(stackedBox(), -1, core::Vec3::UnitZ());
  EXPECT_EQ(placement.index, 2);
  EXPECT_EQ(placement.plane.normal, core::Vec3::UnitZ());
  EXPECT_NEAR(placement.plane.offset, 5.0, 1e-9);
}

}  // namespace
}  // namespace multidir::ui

// What the plan editor says when core refuses an edited plane list: the plane, the problem, what to do.
#include <gtest/gtest.h>

#include "multidir/core/search/plan_from_planes.h"
#include "support/primitives.h"
#include "ui/edit/refusal_text.h"

namespace multidir::ui {
namespace {

// Stem x in [-5, 5] up to z = 30, bar x in [-40, 40] at z 30..40.
core::TriangleMesh tBar() { return test::makeTBar(10, 30, 80, 10, 10); }

core::MachineSpec narrowPlatform() {
  core::MachineSpec machine;
  machine.platformRadiusMm = 4.9;
  return machine;
}

core::Error refusalOf(const core::TriangleMesh& model, const core::MachineSpec& machine,
                      const std::vector<core::Plane>& planes) {
  const core::Result<core::Decomposition> plan =
      core::planFromClippingPlanes(model, machine, core::SearchOptions{}, planes);
  EXPECT_FALSE(plan.ok());
  return plan.ok() ? core::Error{core::ErrorCode::Internal, "accepted", ""} : plan.error();
}

TEST(PlanEditRefusal, APlaneThroughThePlatformRegionIsToldToMoveUpOrTiltLess) {
  const core::Error error = refusalOf(tBar(), core::MachineSpec{}, {core::Plane{core::Vec3::UnitX(), 0.0}});
  EXPECT_EQ(refusedPlaneNumber(error), 1);
  EXPECT_EQ(refusalText(error, 1), QStringLiteral("Plane 1 would cut the platform region: move it up or tilt it less."));
}

TEST(PlanEditRefusal, APlaneLeavingAPieceFloatingSaysSo) {
  const core::Error error =
      refusalOf(test::makeHook(10), core::MachineSpec{}, {core::Plane{core::Vec3::UnitZ(), 40.0}});
  EXPECT_TRUE(refusalText(error, 1).startsWith(QStringLiteral("Plane 1 would leave a piece below it")))
      << refusalText(error, 1).toStdString();
}

TEST(PlanEditRefusal, APlaneAboveWhatIsLeftCutsNothing) {
  const core::Error error = refusalOf(tBar(), narrowPlatform(),
                                      {core::Plane{core::Vec3::UnitX(), 5.0}, core::Plane{core::Vec3::UnitX(), 100.0}});
  EXPECT_EQ(refusedPlaneNumber(error), 2);
  // Core's second plane cut is the lower of the two: plane 1 in printing order, as the Edit plan table says.
  EXPECT_EQ(refusalText(error, 2), QStringLiteral("Plane 1 would cut nothing off: move it into the part it cuts."));
}

TEST(PlanEditRefusal, AnEditThatMakesAnotherPlaneFailNamesThePlaneEditedAndThePlaneRefused) {
  // The user moved plane 2 (printing order; core's first cut) so that plane 1, cut after it, cuts nothing.
  const core::Error error = refusalOf(tBar(), narrowPlatform(),
                                      {core::Plane{core::Vec3::UnitX(), 5.0}, core::Plane{core::Vec3::UnitX(), 100.0}});
  ASSERT_EQ(refusedPlaneNumber(error), 2);
  EXPECT_EQ(refusalText(error, 2, 0),
            QStringLiteral("Plane 2 was not changed: with it there, plane 1 is refused. Plane 1 would cut nothing "
                           "off: move it into the part it cuts."));
  // The plane edited is the one refused: named once.
  EXPECT_EQ(refusalText(error, 2, 1), QStringLiteral("Plane 1 would cut nothing off: move it into the part it cuts."));
  // A deletion names no edited plane.
  EXPECT_EQ(refusalText(error, 2, -1), refusalText(error, 2));
}

TEST(PlanEditRefusal, ADirectionTheMachineCannotPrintAlongIsNamed) {
  core::MachineSpec rotary;
  rotary.kind = core::MachineKind::RotaryPlatform;
  rotary.rotationAxis = core::Vec3::UnitX();
  const core::Error error = refusalOf(tBar(), rotary, {core::Plane{core::Vec3::UnitX(), 5.0}});
  EXPECT_TRUE(refusalText(error, 1).contains(QStringLiteral("cannot print along the normal of plane 1")))
      << refusalText(error, 1).toStdString();
}

TEST(PlanEditRefusal, AnErrorNamingNoPlaneKeepsCoresDescription) {
  const core::Error error{core::ErrorCode::TooLarge, "there is not enough memory to rebuild the plan", "plan"};
  EXPECT_EQ(refusedPlaneNumber(error), 0);
  EXPECT_TRUE(refusalText(error, 3).contains(QStringLiteral("plan: there is not enough memory to rebuild the plan")))
      << refusalText(error, 3).toStdString();
}

}  // namespace
}  // namespace multidir::ui

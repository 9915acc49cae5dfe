// Plans rebuilt from given clipping planes (plan editing, reopened projects).
#include <gtest/gtest.h>

#include <stdexcept>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/search/decompose.h"
#include "multidir/core/search/plan_from_planes.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir::core;
using multidir::test::makeHook;
using multidir::test::makeTBar;

namespace {

// The T-bar's platform region as a disc of radius 4.9 mm: planes at |x| = 5 along the stem's sides clear it.
MachineSpec narrowPlatform() {
  MachineSpec machine;
  machine.platformRadiusMm = 4.9;
  return machine;
}

MachineSpec machineWithUp(const Vec3& up) {
  MachineSpec machine;
  machine.up = up;
  return machine;
}

}  // namespace

TEST(PlanFromPlanes, ThePlanesOfASearchedPlanGiveTheSamePlan) {
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  const MachineSpec machine = machineWithUp(Vec3::UnitY());
  const SearchOptions options;
  JobContext job;
  const auto searched = decompose(kitten, machine, options, job);
  ASSERT_TRUE(searched.ok()) << searched.error().describe();
  ASSERT_FALSE(searched->clippingPlanes.empty());

  const auto rebuilt = planFromClippingPlanes(kitten, machine, options, searched->clippingPlanes);
  ASSERT_TRUE(rebuilt.ok()) << rebuilt.error().describe();
  ASSERT_EQ(rebuilt->regions.size(), searched->regions.size());
  EXPECT_NEAR(rebuilt->jgAfterMm2, searched->jgAfterMm2, 1e-6 * searched->jgBeforeMm2);
  EXPECT_DOUBLE_EQ(rebuilt->jgBeforeMm2, searched->jgBeforeMm2);
  for (std::size_t i = 0; i < rebuilt->regions.size(); ++i) {
    EXPECT_EQ(rebuilt->regions[i].mesh.triangles.size(), searched->regions[i].mesh.triangles.size()) << i;
    EXPECT_NEAR(rebuilt->regions[i].volumeMm3, searched->regions[i].volumeMm3, 1e-9 * searched->regions[i].volumeMm3);
    EXPECT_TRUE(rebuilt->regions[i].printingDirection.isApprox(searched->regions[i].printingDirection)) << i;
  }
}

TEST(PlanFromPlanes, NoPlanesGiveTheWholeModelPrintedAlongUp) {
  const TriangleMesh tbar = makeTBar(10, 30, 80, 10, 10);
  const auto plan = planFromClippingPlanes(tbar, MachineSpec{}, SearchOptions{}, {});
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  ASSERT_EQ(plan->regions.size(), 1u);
  EXPECT_GT(plan->jgBeforeMm2, 0.0);
  EXPECT_DOUBLE_EQ(plan->jgAfterMm2, plan->jgBeforeMm2);
}

TEST(PlanFromPlanes, CuttingTheTBarsArmsOffAlongThemMakesItSupportFree) {
  // Stem x in [-5, 5], bar x in [-40, 40] at z 30..40: each arm printed sideways has no overhang.
  const TriangleMesh tbar = makeTBar(10, 30, 80, 10, 10);
  const std::vector<Plane> planes = {Plane{Vec3::UnitX(), 5.0}, Plane{-Vec3::UnitX(), 5.0}};
  const auto plan = planFromClippingPlanes(tbar, narrowPlatform(), SearchOptions{}, planes);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  EXPECT_EQ(plan->regions.size(), 3u);
  // Planes along the stem's walls are kept a couple of micrometres off its vertices; the slivers of the arms'
  // undersides that this can leave beside the stem are all that remains (docs/jg-definition.md).
  EXPECT_LT(plan->jgAfterMm2, 0.05);
}

TEST(PlanFromPlanes, APlaneThatLeavesAFloatingPieceIsRefusedByCriterionII) {
  // A level cut through the hook's drop leaves its lower end hanging in the air below the plane.
  const auto plan = planFromClippingPlanes(makeHook(10), MachineSpec{}, SearchOptions{}, {Plane{Vec3::UnitZ(), 40.0}});
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().code, ErrorCode::InvalidParameter);
  EXPECT_EQ(plan.error().where, "plane 1");
  EXPECT_NE(plan.error().message.find("Criterion II"), std::string::npos) << plan.error().message;
}

TEST(PlanFromPlanes, APlaneThroughThePlatformRegionIsRefusedByCriterionIII) {
  const TriangleMesh tbar = makeTBar(10, 30, 80, 10, 10);
  const auto plan = planFromClippingPlanes(tbar, MachineSpec{}, SearchOptions{}, {Plane{Vec3::UnitX(), 0.0}});
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().where, "plane 1");
  EXPECT_NE(plan.error().message.find("Criterion III"), std::string::npos) << plan.error().message;
}

TEST(PlanFromPlanes, APlaneTheMachineCannotPrintAlongIsRefused) {
  MachineSpec rotary;
  rotary.kind = MachineKind::RotaryPlatform;
  rotary.rotationAxis = Vec3::UnitX();
  // Printing along +X needs a turn about Y, which a platform turning about X cannot make.
  const auto plan = planFromClippingPlanes(makeTBar(10, 30, 80, 10, 10), rotary, SearchOptions{}, {Plane{Vec3::UnitX(), 5.0}});
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().where, "plane 1");
  EXPECT_NE(plan.error().message.find("cannot print along"), std::string::npos) << plan.error().message;
}

TEST(PlanFromPlanes, APlaneAboveTheModelIsRefusedAsCuttingNothing) {
  const auto plan = planFromClippingPlanes(makeTBar(10, 30, 80, 10, 10), narrowPlatform(), SearchOptions{},
                                           {Plane{Vec3::UnitX(), 5.0}, Plane{Vec3::UnitX(), 100.0}});
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().where, "plane 2");
  EXPECT_NE(plan.error().message.find("cuts nothing"), std::string::npos) << plan.error().message;
}

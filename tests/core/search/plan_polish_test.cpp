// Polishing a plan: its planes moved continuously past the sampled candidates (docs/search.md, "Polishing").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "multidir/core/common/units.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/search/decompose.h"
#include "multidir/core/search/plan_from_planes.h"
#include "multidir/core/search/plan_polish.h"
#include "support/primitives.h"
#include "support/same_planes.h"
#include "support/test_models.h"

using namespace multidir::core;
using multidir::test::makeTBar;

namespace {

MachineSpec machineWithUp(const Vec3& up) {
  MachineSpec machine;
  machine.up = up;
  return machine;
}

// The search alone: what polishing starts from.
SearchOptions unpolished() {
  SearchOptions options;
  options.polish = false;
  return options;
}

// The T-bar (stem x in [-5, 5], bar x in [-40, 40] at z 30..40) on a platform region of radius 4.9 mm, so that
// planes along the stem's walls clear it. Cutting each arm off along the stem's wall, printed sideways, leaves no
// overhang: the best planes are known.
MachineSpec tbarMachine() {
  MachineSpec machine;
  machine.platformRadiusMm = 4.9;
  return machine;
}

// The +X wall plane turned by `degrees` towards up about the arm's root edge's middle (5, 0, 35), then moved
// by `shiftMm` along its normal.
Plane nudgedWallPlane(double degrees, double shiftMm) {
  const double a = degToRad(degrees);
  const Vec3 normal(std::cos(a), 0.0, std::sin(a));
  Plane plane = Plane::throughPoint(normal, Vec3(5.0, 5.0, 35.0));
  plane.offset += shiftMm;
  return plane;
}

// The plan's planes again with every criterion checked (plan_from_planes), or a failed test.
Decomposition recut(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                    const Decomposition& plan) {
  MachineSpec axis = machine;
  axis.rotationAxis = plan.rotationAxis;
  auto rebuilt = planFromClippingPlanes(model, axis, options, plan.clippingPlanes);
  EXPECT_TRUE(rebuilt.ok()) << rebuilt.error().describe();
  return rebuilt.ok() ? *rebuilt : Decomposition{};
}

// Every constraint the search keeps, on a polished plan: the planes make a valid plan again (the machine prints
// along each normal, Criteria II and III, the minimum region height), every region keeps V/w of the finest
// scale, every plane pays for itself, and the regions save.
void expectEveryConstraintKept(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                               const Decomposition& plan, const std::string& name) {
  SCOPED_TRACE(name);
  const Decomposition rebuilt = recut(model, machine, options, plan);
  EXPECT_NEAR(rebuilt.jgAfterMm2, plan.jgAfterMm2, 1e-6 * plan.jgBeforeMm2);
  double volume = 0.0;
  for (const Region& region : plan.regions) volume += region.volumeMm3;
  for (std::size_t r = 1; r < plan.regions.size(); ++r)
    EXPECT_GE(plan.regions[r].volumeMm3, volume / finestVolumeDivisor(options) * (1 - 1e-9)) << "region " << r;
  const double threshold = std::max(options.minPlaneGainMm2, options.minPlaneGainPercent / 100 * plan.jgBeforeMm2);
  for (std::size_t k = 0; k < plan.clippingPlanes.size(); ++k) {
    std::vector<Plane> without = plan.clippingPlanes;
    without.erase(without.begin() + static_cast<std::ptrdiff_t>(k));
    MachineSpec axis = machine;
    axis.rotationAxis = plan.rotationAxis;
    const auto fewer = planFromClippingPlanes(model, axis, options, without);
    if (fewer.ok()) {
      EXPECT_GE(fewer->jgAfterMm2 - plan.jgAfterMm2, threshold) << "plane " << k + 1 << " does not pay";
    }
  }
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("multidir-polish-test-" + name);
  PlanMetadata metadata;
  metadata.machine = machine;
  metadata.up = machine.up;
  metadata.options = options;
  const Status saved = savePlan(plan, metadata, folder.string());
  EXPECT_TRUE(saved.ok()) << saved.error().describe();
  std::filesystem::remove_all(folder);
}

}  // namespace

TEST(PlanPolish, BringsAPlaneNudgedOffTheStemsWallBackToIt) {
  const TriangleMesh tbar = makeTBar(10, 30, 80, 10, 10);
  SearchOptions options;
  options.polishEffort = 5;  // down to 0.125 degrees and 1/32 mm
  const Plane wall{-Vec3::UnitX(), 5.0};
  const auto best = planFromClippingPlanes(tbar, tbarMachine(), options, {Plane{Vec3::UnitX(), 5.0}, wall});
  ASSERT_TRUE(best.ok()) << best.error().describe();
  // 3 degrees towards up and 0.7 mm out: a strip of the arm's underside stays with the stem, over air.
  const auto nudged = planFromClippingPlanes(tbar, tbarMachine(), options, {nudgedWallPlane(3.0, 0.7), wall});
  ASSERT_TRUE(nudged.ok()) << nudged.error().describe();
  ASSERT_GT(nudged->jgAfterMm2, best->jgAfterMm2 + 5.0);

  JobContext job;
  const auto polished = polishPlan(tbar, tbarMachine(), options, *nudged, job);
  ASSERT_TRUE(polished.ok()) << polished.error().describe();
  ASSERT_EQ(polished->clippingPlanes.size(), 2u);
  // Back at the optimum: the whole underside of the arm above the plane (its root edge at x = 5, z = 30 too),
  // printed sideways with the arm. (The optimum is not one plane: any plane that keeps the root edge above it
  // and clears the platform region gives it.)
  EXPECT_LT(polished->jgAfterMm2, 0.05);
  for (const double y : {0.0, 10.0})
    EXPECT_GE(polished->clippingPlanes[0].signedDistance(Vec3(5.0, y, 30.0)), 0.0) << y;
}

TEST(PlanPolish, FollowsAMoveThatWorksBackToAWallMoreMovesAwayThanItsStepsReach) {
  const TriangleMesh tbar = makeTBar(10, 30, 80, 10, 10);
  const SearchOptions options;  // effort 1: offset steps of 0.5 mm, one pass, at most 4 trial moves per plane
  const Plane wall{-Vec3::UnitX(), 5.0};
  // The +X arm cut 6 mm out from the stem's wall: a 6 mm strip of its underside stays with the stem, over air.
  // Twelve steps of 0.5 mm; the trial moves alone take at most four.
  const auto far = planFromClippingPlanes(tbar, tbarMachine(), options, {Plane{Vec3::UnitX(), 11.0}, wall});
  ASSERT_TRUE(far.ok()) << far.error().describe();
  ASSERT_GT(far->jgAfterMm2, 50.0);

  JobContext job;
  const auto polished = polishPlan(tbar, tbarMachine(), options, *far, job);
  ASSERT_TRUE(polished.ok()) << polished.error().describe();
  ASSERT_EQ(polished->clippingPlanes.size(), 2u);
  EXPECT_LT(polished->jgAfterMm2, 0.05);
}

TEST(PlanPolish, NeverRaisesJg) {
  for (const char* name : {"knight.off", "bumpy.off", "screwdriver.off"}) {
    SCOPED_TRACE(name);
    const TriangleMesh model = multidir::test::loadSharedModel(name);
    const MachineSpec machine = machineWithUp(Vec3::UnitY());
    SearchOptions options = unpolished();
    options.scheme = SearchScheme::Greedy;
    JobContext job;
    const auto found = decompose(model, machine, options, job);
    ASSERT_TRUE(found.ok()) << found.error().describe();
    const auto polished = polishPlan(model, machine, options, *found, job);
    ASSERT_TRUE(polished.ok()) << polished.error().describe();
    EXPECT_LE(polished->jgAfterMm2, found->jgAfterMm2);
    EXPECT_DOUBLE_EQ(polished->statistics.jgBeforePolishMm2, found->jgAfterMm2);
  }
}

TEST(PlanPolish, KeepsEveryConstraintOnTheSharedModels) {
  const MachineSpec fiveDof = machineWithUp(Vec3::UnitY());
  MachineSpec fourDof = fiveDof;
  fourDof.kind = MachineKind::RotaryPlatform;
  fourDof.rotationAxis = Vec3::UnitX();
  for (const auto& [name, machine] : {std::pair{"knight.off", fiveDof}, std::pair{"3holes.off", fiveDof},
                                      std::pair{"knight.off", fourDof}}) {
    const TriangleMesh model = multidir::test::loadSharedModel(name);
    const SearchOptions options;
    JobContext job;
    const auto plan = decompose(model, machine, options, job);
    ASSERT_TRUE(plan.ok()) << plan.error().describe();
    ASSERT_GE(plan->statistics.jgBeforePolishMm2, plan->jgAfterMm2) << name;
    expectEveryConstraintKept(model, machine, options, *plan,
                              std::string(name) + "-" + machineKindName(machine.kind));
    if (machine.kind == MachineKind::RotaryPlatform)
      for (const Region& region : plan->regions) {
        const double steps = region.angles.rotaryDegrees / machine.angleStepDegrees;
        EXPECT_NEAR(steps, std::round(steps), 1e-6) << name << ": a 4-DOF direction between the stepper's steps";
      }
  }
}

TEST(PlanPolish, GivesTheSamePlanForOneAndTwoThreads) {
  const TriangleMesh bunny = multidir::test::loadSharedModel("bunny.off");
  const MachineSpec machine = machineWithUp(Vec3::UnitY());
  SearchOptions one;
  one.threads = 1;
  SearchOptions two = one;
  two.threads = 2;
  JobContext job;
  const auto a = decompose(bunny, machine, one, job);
  const auto b = decompose(bunny, machine, two, job);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_LT(a->jgAfterMm2, a->statistics.jgBeforePolishMm2);  // polishing moved planes
  EXPECT_EQ(a->jgAfterMm2, b->jgAfterMm2);
  EXPECT_TRUE(multidir::test::samePlanes(*a, *b));
}

TEST(PlanPolish, ReportsItsProgressAsAStageOfTheSearch) {
  const TriangleMesh tbar = makeTBar(10, 30, 80, 10, 10);
  const auto nudged = planFromClippingPlanes(tbar, tbarMachine(), SearchOptions{}, {nudgedWallPlane(3.0, 0.7)});
  ASSERT_TRUE(nudged.ok()) << nudged.error().describe();
  std::vector<double> fractions;
  JobContext job;
  const auto polished = polishPlan(tbar, tbarMachine(), SearchOptions{}, *nudged, job, [&](const SearchProgress& p) {
    if (p.polishing) fractions.push_back(p.polishFraction);
  });
  ASSERT_TRUE(polished.ok()) << polished.error().describe();
  ASSERT_GE(fractions.size(), 2u);
  EXPECT_EQ(fractions.front(), 0.0);
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
}

TEST(PlanPolish, CancelledReturnsThePlanAsGiven) {
  const TriangleMesh tbar = makeTBar(10, 30, 80, 10, 10);
  const auto nudged = planFromClippingPlanes(tbar, tbarMachine(), SearchOptions{}, {nudgedWallPlane(3.0, 0.7)});
  ASSERT_TRUE(nudged.ok()) << nudged.error().describe();
  JobContext job;
  job.cancel();
  const auto polished = polishPlan(tbar, tbarMachine(), SearchOptions{}, *nudged, job);
  ASSERT_TRUE(polished.ok()) << polished.error().describe();
  EXPECT_EQ(polished->jgAfterMm2, nudged->jgAfterMm2);
  EXPECT_EQ(polished->clippingPlanes[0].offset, nudged->clippingPlanes[0].offset);
}

TEST(PlanPolish, RefusesAPlanWhosePlaneTheCriteriaRefuseNamingIt) {
  const TriangleMesh tbar = makeTBar(10, 30, 80, 10, 10);
  Decomposition plan;
  plan.clippingPlanes = {Plane{Vec3::UnitX(), 5.0}, Plane{Vec3::UnitZ(), 0.5}};  // the second cuts the platform
  JobContext job;
  const auto polished = polishPlan(tbar, tbarMachine(), SearchOptions{}, plan, job);
  ASSERT_FALSE(polished.ok());
  EXPECT_EQ(polished.error().where, "plane 2");
}

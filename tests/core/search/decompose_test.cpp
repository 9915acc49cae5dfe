#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/geometry/clipping.h"
#include "multidir/core/geometry/connectivity.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/samples/samples.h"
#include "multidir/core/search/decompose.h"
#include "support/primitives.h"
#include "support/same_planes.h"
#include "support/test_models.h"

using namespace multidir::core;
using multidir::test::makeBox;
using multidir::test::makeHook;
using multidir::test::makeTBar;

namespace {

// Every plane the scheme finds is kept: removing planes that do not pay for themselves happens after the
// search and may cost each scheme a different share of J_G.
SearchOptions optionsFor(SearchScheme scheme) {
  SearchOptions options;
  options.scheme = scheme;
  options.minPlaneGainPercent = 0;
  options.minPlaneGainMm2 = 0;
  return options;
}

Decomposition run(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options) {
  JobContext job;
  auto result = decompose(model, machine, options, job);
  if (!result.ok()) throw std::runtime_error(result.error().describe());
  return std::move(result).value();
}

MachineSpec machineWithUp(const Vec3& up, MachineKind kind = MachineKind::TiltRotate) {
  MachineSpec machine;
  machine.kind = kind;
  machine.up = up;
  if (kind == MachineKind::RotaryPlatform) machine.rotationAxis = platformFrameX(up);
  return machine;
}

double recomputedJg(const Decomposition& plan, const SearchOptions& options) {
  double total = 0;
  OverhangOptions overhang;
  overhang.alphaMaxDegrees = options.alphaMaxDegrees;
  for (const Region& region : plan.regions) {
    overhang.base = region.basePlane ? RegionBase::CutPlane : RegionBase::Platform;
    total += analyzeOverhang(region.mesh, region.printingDirection, overhang)->riskyAreaMm2;
  }
  return total;
}

}  // namespace

TEST(Decompose, BoxNeedsNoPlane) {
  const Decomposition plan = run(makeBox(Vec3(0, 0, 0), Vec3(30, 30, 30)), MachineSpec{}, SearchOptions{});
  EXPECT_TRUE(plan.clippingPlanes.empty());
  ASSERT_EQ(plan.regions.size(), 1u);
  EXPECT_DOUBLE_EQ(plan.jgAfterMm2, 0.0);
}

TEST(Decompose, TBarIsCutSoItsWingsPrintSideways) {
  const TriangleMesh tbar = makeTBar(10, 30, 80, 10, 10);
  const Decomposition plan = run(tbar, MachineSpec{}, SearchOptions{});
  EXPECT_NEAR(plan.jgBeforeMm2, 700.0, 1e-6);  // two wings of 35 x 10 mm look straight down
  EXPECT_GE(plan.clippingPlanes.size(), 2u);
  EXPECT_LT(plan.jgAfterMm2, 0.05 * plan.jgBeforeMm2);
}

TEST(Decompose, EveryRemainingPartStandsOnThePlatform) {
  // The hook's drop would float if the arm were cut off above it: Criterion II must refuse such cuts.
  const MachineSpec machine;
  for (SearchScheme scheme : {SearchScheme::Greedy, SearchScheme::ConstrainedGreedy, SearchScheme::Beam}) {
    const Decomposition plan = run(makeHook(10), machine, optionsFor(scheme));
    ASSERT_FALSE(plan.regions.empty());
    const auto solids = connectedSolidsOnPlatform(plan.regions.front().mesh, Plane{machine.up, 0.0}, 1e-3);
    ASSERT_TRUE(solids.ok());
    for (const PlacedSolid& solid : *solids) EXPECT_TRUE(solid.touchesPlatform) << schemeName(scheme);
    EXPECT_LT(plan.jgAfterMm2, plan.jgBeforeMm2) << schemeName(scheme);
  }
}

TEST(Decompose, NoClippingPlaneCutsThePlatformRegion) {
  const TriangleMesh tbar = makeTBar(10, 30, 80, 10, 10);
  const MachineSpec machine;
  const Decomposition plan = run(tbar, machine, SearchOptions{});
  const PlatformRegion platform = platformRegionFor(tbar, machine);
  for (const Plane& plane : plan.clippingPlanes) {
    const Vec3 inPlane = plane.normal - plane.normal.dot(machine.up) * machine.up;
    EXPECT_GT(plane.offset, plane.normal.dot(platform.center) + platform.radiusMm * inPlane.norm());
  }
}

TEST(Decompose, ReportedJgEqualsTheRiskyAreaOfTheRegionMeshes) {
  const SearchOptions options;
  for (const char* name : {"kitten.off", "bunny.off"}) {
    const Decomposition plan = run(multidir::test::loadSharedModel(name), machineWithUp(Vec3::UnitY()), options);
    EXPECT_NEAR(recomputedJg(plan, options), plan.jgAfterMm2, 1e-6 * plan.jgBeforeMm2 + 1e-9) << name;
    double volume = 0;
    for (const Region& region : plan.regions) volume += region.volumeMm3;
    EXPECT_NEAR(volume, signedVolume(multidir::test::loadSharedModel(name)), 1e-9 * volume) << name;
  }
}

TEST(Decompose, BeamSearchIsNeverWorseThanEitherGreedyScheme) {
  std::vector<std::pair<TriangleMesh, Vec3>> models = {{makeTBar(10, 30, 80, 10, 10), Vec3::UnitZ()},
                                                      {makeHook(10), Vec3::UnitZ()}};
  for (const samples::SampleInfo& sample : samples::catalogue()) models.push_back({*samples::makeSample(sample.id), Vec3::UnitZ()});
  for (const char* name : {"kitten.off", "3holes.off"}) models.push_back({multidir::test::loadSharedModel(name), Vec3::UnitY()});
  for (const auto& [model, up] : models) {
    const MachineSpec machine = machineWithUp(up);
    const double beam = run(model, machine, optionsFor(SearchScheme::Beam)).jgAfterMm2;
    EXPECT_LE(beam, run(model, machine, optionsFor(SearchScheme::Greedy)).jgAfterMm2 + 1e-9);
    EXPECT_LE(beam, run(model, machine, optionsFor(SearchScheme::ConstrainedGreedy)).jgAfterMm2 + 1e-9);
  }
}

// With the unpaid planes removed (the default plane gain): the beam scheme chooses among its searches' plans
// once each pays for every plane. On the bunny the constrained greedy chain's plan pays with 223.46 mm^2, while
// the beam's best as found, which was delivered before, ended at 233.39 mm^2 once its unpaid planes went.
TEST(Decompose, BeamSchemeWithUnpaidPlanesRemovedIsNeverWorseThanEitherGreedyScheme) {
  const TriangleMesh bunny = multidir::test::loadSharedModel("bunny.off");
  const MachineSpec machine = machineWithUp(Vec3::UnitY());
  SearchOptions options;
  options.polish = false;
  const double beam = run(bunny, machine, options).jgAfterMm2;
  for (SearchScheme scheme : {SearchScheme::Greedy, SearchScheme::ConstrainedGreedy}) {
    SearchOptions greedy = options;
    greedy.scheme = scheme;
    EXPECT_LE(beam, run(bunny, machine, greedy).jgAfterMm2 + 1e-9) << schemeName(scheme);
  }
}

TEST(Decompose, DefaultBeamSearchLeavesAtMostTheTargetShareOfJgOnKittenAndBunny) {
  // Honest J_G (docs/jg-definition.md), 5-DOF defaults, alpha 45: targets kitten <= 2 %, bunny <= 3.5 % (the
  // paper's share); measured 0.77 % and 2.62 %.
  for (const auto& [name, share] : {std::pair<const char*, double>{"kitten.off", 0.02}, {"bunny.off", 0.035}}) {
    const Decomposition plan = run(multidir::test::loadSharedModel(name), machineWithUp(Vec3::UnitY()), SearchOptions{});
    EXPECT_LE(plan.jgAfterMm2, share * plan.jgBeforeMm2) << name;
  }
}

TEST(Decompose, OneTwoAndThreeThreadsGiveTheSamePlanAtTwoScales) {
  // The greedy chains and the two scales' beams run side by side on as many threads as there are, and a
  // search that finishes hands its threads to one still running: the plan must not show it.
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  SearchOptions options;
  options.volumeScales = 2;
  options.threads = 1;
  const Decomposition one = run(kitten, machineWithUp(Vec3::UnitY()), options);
  ASSERT_GE(one.clippingPlanes.size(), 1u);
  for (int threads : {2, 3}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    options.threads = threads;
    const Decomposition other = run(kitten, machineWithUp(Vec3::UnitY()), options);
    EXPECT_TRUE(multidir::test::samePlanes(other, one));
    EXPECT_EQ(other.jgAfterMm2, one.jgAfterMm2);
    EXPECT_EQ(other.statistics.candidatesScored, one.statistics.candidatesScored);
  }
}

TEST(Decompose, RotaryPlatformPlansUseOnlyRealizableDirections) {
  const MachineSpec machine = machineWithUp(Vec3::UnitY(), MachineKind::RotaryPlatform);
  JobContext job;
  auto result = decomposeWithAxisSearch(multidir::test::loadSharedModel("kitten.off"), machine, SearchOptions{}, 6, job);
  ASSERT_TRUE(result.ok()) << result.error().describe();
  MachineSpec used = machine;
  used.rotationAxis = result->rotationAxis;
  EXPECT_NEAR(used.rotationAxis.dot(machine.up), 0.0, 1e-12);
  for (const Region& region : result->regions) {
    EXPECT_TRUE(isRealizable(used, region.printingDirection));
    EXPECT_NEAR(region.printingDirection.dot(used.rotationAxis), 0.0, 1e-9);
  }
  EXPECT_LT(result->jgAfterMm2, result->jgBeforeMm2);
}

TEST(Decompose, CancelReturnsTheBestPlanFoundSoFar) {
  JobContext job;
  int reportsBeforeCancel = 0;
  auto result = decompose(multidir::test::loadSharedModel("kitten.off"), machineWithUp(Vec3::UnitY()), SearchOptions{}, job,
                          [&](const SearchProgress&) {
                            if (!job.isCancelled()) ++reportsBeforeCancel;  // then one: the delivered plan's
                            job.cancel();
                          });
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(result->cancelled);
  EXPECT_EQ(reportsBeforeCancel, 1);
  EXPECT_LE(result->statistics.levels, 2);
  EXPECT_LE(result->jgAfterMm2, result->jgBeforeMm2);
}

TEST(Decompose, CancelledBeforeStartReturnsTheUncutModel) {
  JobContext job;
  job.cancel();
  auto result = decompose(makeTBar(10, 30, 80, 10, 10), MachineSpec{}, SearchOptions{}, job);
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(result->cancelled);
  EXPECT_EQ(result->regions.size(), 1u);
}

TEST(Decompose, AbsurdParametersAreRefusedByName) {
  JobContext job;
  SearchOptions options;
  options.beamWidth = 0;
  auto result = decompose(makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)), MachineSpec{}, options, job);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().where, "beam width");
  options = SearchOptions{};
  options.candidates.offsetStepMm = -1;
  result = decompose(makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)), MachineSpec{}, options, job);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().where, "offset step");
}

TEST(Decompose, VolumeScalesOutsideOneToFourAreRefusedByName) {
  for (int scales : {0, 5, -1}) {
    SearchOptions options;
    options.volumeScales = scales;
    const Status valid = validate(options);
    ASSERT_FALSE(valid.ok()) << scales;
    EXPECT_EQ(valid.error().code, ErrorCode::InvalidParameter);
    EXPECT_EQ(valid.error().where, "volume scales");
    EXPECT_NE(valid.error().message.find("volume scales must be between 1 and 4"), std::string::npos)
        << valid.error().message;
  }
  for (int scales : {1, 4}) {
    SearchOptions options;
    options.volumeScales = scales;
    EXPECT_TRUE(validate(options).ok()) << scales;
  }
}

TEST(Decompose, EachRegionScaleHalvesTheSmallestRegionOfTheOneBefore) {
  SearchOptions options;
  options.minVolumeDivisor = 40;
  EXPECT_EQ(volumeDivisorOfScale(options, 0), 40.0);
  EXPECT_EQ(volumeDivisorOfScale(options, 1), 80.0);
  EXPECT_EQ(volumeDivisorOfScale(options, 3), 320.0);
}

TEST(Decompose, FinestVolumeDivisorIsTheLastScales) {
  // (The levels progress names: SearchProgressReports.TotalLevelsAreTheDeepestOneSearchMayReach.)
  SearchOptions options;
  options.minVolumeDivisor = 40;
  options.volumeScales = 2;
  EXPECT_EQ(finestVolumeDivisor(options), 80.0);
  options.volumeScales = 3;
  options.minVolumeDivisor = 2.5;
  EXPECT_EQ(finestVolumeDivisor(options), 10.0);
  options.scheme = SearchScheme::Greedy;  // the greedy schemes run at w alone
  EXPECT_EQ(finestVolumeDivisor(options), 2.5);
}

namespace {

// The smallest region a plan cuts off, as a share of the model's volume (1 when it cuts none off).
double smallestCutOffShare(const Decomposition& plan, double modelVolume) {
  double smallest = modelVolume;
  for (const Region& region : plan.regions)
    if (region.basePlane) smallest = std::min(smallest, region.volumeMm3);
  return smallest / modelVolume;
}

}  // namespace

TEST(Decompose, EveryRegionCutOffAtTwoScalesKeepsAtLeastVOverTwoW) {
  // The finer scale (2w) may cut off regions down to V/(2w), never smaller. Every plane found is kept, so no
  // small region is merged away after the search (the kitten's smallest was V/73.8 when this was written).
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  const SearchOptions options = optionsFor(SearchScheme::Beam);
  ASSERT_EQ(options.volumeScales, 2);
  const Decomposition plan = run(kitten, machineWithUp(Vec3::UnitY()), options);
  ASSERT_GE(plan.clippingPlanes.size(), 1u);
  EXPECT_GE(smallestCutOffShare(plan, signedVolume(kitten)), (1.0 - 1e-9) / (2.0 * options.minVolumeDivisor));
}

TEST(Decompose, EveryRegionCutOffAtOneScaleKeepsAtLeastVOverW) {
  // At one scale nothing below V/w is cut off, though at two the kitten's plan cuts off a region near V/74.
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  SearchOptions options = optionsFor(SearchScheme::Beam);
  options.volumeScales = 1;
  const Decomposition plan = run(kitten, machineWithUp(Vec3::UnitY()), options);
  ASSERT_GE(plan.clippingPlanes.size(), 1u);
  EXPECT_GE(smallestCutOffShare(plan, signedVolume(kitten)), (1.0 - 1e-9) / options.minVolumeDivisor);
}

// The one definition of J_G (docs/jg-definition.md): invariants that any honest count must keep.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <set>
#include <unistd.h>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/geometry/clipping.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/search/decompose.h"
#include "multidir/core/search/plan_from_planes.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir::core;
namespace fs = std::filesystem;

namespace {

MachineSpec machineWithUp(const Vec3& up, MachineKind kind = MachineKind::TiltRotate) {
  MachineSpec machine;
  machine.kind = kind;
  machine.up = up;
  machine.rotationAxis = platformFrameX(up);
  return machine;
}

Decomposition searched(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options = {}) {
  JobContext job;
  auto result = decompose(model, machine, options, job);
  if (!result.ok()) throw std::runtime_error(result.error().describe());
  return std::move(result).value();
}

// A box 20 x 20 x 20 mm on the bed (+Z up) with a slab 10 x 20 x 2 mm sticking out of its side at z = 16..18:
// the slab's 200 mm^2 underside faces straight down, 16 mm above the bed.
TriangleMesh boxWithSlab() {
  return multidir::test::makeExtrudedProfile(
      {Vec3(0, 0, 0), Vec3(20, 0, 0), Vec3(20, 0, 16), Vec3(30, 0, 16), Vec3(30, 0, 18), Vec3(20, 0, 18),
       Vec3(20, 0, 20), Vec3(0, 0, 20)},
      20.0);
}

double regionRisky(const TriangleMesh& mesh, const Vec3& direction, bool onPlatform) {
  OverhangOptions options;
  options.base = onPlatform ? RegionBase::Platform : RegionBase::CutPlane;
  return analyzeOverhang(mesh, direction, options)->riskyAreaMm2;
}

// Closed and consistently oriented: every directed edge appears once and its reverse once.
bool isClosed(const TriangleMesh& mesh) {
  std::set<std::pair<std::int32_t, std::int32_t>> edges;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (!edges.insert({t[k], t[(k + 1) % 3]}).second) return false;
  for (const auto& [a, b] : edges)
    if (!edges.count({b, a})) return false;
  return !mesh.triangles.empty();
}

PlanMetadata metadataFor(const MachineSpec& machine) {
  PlanMetadata metadata;
  metadata.machine = machine;
  metadata.up = machine.up;
  return metadata;
}

fs::path freshFolder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("multidir-jg-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

}  // namespace

TEST(Jg, BoxWithSlabCountsTheSlabUndersideBeforeAnyCut) {
  const TriangleMesh model = boxWithSlab();
  EXPECT_NEAR(regionRisky(model, Vec3::UnitZ(), true), 200.0, 1e-9);
}

TEST(Jg, ThreeDofPlanLeavesJgUnchanged) {
  // Horizontal cuts, everything printed along up: nothing can need less support than before.
  const MachineSpec machine = machineWithUp(Vec3::UnitY(), MachineKind::ThreeAxis);
  for (const char* name : {"kitten.off", "bunny.off", "fertility.off"}) {
    const TriangleMesh model = multidir::test::loadSharedModel(name);
    const BoundingBox box = boundingBox(model);
    const double low = box.min.y(), high = box.max.y();
    SearchOptions options;
    options.minPlaneGainPercent = 0;
    options.minPlaneGainMm2 = 0;
    const auto plan = planFromClippingPlanes(
        model, machine, options, {Plane{Vec3::UnitY(), low + 0.7 * (high - low)}, Plane{Vec3::UnitY(), low + 0.4 * (high - low)}});
    ASSERT_TRUE(plan.ok()) << name << ": " << plan.error().describe();
    EXPECT_EQ(plan->regions.size(), 3u) << name;
    EXPECT_NEAR(plan->jgAfterMm2, plan->jgBeforeMm2, 1e-6 * plan->jgBeforeMm2) << name;
  }
}

TEST(Jg, ThreeDofSearchReportsJgAfterEqualToBefore) {
  for (const char* name : {"kitten.off", "bunny.off", "fertility.off"}) {
    const Decomposition plan =
        searched(multidir::test::loadSharedModel(name), machineWithUp(Vec3::UnitY(), MachineKind::ThreeAxis));
    EXPECT_NEAR(plan.jgAfterMm2, plan.jgBeforeMm2, 1e-6 * plan.jgBeforeMm2) << name;
  }
}

TEST(Jg, FlatOverhangJustAboveACutPlaneStillCounts) {
  const TriangleMesh model = boxWithSlab();
  SearchOptions options;
  options.minRegionHeightMm = 0;
  options.minPlaneGainPercent = 0;
  options.minPlaneGainMm2 = 0;
  for (const double gap : {0.3, 0.6, 0.9}) {
    // A horizontal plane (3-DOF) and one tilted 3 degrees from up (5-DOF), each `gap` under the slab.
    const auto flat = planFromClippingPlanes(model, machineWithUp(Vec3::UnitZ(), MachineKind::ThreeAxis), options,
                                             {Plane{Vec3::UnitZ(), 16.0 - gap}});
    ASSERT_TRUE(flat.ok()) << flat.error().describe();
    EXPECT_NEAR(flat->jgAfterMm2, 200.0, 1e-6) << "gap " << gap;

    const Vec3 tilted = Vec3(-std::sin(degToRad(3.0)), 0, std::cos(degToRad(3.0)));
    const double offset = std::min(tilted.dot(Vec3(20, 0, 16)), tilted.dot(Vec3(30, 0, 16))) - gap;
    const auto tilt = planFromClippingPlanes(model, machineWithUp(Vec3::UnitZ()), options, {Plane{tilted, offset}});
    ASSERT_TRUE(tilt.ok()) << tilt.error().describe();
    EXPECT_GE(tilt->regions.back().riskyAreaMm2, 200.0 - 1e-6) << "gap " << gap;
  }
}

TEST(Jg, CuttingTheSlabOffAlongATiltedDirectionLeavesNothingToSupport) {
  // The worked example of docs/jg-definition.md: the slab printed 50 degrees from up, on its cap through the
  // slab's root, needs no support: its underside is then within alpha of the printing direction's horizon.
  const Vec3 d(std::sin(degToRad(50.0)), 0, std::cos(degToRad(50.0)));
  const auto plan = planFromClippingPlanes(boxWithSlab(), machineWithUp(Vec3::UnitZ()), SearchOptions{},
                                           {Plane{d, d.dot(Vec3(20, 0, 16))}});
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  EXPECT_NEAR(plan->jgBeforeMm2, 200.0, 1e-9);
  EXPECT_NEAR(plan->jgAfterMm2, 0.0, 1e-9);
}

TEST(Jg, RecomputedFromSavedRegionMeshesEqualsReported) {
  for (const char* name : {"kitten.off", "bunny.off"}) {
    const MachineSpec machine = machineWithUp(Vec3::UnitY());
    const Decomposition plan = searched(multidir::test::loadSharedModel(name), machine);
    ASSERT_GT(plan.regions.size(), 1u) << name;
    const fs::path dir = freshFolder(name);
    const Status written = savePlan(plan, metadataFor(machine), dir.string());
    ASSERT_TRUE(written.ok()) << name << ": " << written.error().describe();
    double total = 0;
    for (std::size_t i = 0; i < plan.regions.size(); ++i) {
      char file[32];
      std::snprintf(file, sizeof file, "region-%02zu.stl", i + 1);
      const auto loaded = loadMesh((dir / file).string());
      ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
      // Only the STL and the printing direction: the cap is told by lying in the region's lowest level.
      const double risky = regionRisky(loaded->mesh, plan.regions[i].printingDirection, i == 0);
      EXPECT_NEAR(risky, plan.regions[i].riskyAreaMm2, 1e-5 * plan.jgBeforeMm2) << name << " region " << i;
      total += risky;
    }
    EXPECT_NEAR(total, plan.jgAfterMm2, 1e-5 * plan.jgBeforeMm2) << name;
    fs::remove_all(dir);
  }
}

TEST(Jg, NoRegionIsThinnerThanTheMinimumHeight) {
  for (const char* name : {"kitten.off", "bunny.off", "fertility.off"}) {
    const SearchOptions options;
    const Decomposition plan = searched(multidir::test::loadSharedModel(name), machineWithUp(Vec3::UnitY()), options);
    for (std::size_t i = 0; i < plan.regions.size(); ++i) {
      const Region& region = plan.regions[i];
      double low = INFINITY, high = -INFINITY;
      for (const Vec3& v : region.mesh.vertices) {
        low = std::min(low, region.printingDirection.dot(v));
        high = std::max(high, region.printingDirection.dot(v));
      }
      EXPECT_GE(high - low, options.minRegionHeightMm - 1e-6) << name << " region " << i;
    }
  }
}

TEST(Jg, ThinPlatformRegionIsRefusedWithTheReason) {
  // The exploit found on the kitten: a plane a fraction of a millimetre above the bed.
  const TriangleMesh model = multidir::test::loadSharedModel("kitten.off");
  const double bed = boundingBox(model).min.y();
  const auto plan = planFromClippingPlanes(model, machineWithUp(Vec3::UnitY()), SearchOptions{},
                                           {Plane{Vec3(0.02, 1, 0).normalized(), bed + 0.4}});
  ASSERT_FALSE(plan.ok());
  EXPECT_NE(plan.error().message.find("tall"), std::string::npos) << plan.error().message;
}

TEST(Jg, EveryPlaneOfADefaultPlanPaysForItself) {
  const TriangleMesh model = multidir::test::loadSharedModel("kitten.off");
  const MachineSpec machine = machineWithUp(Vec3::UnitY());
  const SearchOptions options;
  const Decomposition plan = searched(model, machine, options);
  const double threshold =
      std::max(options.minPlaneGainMm2, options.minPlaneGainPercent / 100.0 * plan.jgBeforeMm2);
  for (std::size_t k = 0; k < plan.clippingPlanes.size(); ++k) {
    std::vector<Plane> fewer = plan.clippingPlanes;
    fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(k));
    const auto without = planFromClippingPlanes(model, machine, options, fewer);
    if (without.ok()) {
      EXPECT_GE(without->jgAfterMm2 - plan.jgAfterMm2, threshold - 1e-6) << "plane " << k + 1;
    }
  }
}

TEST(Jg, PlanesThroughVerticesStillGiveRegionsThatSaveClosed) {
  // Planes through model vertices, exactly: the regions must survive the float round trip of a binary STL.
  const TriangleMesh model = multidir::test::loadSharedModel("kitten.off");
  const MachineSpec machine = machineWithUp(Vec3::UnitY());
  SearchOptions options;
  options.minPlaneGainPercent = 0;
  options.minPlaneGainMm2 = 0;
  std::mt19937 random(11);
  int saved = 0;
  for (int trial = 0; trial < 40 && saved < 6; ++trial) {
    const Vec3& vertex = model.vertices[std::uniform_int_distribution<std::size_t>(0, model.vertices.size() - 1)(random)];
    const double tilt = std::uniform_real_distribution<double>(0.3, 1.2)(random);
    const double turn = std::uniform_real_distribution<double>(0, 2 * kPi)(random);
    const Vec3 n = Vec3(std::sin(tilt) * std::cos(turn), std::cos(tilt), std::sin(tilt) * std::sin(turn)).normalized();
    const auto plan = planFromClippingPlanes(model, machine, options, {Plane{n, n.dot(vertex)}});
    if (!plan.ok()) continue;  // a plane that breaks a criterion: not what this test is about
    const fs::path dir = freshFolder("vertex" + std::to_string(trial));
    const Status written = savePlan(*plan, metadataFor(machine), dir.string());
    ASSERT_TRUE(written.ok()) << written.error().describe();
    const auto reloaded = loadPlan(dir.string());
    ASSERT_TRUE(reloaded.ok()) << reloaded.error().describe();
    for (const Region& region : reloaded->decomposition.regions) EXPECT_TRUE(isClosed(region.mesh));
    fs::remove_all(dir);
    ++saved;
  }
  EXPECT_GE(saved, 3);
}

TEST(Jg, GridAlignedModelSearchedAndSaved) {
  // Every vertex on the 1 mm grid, as the candidate offsets are: a stepped pyramid upside down.
  std::vector<Vec3> profile = {Vec3(10, 0, 0), Vec3(20, 0, 0), Vec3(20, 0, 4), Vec3(25, 0, 4), Vec3(25, 0, 8),
                               Vec3(30, 0, 8), Vec3(30, 0, 12), Vec3(0, 0, 12), Vec3(0, 0, 8), Vec3(5, 0, 8),
                               Vec3(5, 0, 4), Vec3(10, 0, 4)};
  const TriangleMesh model = multidir::test::makeExtrudedProfile(profile, 10.0);
  for (const MachineKind kind : {MachineKind::TiltRotate, MachineKind::RotaryPlatform}) {
    const MachineSpec machine = machineWithUp(Vec3::UnitZ(), kind);
    const Decomposition plan = searched(model, machine);
    const fs::path dir = freshFolder("grid");
    const Status written = savePlan(plan, metadataFor(machine), dir.string());
    ASSERT_TRUE(written.ok()) << written.error().describe();
    fs::remove_all(dir);
  }
}

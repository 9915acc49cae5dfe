// Projected tree supports (paper Section V): overhang sampling, tree growth inside each region's sub-space,
// progressive projection, strut radii (Eq. 14), solids, and the fixed- against multi-direction comparison.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/search/decompose.h"
#include "multidir/core/supports/projected_supports.h"
#include "multidir/core/supports/support_report.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir::core;
using multidir::test::makeBox;
using multidir::test::makeTBar;

namespace {

TriangleMesh translated(TriangleMesh mesh, const Vec3& by) {
  for (Vec3& v : mesh.vertices) v += by;
  return mesh;
}

ProjectedSupports fixedSupports(const TriangleMesh& model, const Vec3& up, const SupportOptions& options = {}) {
  JobContext job;
  auto result = generateFixedDirectionSupports(model, up, options, job);
  if (!result.ok()) throw std::runtime_error(result.error().describe());
  return std::move(result).value();
}

MachineSpec machineWithUp(const Vec3& up) {
  MachineSpec machine;
  machine.up = up;
  return machine;
}

// The kitten cut by a quick beam search (width 2), with its projected supports: shared by several tests.
struct KittenPlan {
  TriangleMesh model;
  MachineSpec machine;
  Decomposition plan;
  ProjectedSupports supports;
};

const KittenPlan& kittenPlan() {
  static const KittenPlan result = [] {
    KittenPlan k;
    k.model = multidir::test::loadSharedModel("kitten.off");
    k.machine = machineWithUp(Vec3::UnitY());
    SearchOptions search;
    search.beamWidth = 2;
    JobContext job;
    k.plan = decompose(k.model, k.machine, search, job).value();
    k.supports = generateSupports(k.model, k.plan, k.machine, SupportOptions{}, job).value();
    return k;
  }();
  return result;
}

// Which nodes each strut ends on, and what leaves each node.
std::vector<int> outgoingCount(const ProjectedSupports& s) {
  std::vector<int> out(s.nodes.size(), 0);
  for (const SupportStrut& strut : s.struts) ++out[static_cast<std::size_t>(strut.upper)];
  return out;
}

// Follows the struts down from every node; returns the kinds of the nodes where the paths end.
std::set<SupportNodeKind> pathEnds(const ProjectedSupports& s) {
  std::vector<int> below(s.nodes.size(), -1);
  for (const SupportStrut& strut : s.struts) below[static_cast<std::size_t>(strut.upper)] = strut.lower;
  std::set<SupportNodeKind> ends;
  for (std::size_t n = 0; n < s.nodes.size(); ++n)
    if (below[n] < 0) ends.insert(s.nodes[n].kind);
  return ends;
}

// Whether the segment crosses any face of the mesh (brute force, independent of the generator's grid).
bool crossesMesh(const TriangleMesh& mesh, const Vec3& from, const Vec3& to) {
  const Vec3 delta = to - from;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Vec3 &a = mesh.corner(f, 0), e1 = mesh.corner(f, 1) - a, e2 = mesh.corner(f, 2) - a;
    const Vec3 p = delta.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-18) continue;
    const Vec3 s = from - a;
    const double u = s.dot(p) / det;
    const Vec3 q = s.cross(e1);
    const double v = delta.dot(q) / det;
    const double t = e2.dot(q) / det;
    if (u >= 0 && v >= 0 && u + v <= 1 && t >= 0 && t <= 1) return true;
  }
  return false;
}

bool insideOmega(const Decomposition& plan, std::size_t region, const Vec3& p, double tolerance) {
  const std::size_t planes = plan.clippingPlanes.size();
  const std::size_t k = region == 0 ? planes : planes - region;  // region 0 lies below every plane
  for (std::size_t j = 0; j < k; ++j)
    if (plan.clippingPlanes[j].signedDistance(p) > tolerance) return false;
  return k == planes || plan.clippingPlanes[k].signedDistance(p) >= -tolerance;
}

}  // namespace

TEST(OverhangSampling, BoxHasNoOverhang) {
  const auto samples = sampleOverhangs(makeBox(Vec3(0, 0, 0), Vec3(20, 20, 20)), Vec3::UnitZ());
  ASSERT_TRUE(samples.ok());
  EXPECT_TRUE(samples->empty());
}

TEST(OverhangSampling, SlabUndersideIsSampledOnTheGrid) {
  // Bar 31 x 9 at height 20 on a 6 x 9 stem; shifted half a millimetre so no grid line runs along an edge.
  const TriangleMesh slab = translated(makeTBar(6, 20, 31, 4, 9), Vec3(0, 0.5, 0));
  const auto samples = sampleOverhangs(slab, Vec3::UnitZ());
  ASSERT_TRUE(samples.ok());
  // x in {-14, ..., -4, 4, ..., 14}, y in {2, 4, 6, 8}: 12 x 4 grid points.
  EXPECT_EQ(samples->size(), 48u);
  for (const OverhangSample& s : *samples) {
    EXPECT_EQ(s.kind, OverhangKind::Face);
    EXPECT_NEAR(s.position.z(), 20.0, 1e-9);
  }
}

TEST(OverhangSampling, InvertedPyramidTipIsAPointOverhang) {
  // A pyramid on its apex lifted above a base block: the apex hangs lower than all its neighbours.
  TriangleMesh pyramid = translated(multidir::test::makeInvertedPyramid(10, 10), Vec3(0, 0, 5));
  // Its faces rise 63 degrees from the horizontal, printable at alpha 45: only the apex hangs.
  TriangleMesh model = pyramid;
  const TriangleMesh block = makeBox(Vec3(-20, -20, 0), Vec3(-15, -15, 1));
  const auto offset = static_cast<std::int32_t>(model.vertices.size());
  model.vertices.insert(model.vertices.end(), block.vertices.begin(), block.vertices.end());
  for (Triangle t : block.triangles) model.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  model.resetOrigins();
  const auto samples = sampleOverhangs(model, Vec3::UnitZ());
  ASSERT_TRUE(samples.ok());
  ASSERT_EQ(samples->size(), 1u);
  EXPECT_EQ((*samples)[0].kind, OverhangKind::Point);
  EXPECT_NEAR(((*samples)[0].position - Vec3(0, 0, 5)).norm(), 0.0, 1e-9);
}

TEST(Supports, BoxGetsNone) {
  const ProjectedSupports s = fixedSupports(makeBox(Vec3(0, 0, 0), Vec3(20, 20, 20)), Vec3::UnitZ());
  EXPECT_TRUE(s.struts.empty());
  EXPECT_EQ(s.volumeMm3, 0.0);
  ASSERT_EQ(s.regions.size(), 1u);
  EXPECT_TRUE(s.regions[0].mesh.empty());
}

TEST(Supports, TBarAlongUpReachesThePlatform) {
  const ProjectedSupports s = fixedSupports(makeTBar(10, 30, 80, 10, 10), Vec3::UnitZ());
  ASSERT_FALSE(s.struts.empty());
  EXPECT_GT(s.statistics.onPlatform, 0);
  EXPECT_EQ(s.statistics.onModel, 0);
  EXPECT_EQ(s.statistics.stuck, 0);
  EXPECT_EQ(pathEnds(s), std::set<SupportNodeKind>{SupportNodeKind::Platform});
  EXPECT_GT(s.statistics.merges, 0);  // neighbouring struts join into trees
  for (const SupportNode& node : s.nodes) EXPECT_GE(node.position.z(), -1e-9);
}

TEST(Supports, EveryStrutEndsOnThePlatformTheModelOrAnotherStrut) {
  const ProjectedSupports& s = kittenPlan().supports;
  ASSERT_FALSE(s.struts.empty());
  const std::vector<int> out = outgoingCount(s);
  for (std::size_t n = 0; n < s.nodes.size(); ++n) {
    const SupportNodeKind kind = s.nodes[n].kind;
    if (kind == SupportNodeKind::Platform || kind == SupportNodeKind::Model || kind == SupportNodeKind::Stuck)
      EXPECT_EQ(out[n], 0) << "node " << n;
    else
      EXPECT_EQ(out[n], 1) << "node " << n << " (" << supportNodeKindName(kind) << ") must go on down";
  }
  for (SupportNodeKind end : pathEnds(s))
    EXPECT_TRUE(end == SupportNodeKind::Platform || end == SupportNodeKind::Model || end == SupportNodeKind::Stuck);
  EXPECT_EQ(s.statistics.stuck, 0);
}

TEST(Supports, EveryNodeLiesInsideItsRegionsSubSpace) {
  const KittenPlan& k = kittenPlan();
  ASSERT_GE(k.plan.regions.size(), 2u);
  ASSERT_EQ(k.supports.regions.size(), k.plan.regions.size());
  std::size_t checked = 0;
  for (std::size_t r = 0; r < k.supports.regions.size(); ++r)
    for (const SupportNode& node : k.supports.regions[r].nodes) {
      EXPECT_TRUE(insideOmega(k.plan, r, node.position, 1e-6)) << "region " << r << " node at "
                                                                 << node.position.transpose();
      ++checked;
    }
  EXPECT_GT(checked, 0u);
}

TEST(Supports, ProjectionCarriesStrutsIntoTheSubSpaceBelow) {
  const KittenPlan& k = kittenPlan();
  // A strut crossing a base plane ends on a plane node in its region and goes on in an earlier one.
  std::map<int, int> regionAbove, regionBelow;
  for (std::size_t s = 0; s < k.supports.struts.size(); ++s) {
    const SupportStrut& strut = k.supports.struts[s];
    if (k.supports.nodes[static_cast<std::size_t>(strut.lower)].kind == SupportNodeKind::Plane)
      regionAbove[strut.lower] = k.supports.strutRegion[s];
    if (k.supports.nodes[static_cast<std::size_t>(strut.upper)].kind == SupportNodeKind::Plane)
      regionBelow[strut.upper] = k.supports.strutRegion[s];
  }
  EXPECT_GT(k.supports.statistics.projections, 0);
  EXPECT_EQ(static_cast<int>(regionAbove.size()), k.supports.statistics.projections);
  for (const auto& [node, above] : regionAbove) {
    ASSERT_TRUE(regionBelow.count(node)) << "plane node " << node << " is not carried on";
    EXPECT_LT(regionBelow[node], above);
  }
}

TEST(Supports, StrutsStayOutOfTheModelExceptAtTheirTips) {
  const KittenPlan& k = kittenPlan();
  std::size_t tested = 0;
  for (const SupportStrut& strut : k.supports.struts) {
    Vec3 top = k.supports.nodes[static_cast<std::size_t>(strut.upper)].position;
    Vec3 bottom = k.supports.nodes[static_cast<std::size_t>(strut.lower)].position;
    const Vec3 along = (bottom - top).normalized();
    // Contact tips touch the model at one end: leave out the last micrometre there.
    if (k.supports.nodes[static_cast<std::size_t>(strut.upper)].kind == SupportNodeKind::Contact) top += 1e-3 * along;
    if (k.supports.nodes[static_cast<std::size_t>(strut.lower)].kind == SupportNodeKind::Model) bottom -= 1e-3 * along;
    EXPECT_FALSE(crossesMesh(k.model, top, bottom)) << "strut from " << top.transpose() << " to "
                                                          << bottom.transpose();
    ++tested;
  }
  EXPECT_GT(tested, 0u);
}

TEST(Supports, StrutRadiusFollowsEquation14) {
  EXPECT_DOUBLE_EQ(strutRadiusMm(2.0, 1e-6, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(strutRadiusMm(3.0, 1e-6, 0.0), 0.75);
  // 1000 mm^3 with a 10 mm lever across gravity: torque 1e4 mm^4, so the radius grows by 1 %.
  const Vec3 torque = gravityTorque({1000.0}, {Vec3(10, 0, 5)}, Vec3(0, 0, 0), Vec3(0, 0, -1));
  EXPECT_NEAR(torque.norm(), 1e4, 1e-9);
  EXPECT_NEAR(strutRadiusMm(2.0, 1e-6, torque.norm()), 0.505, 1e-12);
  // Two pieces balanced about the pivot cancel; a piece straight above it has no lever.
  EXPECT_NEAR(gravityTorque({500.0, 500.0}, {Vec3(4, 0, 1), Vec3(-4, 0, 3)}, Vec3::Zero(), Vec3(0, 0, -1)).norm(), 0.0,
              1e-9);
  EXPECT_NEAR(gravityTorque({800.0}, {Vec3(0, 0, 7)}, Vec3::Zero(), Vec3(0, 0, -1)).norm(), 0.0, 1e-12);
}

TEST(Supports, LeaningTreeThickensItsTrunk) {
  // The T-bar's trees merge sideways: the struts under a merge carry a lever and are thicker than R/4.
  const ProjectedSupports s = fixedSupports(makeTBar(10, 30, 80, 10, 10), Vec3::UnitZ());
  double thickest = 0.0;
  for (const SupportStrut& strut : s.struts) thickest = std::max(thickest, strut.upperRadiusMm);
  EXPECT_GT(thickest, 0.5);
  EXPECT_LT(thickest, 0.6);  // lambda = 1e-6 makes the effect small, as in the paper
}

TEST(Supports, VolumeOfColumnsUnderAFloatingSlabMatchesTheAnalyticValue) {
  const TriangleMesh slab = translated(makeTBar(6, 20, 31, 4, 9), Vec3(0, 0.5, 0));
  SupportOptions options;
  options.mergeStruts = false;
  const ProjectedSupports s = fixedSupports(slab, Vec3::UnitZ(), options);
  // 48 columns: a tip cone 1 mm long from 0.2 to 0.5 mm radius, then a 19 mm strut of radius 0.5 mm.
  const double tip = kPi * 1.0 * (0.2 * 0.2 + 0.2 * 0.5 + 0.5 * 0.5) / 3.0;
  const double expected = 48 * (tip + kPi * 0.25 * 19.0);
  EXPECT_NEAR(s.volumeMm3, expected, 0.05 * expected);
  EXPECT_NEAR(signedVolume(s.regions[0].mesh), expected, 0.05 * expected);
  EXPECT_EQ(s.contacts, 48);
  EXPECT_NEAR(s.contactAreaMm2, 48 * kPi * 0.04, 1e-9);
}

TEST(Supports, SolidsAreClosedAndOutward) {
  const ProjectedSupports s = fixedSupports(makeTBar(10, 30, 80, 10, 10), Vec3::UnitZ());
  const TriangleMesh& mesh = s.regions[0].mesh;
  ASSERT_FALSE(mesh.empty());
  EXPECT_TRUE(edgeCensus(mesh).closedOriented());
  EXPECT_GT(signedVolume(mesh), 0.0);
  EXPECT_EQ(mesh.origins.size(), mesh.triangles.size());
}

TEST(Supports, RejectsInconsistentPlan) {
  Decomposition plan;
  plan.regions.resize(2);
  JobContext job;
  const auto result = generateSupports(makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)), plan, MachineSpec{}, {}, job);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::InvalidParameter);
}

TEST(Supports, RejectsBadOptions) {
  SupportOptions options;
  options.samplingSpacingMm = 0;
  JobContext job;
  const auto result = generateFixedDirectionSupports(makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)), Vec3::UnitZ(), options, job);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().where, "samplingSpacingMm");
}

TEST(Supports, CancelledJobGivesNoPartialResult) {
  JobContext job;
  job.cancel();
  const auto result = generateFixedDirectionSupports(makeTBar(10, 30, 80, 10, 10), Vec3::UnitZ(), {}, job);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::Cancelled);
}

TEST(SupportReport, MultiDirectionNeedsLessSupportOnKittenAndFertility) {
  for (const char* name : {"kitten.off", "fertility.off"}) {
    SearchOptions search;
    search.beamWidth = 2;
    JobContext job;
    const auto report = supportReport(multidir::test::loadSharedModel(name), machineWithUp(Vec3::UnitY()), search, {}, job);
    ASSERT_TRUE(report.ok()) << name << ": " << report.error().describe();
    EXPECT_GT(report->fixedVolumeMm3, 0.0) << name;
    EXPECT_LT(report->multiVolumeMm3, report->fixedVolumeMm3) << name;
    EXPECT_LT(report->jgAfterMm2, report->jgBeforeMm2) << name;
  }
}

TEST(SupportPlan, SupportsRoundTripThroughThePlanFolder) {
  const KittenPlan& k = kittenPlan();
  const std::string dir = multidir::test::scratchDirectory("SupportPlanRoundTrip");
  PlanMetadata metadata;
  metadata.up = k.machine.up;
  metadata.machine = k.machine;
  metadata.multidirVersion = "test";
  ASSERT_TRUE(savePlan(k.plan, metadata, k.supports.regions, dir).ok());
  const auto loaded = loadPlan(dir);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  ASSERT_EQ(loaded->supports.size(), k.supports.regions.size());
  for (std::size_t r = 0; r < loaded->supports.size(); ++r) {
    const SupportSet& saved = k.supports.regions[r];
    const SupportSet& read = loaded->supports[r];
    EXPECT_EQ(read.regionIndex, static_cast<int>(r));
    ASSERT_EQ(read.struts.size(), saved.struts.size());
    ASSERT_EQ(read.nodes.size(), saved.nodes.size());
    EXPECT_EQ(read.mesh.triangles.size(), saved.mesh.triangles.size());
    EXPECT_DOUBLE_EQ(read.volumeMm3, saved.volumeMm3);
    EXPECT_EQ(read.contacts, saved.contacts);
    for (std::size_t n = 0; n < read.nodes.size(); ++n) {
      EXPECT_EQ(read.nodes[n].position, saved.nodes[n].position);
      EXPECT_EQ(read.nodes[n].kind, saved.nodes[n].kind);
    }
    const bool file = std::ifstream(dir + "/region-0" + std::to_string(r + 1) + "-supports.stl").good();
    EXPECT_EQ(file, !saved.empty()) << "region " << r;
  }
}

TEST(SupportPlan, PlanWithoutSupportsLoadsEmptySets) {
  const KittenPlan& k = kittenPlan();
  const std::string dir = multidir::test::scratchDirectory("SupportPlanNone");
  PlanMetadata metadata;
  metadata.up = k.machine.up;
  metadata.machine = k.machine;
  ASSERT_TRUE(savePlan(k.plan, metadata, dir).ok());
  const auto loaded = loadPlan(dir);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  ASSERT_EQ(loaded->supports.size(), k.plan.regions.size());
  for (const SupportSet& set : loaded->supports) EXPECT_TRUE(set.empty());
}

TEST(SupportPlan, RefusesOneSetTooFew) {
  const KittenPlan& k = kittenPlan();
  std::vector<SupportSet> sets = k.supports.regions;
  sets.pop_back();
  const Status saved = savePlan(k.plan, PlanMetadata{}, sets, multidir::test::scratchDirectory("SupportPlanFew"));
  ASSERT_FALSE(saved.ok());
  EXPECT_EQ(saved.error().code, ErrorCode::InvalidParameter);
}

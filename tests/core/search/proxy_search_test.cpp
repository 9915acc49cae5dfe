#include <gtest/gtest.h>

#include <set>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/mesh/mesh_resolution.h"
#include "multidir/core/search/decompose.h"
#include "multidir/core/search/plan_from_planes.h"
#include "multidir/core/search/pose_search.h"
#include "search/run_decomposition.h"
#include "support/test_models.h"
#include "support/up_y_machine.h"

using namespace multidir::core;

namespace {

using multidir::test::upY;

Decomposition run(const TriangleMesh& model, const SearchOptions& options) {
  JobContext job;
  auto plan = decompose(model, upY(), options, job);
  if (!plan.ok()) throw std::runtime_error(plan.error().describe());
  return std::move(plan).value();
}

// The kitten with four times its faces (the same surface), searched on a proxy of at most 20,000 faces.
struct ProxySearch : ::testing::Test {
  static void SetUpTestSuite() {
    kitten = new TriangleMesh(multidir::test::loadSharedModel("kitten.off"));
    fine = new TriangleMesh(subdivided(*kitten, 1).value());
    SearchOptions options;
    options.proxyFaces = 20000;
    proxyPlan = new Decomposition(run(*fine, options));
  }
  static void TearDownTestSuite() {
    delete kitten;
    delete fine;
    delete proxyPlan;
  }
  static TriangleMesh* kitten;
  static TriangleMesh* fine;
  static Decomposition* proxyPlan;
};
TriangleMesh* ProxySearch::kitten = nullptr;
TriangleMesh* ProxySearch::fine = nullptr;
Decomposition* ProxySearch::proxyPlan = nullptr;

}  // namespace

TEST_F(ProxySearch, AModelAboveTheFaceCountIsSearchedOnAProxyAndTheLogSaysSo) {
  EXPECT_GT(proxyPlan->statistics.proxyFaces, 0);
  EXPECT_LE(proxyPlan->statistics.proxyFaces, 20000);
  ASSERT_FALSE(proxyPlan->statistics.notes.empty());
  EXPECT_NE(proxyPlan->statistics.notes.front().find("proxy"), std::string::npos);
}

TEST_F(ProxySearch, EveryNumberIsTheFullMeshs) {
  // The same planes cut through the full mesh by the plain evaluator give the same plan.
  const auto again = planFromClippingPlanes(*fine, upY(), SearchOptions{}, proxyPlan->clippingPlanes);
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_NEAR(again->jgAfterMm2, proxyPlan->jgAfterMm2, 1e-9 * proxyPlan->jgBeforeMm2);
  EXPECT_NEAR(proxyPlan->jgBeforeMm2, again->jgBeforeMm2, 1e-9 * proxyPlan->jgBeforeMm2);
  double volume = 0;
  std::size_t faces = 0;
  for (const Region& region : proxyPlan->regions) {
    volume += region.volumeMm3;
    faces += region.mesh.faceCount();
  }
  EXPECT_NEAR(volume, signedVolume(*fine), 1e-9 * volume);
  EXPECT_GT(faces, fine->faceCount());  // the regions are pieces of the full mesh, not of the proxy
}

TEST_F(ProxySearch, GivesTheSamePlanOnOneThreadAsOnAll) {
  // The fixture's search ran on all threads (two or more on the machines that run the tests).
  SearchOptions options;
  options.proxyFaces = 20000;
  options.threads = 1;
  const Decomposition one = run(*fine, options);
  EXPECT_EQ(one.statistics.proxyFaces, proxyPlan->statistics.proxyFaces);
  EXPECT_EQ(one.jgAfterMm2, proxyPlan->jgAfterMm2);
  ASSERT_EQ(one.clippingPlanes.size(), proxyPlan->clippingPlanes.size());
  for (std::size_t k = 0; k < one.clippingPlanes.size(); ++k) {
    EXPECT_EQ(one.clippingPlanes[k].normal, proxyPlan->clippingPlanes[k].normal) << "plane " << k + 1;
    EXPECT_EQ(one.clippingPlanes[k].offset, proxyPlan->clippingPlanes[k].offset) << "plane " << k + 1;
  }
  // The full mesh's cuts measure each region on two threads when there are two: the same numbers on one.
  ASSERT_EQ(one.regions.size(), proxyPlan->regions.size());
  for (std::size_t r = 0; r < one.regions.size(); ++r) {
    EXPECT_EQ(one.regions[r].riskyAreaMm2, proxyPlan->regions[r].riskyAreaMm2) << "region " << r + 1;
    EXPECT_EQ(one.regions[r].volumeMm3, proxyPlan->regions[r].volumeMm3) << "region " << r + 1;
    EXPECT_EQ(one.regions[r].mesh.faceCount(), proxyPlan->regions[r].mesh.faceCount()) << "region " << r + 1;
  }
}

TEST_F(ProxySearch, ThePlanIsWithinATenthOfTheOriginalModelsPlan) {
  const Decomposition original = run(*kitten, SearchOptions{});
  const double proxyShare = proxyPlan->jgAfterMm2 / proxyPlan->jgBeforeMm2;
  const double originalShare = original.jgAfterMm2 / original.jgBeforeMm2;
  EXPECT_LE(proxyShare, 1.1 * originalShare + 1e-4) << proxyPlan->jgAfterMm2 << " vs " << original.jgAfterMm2;
}

TEST_F(ProxySearch, AModelAtOrBelowTheFaceCountIsSearchedInFull) {
  SearchOptions options;
  options.proxyFaces = 50000;
  options.beamWidth = 2;
  const Decomposition plan = run(*fine, options);
  EXPECT_EQ(plan.statistics.proxyFaces, 0);
  options.proxyFaces = 0;  // --no-proxy
  EXPECT_EQ(run(*fine, options).statistics.proxyFaces, 0);
}

TEST_F(ProxySearch, AnAxisSearchOfAHugeModelRunsOnTheProxyAndCutsTheFullMesh) {
  MachineSpec rotary = upY();
  rotary.kind = MachineKind::RotaryPlatform;
  rotary.rotationAxis = platformFrameX(rotary.up);
  SearchOptions options;
  options.proxyFaces = 20000;
  JobContext job;
  const auto plan = decomposeWithAxisSearch(*fine, rotary, options, 12, job);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  EXPECT_GT(plan->statistics.proxyFaces, 0);
  MachineSpec chosen = rotary;
  chosen.rotationAxis = plan->rotationAxis;
  const auto again = planFromClippingPlanes(*fine, chosen, SearchOptions{}, plan->clippingPlanes);
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_NEAR(again->jgAfterMm2, plan->jgAfterMm2, 1e-9 * plan->jgBeforeMm2);
}

namespace {

// Scan-like noise: every vertex moved along its normal by a pseudo-random amount in [-amplitude, amplitude]
// (the bench's noisy_surface.h, a hash of the vertex index).
void addNoise(TriangleMesh& mesh, double amplitudeMm) {
  std::vector<Vec3> normals(mesh.vertices.size(), Vec3::Zero());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (std::int32_t v : mesh.triangles[f]) normals[static_cast<std::size_t>(v)] += mesh.areaNormal(f);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    std::uint64_t h = v * 0x9e3779b97f4a7c15ull;
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 29;
    const double unit = static_cast<double>(h % 2000001) / 1000000.0 - 1.0;
    mesh.vertices[v] += amplitudeMm * unit * normals[v].normalized();
  }
}

}  // namespace

TEST(ProxyTolerance, ScanNoiseAPrinterCannotResolveIsSimplifiedAwayAndTheNoteSaysWhatItMoved) {
  // The knight with 64 times its faces and 0.02 mm of noise: no collapse of the noisy surface moves it by less
  // than 0.01 mm (a proxy at that tolerance kept 19,872 faces), while its noise lies within half a 0.2 mm
  // layer: the proxy goes down to the floor of 10,000 faces.
  TriangleMesh noisy = subdivided(multidir::test::loadSharedModel("knight.off"), 3).value();
  addNoise(noisy, 0.02);
  SearchOptions options;
  options.proxyFaces = 20000;
  options.polish = false;
  const Decomposition plan = run(noisy, options);
  EXPECT_GT(plan.statistics.proxyFaces, 0);
  EXPECT_LE(plan.statistics.proxyFaces, 10000);
  ASSERT_FALSE(plan.statistics.notes.empty());
  EXPECT_NE(plan.statistics.notes.front().find("of the risky area along up"), std::string::npos);
}

TEST(ProxyTolerance, EachOfSeveralUpsGetsTheProxyItsOwnSearchMakesAndEachProxyIsMadeOnce) {
  // The fandisk with 16 times its faces and 0.05 mm of noise, along twelve of its poses: along two of them the
  // proxy's tolerance moved more than a tenth of the risky area (the strict proxy), along the others not.
  TriangleMesh noisy = subdivided(multidir::test::loadSharedModel("fandisk.off"), 2).value();
  addNoise(noisy, 0.05);
  SearchOptions options;
  options.proxyFaces = static_cast<int>(noisy.faceCount() / 3);
  PoseOptions twelve;
  twelve.poses = 12;
  const auto poses = candidatePoses(noisy, Vec3::UnitY(), twelve, options);
  ASSERT_TRUE(poses.ok()) << poses.error().describe();
  std::vector<Vec3> ups;
  for (const PoseCandidate& pose : *poses) ups.push_back(pose.up);
  const std::vector<Result<detail::SearchProxy>> proxies = detail::makeSearchProxies(noisy, ups, options);
  ASSERT_EQ(proxies.size(), ups.size());
  std::set<const TriangleMesh*> meshes, strict;
  for (std::size_t u = 0; u < ups.size(); ++u) {
    const Result<detail::SearchProxy> own = detail::makeSearchProxy(noisy, ups[u], options);
    ASSERT_TRUE(own.ok() && proxies[u].ok()) << "up " << u;
    EXPECT_EQ(proxies[u]->mesh->faceCount(), own->mesh->faceCount()) << "up " << u;
    EXPECT_TRUE(proxies[u]->mesh->vertices == own->mesh->vertices) << "up " << u;
    EXPECT_EQ(proxies[u]->toleranceNote, own->toleranceNote) << "up " << u;
    meshes.insert(proxies[u]->mesh.get());
    if (proxies[u]->toleranceMm < 0.1) strict.insert(proxies[u]->mesh.get());
  }
  EXPECT_EQ(meshes.size(), 2u);  // the tolerant proxy and the strict one, each made once
  EXPECT_EQ(strict.size(), 1u);
}

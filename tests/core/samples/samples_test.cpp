#include "multidir/core/samples/samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/common/units.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/samples/coarsen.h"
#include "multidir/core/samples/implicit_surface.h"
#include "multidir/core/samples/revolve.h"
#include "multidir/core/samples/sample_shapes.h"
#include "multidir/core/samples/sdf.h"

using namespace multidir::core;
using namespace multidir::core::samples;

namespace {

// Generating a sample takes a moment; every test of the same sample shares one mesh.
const TriangleMesh& sampleMesh(const std::string& id) {
  static std::map<std::string, TriangleMesh> cache;
  auto found = cache.find(id);
  if (found == cache.end()) {
    Result<TriangleMesh> mesh = makeSample(id);
    EXPECT_TRUE(mesh.ok()) << (mesh.ok() ? "" : mesh.error().describe());
    found = cache.emplace(id, mesh.ok() ? std::move(mesh).value() : TriangleMesh{}).first;
  }
  return found->second;
}

std::vector<std::string> catalogueIds() {
  std::vector<std::string> ids;
  for (const SampleInfo& info : catalogue()) ids.push_back(info.id);
  return ids;
}

long long genus(const TriangleMesh& mesh) { return (2 - eulerCharacteristic(mesh)) / 2; }

double lowestZ(const TriangleMesh& mesh) {
  double lowest = mesh.vertices.empty() ? std::nan("") : mesh.vertices.front().z();
  for (const Vec3& v : mesh.vertices) lowest = std::min(lowest, v.z());
  return lowest;
}

// Volume of the solid swept by a closed (r, z) profile around Z, by Pappus: 2 pi times the integral of
// r over the profile's area, computed edge by edge (the closing edge lies on the axis and adds nothing).
double pappusVolume(const std::vector<Vec2>& profile) {
  double integralOfR = 0.0;
  for (std::size_t i = 0; i < profile.size(); ++i) {
    const Vec2& a = profile[i];
    const Vec2& b = profile[(i + 1) % profile.size()];
    integralOfR += (a.x() + b.x()) * (a.x() * b.y() - b.x() * a.y()) / 6.0;
  }
  return 2.0 * kPi * integralOfR;
}

class EverySample : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST(Samples, CatalogueListsSnowmanFirstThenMushroomAndMug) {
  const std::vector<std::string> ids = catalogueIds();
  ASSERT_GE(ids.size(), 3u);
  EXPECT_EQ(ids[0], "snowman");
  EXPECT_NE(std::find(ids.begin(), ids.end(), "mushroom"), ids.end());
  EXPECT_NE(std::find(ids.begin(), ids.end(), "mug"), ids.end());
  for (const SampleInfo& info : catalogue()) {
    EXPECT_FALSE(info.title.empty()) << info.id;
    EXPECT_FALSE(info.description.empty()) << info.id;
  }
}

TEST(Samples, UnknownIdIsInvalidParameterNamingTheKnownOnes) {
  const Result<TriangleMesh> mesh = makeSample("teapot");
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::InvalidParameter);
  EXPECT_NE(mesh.error().message.find("snowman"), std::string::npos);
}

TEST(Samples, UpIsPlusZ) { EXPECT_EQ(sampleUp(), Vec3(0, 0, 1)); }

TEST_P(EverySample, IsAClosedOrientedSolidInOneShell) {
  const TriangleMesh& mesh = sampleMesh(GetParam());
  ASSERT_FALSE(mesh.empty());
  EXPECT_TRUE(edgeCensus(mesh).closedOriented());
  EXPECT_GT(signedVolume(mesh), 0.0);
  EXPECT_EQ(faceComponents(mesh).count, 1);
  EXPECT_EQ(mesh.origins.size(), mesh.triangles.size());
}

TEST_P(EverySample, StandsWithItsLowestPointAtZero) { EXPECT_NEAR(lowestZ(sampleMesh(GetParam())), 0.0, 1e-9); }

TEST_P(EverySample, HasTheGenusItIsDesignedWith) {
  const std::map<std::string, long long> designed = {{"snowman", 0}, {"mushroom", 0}, {"mug", 1}};
  ASSERT_EQ(designed.count(GetParam()), 1u) << "a new sample needs its genus listed here";
  EXPECT_EQ(genus(sampleMesh(GetParam())), designed.at(GetParam()));
}

TEST_P(EverySample, HasNoDegenerateFaces) {
  const TriangleMesh& mesh = sampleMesh(GetParam());
  std::size_t degenerate = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) degenerate += mesh.faceArea(f) <= 1e-10 ? 1 : 0;
  EXPECT_EQ(degenerate, 0u);
}

TEST_P(EverySample, HasNoDuplicateVertices) {
  std::vector<Vec3> sorted = sampleMesh(GetParam()).vertices;
  std::sort(sorted.begin(), sorted.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
}

TEST_P(EverySample, HasOverhangsWhenPrintedUpright) {
  const Result<OverhangAnalysis> overhang = analyzeOverhang(sampleMesh(GetParam()), sampleUp());
  ASSERT_TRUE(overhang.ok());
  EXPECT_GT(overhang->riskyAreaMm2, 100.0);
}

TEST_P(EverySample, IsDeterministic) {
  const Result<TriangleMesh> again = makeSample(GetParam());
  ASSERT_TRUE(again.ok());
  const TriangleMesh& first = sampleMesh(GetParam());
  EXPECT_EQ(again->vertices, first.vertices);
  EXPECT_EQ(again->triangles, first.triangles);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, EverySample, ::testing::ValuesIn(catalogueIds()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(Samples, SnowmanIsAbout150MmTallWithATriangleCountAViewerHandlesEasily) {
  const TriangleMesh& mesh = sampleMesh("snowman");
  EXPECT_NEAR(boundingBox(mesh).size().z(), 150.0, 10.0);
  EXPECT_GE(mesh.faceCount(), 10000u);
  EXPECT_LE(mesh.faceCount(), 40000u);
}

TEST(Samples, MushroomVolumeMatchesPappusForItsProfile) {
  const TriangleMesh& mesh = sampleMesh("mushroom");
  EXPECT_NEAR(boundingBox(mesh).size().z(), 100.0, 1e-9);
  const double expected = pappusVolume(mushroomProfile());
  EXPECT_NEAR(signedVolume(mesh), expected, 0.01 * expected);
}

TEST(Samples, MugIsAbout80MmTallWithItsHandleOffToPlusX) {
  const BoundingBox box = boundingBox(sampleMesh("mug"));
  EXPECT_NEAR(box.size().z(), 80.0, 1.0);
  EXPECT_GT(box.max.x(), 55.0);
  EXPECT_NEAR(box.min.x(), -30.0, 1.0);
}

TEST(ImplicitSurface, SphereVolumeIsWithinOnePercentOfFourThirdsPiRCubed) {
  const double r = 20.0;
  const Result<TriangleMesh> mesh = polygonize([&](const Vec3& p) { return sdfSphere(p, Vec3(1.3, -0.7, 0.4), r); },
                                               {Vec3::Constant(-23.0), Vec3::Constant(23.0)}, 1.0);
  ASSERT_TRUE(mesh.ok()) << mesh.error().describe();
  EXPECT_TRUE(edgeCensus(*mesh).closedOriented());
  EXPECT_EQ(eulerCharacteristic(*mesh), 2);
  const double expected = 4.0 / 3.0 * kPi * r * r * r;
  EXPECT_NEAR(signedVolume(*mesh), expected, 0.01 * expected);
}

TEST(ImplicitSurface, TorusGivesAClosedSurfaceOfGenusOne) {
  const Result<TriangleMesh> mesh = polygonize([](const Vec3& p) { return sdfTorusY(p, Vec3::Zero(), 10.0, 3.0); },
                                               {Vec3::Constant(-15.0), Vec3::Constant(15.0)}, 0.7);
  ASSERT_TRUE(mesh.ok()) << mesh.error().describe();
  EXPECT_TRUE(edgeCensus(*mesh).closedOriented());
  EXPECT_EQ(genus(*mesh), 1);
  const double expected = 2.0 * kPi * kPi * 10.0 * 3.0 * 3.0;
  EXPECT_NEAR(signedVolume(*mesh), expected, 0.02 * expected);
}

TEST(ImplicitSurface, ValuesExactlyZeroOnGridPointsStillGiveAClosedManifold) {
  // A box whose faces pass through grid points: every face value there is exactly 0.
  const auto cube = [](const Vec3& p) { return p.cwiseAbs().maxCoeff() - 4.0; };
  const Result<TriangleMesh> mesh = polygonize(cube, {Vec3::Constant(-6.0), Vec3::Constant(6.0)}, 1.0);
  ASSERT_TRUE(mesh.ok()) << mesh.error().describe();
  EXPECT_TRUE(edgeCensus(*mesh).closedOriented());
  EXPECT_EQ(eulerCharacteristic(*mesh), 2);
  for (std::size_t f = 0; f < mesh->faceCount(); ++f) ASSERT_GT(mesh->faceArea(f), 1e-10) << "face " << f;
}

TEST(ImplicitSurface, SolidReachingTheBoxIsRejected) {
  const Result<TriangleMesh> mesh =
      polygonize([](const Vec3& p) { return p.norm() - 10.0; }, {Vec3::Constant(-5.0), Vec3::Constant(5.0)}, 1.0);
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::InvalidParameter);
}

TEST(ImplicitSurface, NothingInsideIsAnEmptyMesh) {
  const Result<TriangleMesh> mesh =
      polygonize([](const Vec3&) { return 1.0; }, {Vec3::Constant(-5.0), Vec3::Constant(5.0)}, 1.0);
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::EmptyMesh);
}

TEST(ImplicitSurface, BadCellSizesAndHugeGridsAreRejected) {
  const auto sphere = [](const Vec3& p) { return p.norm() - 1.0; };
  const BoundingBox box{Vec3::Constant(-2.0), Vec3::Constant(2.0)};
  for (double cell : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    const Result<TriangleMesh> mesh = polygonize(sphere, box, cell);
    ASSERT_FALSE(mesh.ok()) << cell;
    EXPECT_EQ(mesh.error().code, ErrorCode::InvalidParameter);
  }
  const Result<TriangleMesh> huge = polygonize(sphere, box, 1e-6);
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.error().code, ErrorCode::InvalidParameter);
}

TEST(ImplicitSurface, NonFiniteDistanceIsRejected) {
  const Result<TriangleMesh> mesh =
      polygonize([](const Vec3& p) { return p.x() > 0.5 ? std::nan("") : p.norm() - 1.0; },
                 {Vec3::Constant(-2.0), Vec3::Constant(2.0)}, 0.5);
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::InvalidParameter);
}

TEST(Revolve, CylinderProfileGivesAClosedSolidWithPolygonCrossSectionVolume) {
  const int segments = 64;
  const Result<TriangleMesh> mesh = revolveProfile({{0, 0}, {10, 0}, {10, 20}, {0, 20}}, segments);
  ASSERT_TRUE(mesh.ok()) << mesh.error().describe();
  EXPECT_TRUE(edgeCensus(*mesh).closedOriented());
  EXPECT_EQ(eulerCharacteristic(*mesh), 2);
  EXPECT_EQ(mesh->vertexCount(), 2u + 2u * segments);
  // Each cross-section is a regular 64-gon inscribed in the r = 10 circle.
  const double polygonArea = 0.5 * segments * 100.0 * std::sin(2.0 * kPi / segments);
  EXPECT_NEAR(signedVolume(*mesh), polygonArea * 20.0, 1e-9);
}

TEST(Revolve, ConeProfileVolumeApproachesPappus) {
  const std::vector<Vec2> profile = {{0, 0}, {10, 0}, {0, 30}};
  const Result<TriangleMesh> mesh = revolveProfile(profile, 256);
  ASSERT_TRUE(mesh.ok()) << mesh.error().describe();
  EXPECT_TRUE(edgeCensus(*mesh).closedOriented());
  EXPECT_NEAR(signedVolume(*mesh), pappusVolume(profile), 0.001 * pappusVolume(profile));
}

TEST(Revolve, BadProfilesAreRejected) {
  const std::vector<std::vector<Vec2>> bad = {
      {{0, 0}, {10, 0}},                               // too few points
      {{0, 0}, {0, 20}, {10, 20}, {10, 0}},            // an inner point on the axis
      {{1, 0}, {10, 0}, {10, 20}, {0, 20}},            // starts off the axis
      {{0, 20}, {10, 20}, {10, 0}, {0, 0}},            // clockwise
      {{0, 0}, {10, 0}, {10, 0}, {10, 20}, {0, 20}},   // repeated point
      {{0, 0}, {10, 10}, {10, 0}, {0, 20}},            // crosses itself
      {{0, 0}, {std::nan(""), 0}, {10, 20}, {0, 20}},  // not finite
  };
  for (std::size_t i = 0; i < bad.size(); ++i) {
    const Result<TriangleMesh> mesh = revolveProfile(bad[i], 32);
    ASSERT_FALSE(mesh.ok()) << "profile " << i;
    EXPECT_EQ(mesh.error().code, ErrorCode::InvalidParameter) << "profile " << i;
  }
  EXPECT_FALSE(revolveProfile({{0, 0}, {10, 0}, {0, 30}}, 2).ok());
}

TEST(Coarsen, PolygonizedSphereKeepsItsShapeWithFewerFacesAndOnlyInputVertices) {
  const Result<TriangleMesh> fine =
      polygonize([](const Vec3& p) { return p.norm() - 15.0; }, {Vec3::Constant(-17.0), Vec3::Constant(17.0)}, 0.8);
  ASSERT_TRUE(fine.ok()) << fine.error().describe();
  CoarsenOptions options;
  options.minEdgeMm = 1.0;
  options.maxEdgeMm = 2.5;
  const Result<TriangleMesh> coarse = collapseShortEdges(*fine, options);
  ASSERT_TRUE(coarse.ok()) << coarse.error().describe();
  EXPECT_TRUE(edgeCensus(*coarse).closedOriented());
  EXPECT_EQ(eulerCharacteristic(*coarse), 2);
  EXPECT_LT(coarse->faceCount(), fine->faceCount() / 2);
  EXPECT_NEAR(signedVolume(*coarse), signedVolume(*fine), 0.01 * signedVolume(*fine));
  std::vector<Vec3> before = fine->vertices;
  const auto lexicographic = [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(before.begin(), before.end(), lexicographic);
  for (const Vec3& v : coarse->vertices)
    ASSERT_TRUE(std::binary_search(before.begin(), before.end(), v, lexicographic));
}

TEST(Coarsen, TorusKeepsGenusOne) {
  const Result<TriangleMesh> fine = polygonize([](const Vec3& p) { return sdfTorusY(p, Vec3::Zero(), 10.0, 3.0); },
                                               {Vec3::Constant(-15.0), Vec3::Constant(15.0)}, 0.5);
  ASSERT_TRUE(fine.ok());
  CoarsenOptions options;
  options.minEdgeMm = 1.5;
  options.maxEdgeMm = 3.0;
  const Result<TriangleMesh> coarse = collapseShortEdges(*fine, options);
  ASSERT_TRUE(coarse.ok());
  EXPECT_TRUE(edgeCensus(*coarse).closedOriented());
  EXPECT_EQ(genus(*coarse), 1);
}

TEST(Coarsen, OptionsOutOfRangeAreRejected) {
  const TriangleMesh box = revolveProfile({{0, 0}, {10, 0}, {10, 20}, {0, 20}}, 16).value();
  CoarsenOptions inverted;
  inverted.minEdgeMm = 3.0;
  inverted.maxEdgeMm = 2.0;
  CoarsenOptions turn;
  turn.maxNormalTurnDegrees = 120.0;
  CoarsenOptions quality;
  quality.minFaceQuality = 1.0;
  for (const CoarsenOptions& options : {inverted, turn, quality}) {
    const Result<TriangleMesh> out = collapseShortEdges(box, options);
    ASSERT_FALSE(out.ok());
    EXPECT_EQ(out.error().code, ErrorCode::InvalidParameter);
  }
}

TEST(Coarsen, MisorientedInputIsNotManifold) {
  TriangleMesh mesh = revolveProfile({{0, 0}, {10, 0}, {10, 20}, {0, 20}}, 16).value();
  std::swap(mesh.triangles[3][0], mesh.triangles[3][1]);
  const Result<TriangleMesh> out = collapseShortEdges(mesh);
  ASSERT_FALSE(out.ok());
  EXPECT_EQ(out.error().code, ErrorCode::NotManifold);
}

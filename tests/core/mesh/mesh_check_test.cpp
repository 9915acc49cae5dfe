// checkAndRepair on soups built in memory: one test per defect class.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "multidir/core/mesh/mesh_io.h"
#include "support/mesh_fixtures.h"

using namespace multidir::core;
using multidir::test::append;
using multidir::test::cubeSoup;
using multidir::test::unshared;

namespace {

const MeshDefect* findDefect(const MeshReport& report, const std::string& kind) {
  for (const MeshDefect& d : report.defects)
    if (d.kind == kind) return &d;
  return nullptr;
}

LoadOptions noRepair() {
  LoadOptions options;
  options.repair = false;
  return options;
}

}  // namespace

TEST(MeshCheck, CleanCubeHasNoDefectsAndMeasuresRight) {
  auto loaded = checkAndRepair(cubeSoup());
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_TRUE(loaded->report.defects.empty());
  EXPECT_TRUE(loaded->report.repairs.empty());
  const MeshStatistics& s = loaded->report.statistics;
  EXPECT_EQ(s.triangles, 12u);
  EXPECT_EQ(s.vertices, 8u);
  EXPECT_EQ(s.shells, 1u);
  EXPECT_EQ(s.genus, 0);
  EXPECT_TRUE(s.closed);
  EXPECT_NEAR(s.volumeMm3, 1000.0, 1e-9);
  EXPECT_NEAR(s.areaMm2, 600.0, 1e-9);
  EXPECT_EQ(s.bounds.size(), Vec3(10, 10, 10));
  ASSERT_EQ(loaded->mesh.origins.size(), 12u);
  EXPECT_EQ(loaded->mesh.origins[7], FaceOrigin::surface(7));
}

TEST(MeshCheck, EmptySoupIsAnEmptyMeshError) {
  auto loaded = checkAndRepair(RawSoup{}, {}, "nothing.stl");
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::EmptyMesh);
  EXPECT_EQ(loaded.error().where, "nothing.stl");
}

TEST(MeshCheck, NanCoordinateIsAnErrorNamingTheVertex) {
  RawSoup soup = cubeSoup();
  soup.vertices[6].y() = std::numeric_limits<double>::quiet_NaN();
  auto loaded = checkAndRepair(soup);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::NonFiniteVertex);
  EXPECT_NE(loaded.error().message.find("vertices 6"), std::string::npos) << loaded.error().message;
}

TEST(MeshCheck, IndexOutOfRangeIsMalformed) {
  RawSoup soup = cubeSoup();
  soup.triangles[3][1] = 8;
  auto loaded = checkAndRepair(soup);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
}

TEST(MeshCheck, ZeroAreaFaceIsDroppedAndItsVertexLeftOut) {
  RawSoup soup = cubeSoup();
  soup.vertices.emplace_back(5.0, 0.0, 0.0);  // on edge 0-1: the face 0-8-1 has no area
  soup.triangles.push_back({0, 8, 1});
  auto loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const MeshDefect* d = findDefect(loaded->report, "degenerate-faces");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->count, 1u);
  EXPECT_TRUE(d->repaired);
  EXPECT_EQ(d->firstIndices, std::vector<std::int64_t>{12});
  EXPECT_EQ(loaded->mesh.faceCount(), 12u);
  EXPECT_EQ(loaded->mesh.vertexCount(), 8u);
  EXPECT_TRUE(loaded->report.statistics.closed);
}

TEST(MeshCheck, DegenerateFaceWithoutRepairIsAnError) {
  RawSoup soup = cubeSoup();
  soup.triangles.push_back({0, 1, 1});
  auto loaded = checkAndRepair(soup, noRepair());
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().message.find("degenerate"), std::string::npos);
}

TEST(MeshCheck, DuplicateVerticesAreWeldedIntoOne) {
  auto loaded = checkAndRepair(unshared(cubeSoup()));
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const MeshDefect* d = findDefect(loaded->report, "duplicate-vertices");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->count, 36u - 8u);
  EXPECT_EQ(loaded->mesh.vertexCount(), 8u);
  EXPECT_NEAR(loaded->report.statistics.volumeMm3, 1000.0, 1e-9);
  ASSERT_EQ(loaded->report.repairs.size(), 1u);
  EXPECT_EQ(loaded->report.repairs[0], "merged 28 duplicate vertices");
}

TEST(MeshCheck, VerticesWithinTheWeldToleranceAreWelded) {
  RawSoup soup = unshared(cubeSoup());
  for (std::size_t v = 0; v < soup.vertices.size(); v += 2) soup.vertices[v].x() += 4e-7;  // below 1e-6 mm
  auto loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->mesh.vertexCount(), 8u);
  EXPECT_TRUE(loaded->report.statistics.closed);
}

TEST(MeshCheck, DuplicateVerticesWithoutRepairAreAnError) {
  auto loaded = checkAndRepair(unshared(cubeSoup()), noRepair());
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().message.find("28 vertices repeat"), std::string::npos) << loaded.error().message;
}

TEST(MeshCheck, DuplicateFaceIsDropped) {
  RawSoup soup = cubeSoup();
  soup.triangles.push_back({2, 1, 0});  // face 0 again, other order
  auto loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const MeshDefect* d = findDefect(loaded->report, "duplicate-faces");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->firstIndices, std::vector<std::int64_t>{12});
  EXPECT_EQ(loaded->mesh.faceCount(), 12u);
  EXPECT_TRUE(loaded->report.statistics.closed);
}

TEST(MeshCheck, EdgeOnThreeFacesIsNotManifold) {
  RawSoup soup = cubeSoup();
  soup.vertices.emplace_back(5.0, -5.0, 5.0);
  soup.triangles.push_back({0, 1, 8});  // a fin on edge 0-1
  auto loaded = checkAndRepair(soup, {}, "fin.off");
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::NotManifold);
  EXPECT_NE(loaded.error().message.find("1 edges are shared by more than two faces (first: edges 0-1)"),
            std::string::npos)
      << loaded.error().message;
}

TEST(MeshCheck, TwoCubesSharingOneVertexAreNotManifold) {
  RawSoup soup = cubeSoup();
  append(soup, cubeSoup(Vec3(10, 10, 10)));  // touches the first cube at (10,10,10) only
  auto loaded = checkAndRepair(soup);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::NotManifold);
  EXPECT_NE(loaded.error().message.find("not a 2-manifold: 1 vertices join surface parts"), std::string::npos) << loaded.error().message;
  EXPECT_NE(loaded.error().message.find("vertices 6"), std::string::npos) << loaded.error().message;
}

TEST(MeshCheck, MissingFaceLeavesAnOpenBoundary) {
  RawSoup soup = cubeSoup();
  soup.triangles.pop_back();
  auto loaded = checkAndRepair(soup, {}, "open.stl");
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::OpenBoundary);
  EXPECT_EQ(loaded.error().describe().rfind("open.stl: not a solid: 3 open boundary edges (first: edges ", 0), 0u)
      << loaded.error().describe();
  EXPECT_NE(loaded.error().message.find("Close Holes"), std::string::npos);
}

TEST(MeshCheck, OneFlippedFaceIsTurnedBack) {
  RawSoup soup = cubeSoup();
  std::swap(soup.triangles[5][1], soup.triangles[5][2]);
  auto loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const MeshDefect* d = findDefect(loaded->report, "inconsistent-orientation");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->count, 1u);
  EXPECT_EQ(d->firstIndices, std::vector<std::int64_t>{5});
  EXPECT_TRUE(edgeCensus(loaded->mesh).closedOriented());
  EXPECT_NEAR(signedVolume(loaded->mesh), 1000.0, 1e-9);
}

TEST(MeshCheck, FlippedFirstFaceIsTheOneTurnedBack) {
  RawSoup soup = cubeSoup();
  std::swap(soup.triangles[0][1], soup.triangles[0][2]);
  auto loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(findDefect(loaded->report, "inconsistent-orientation")->firstIndices, std::vector<std::int64_t>{0});
  EXPECT_NEAR(signedVolume(loaded->mesh), 1000.0, 1e-9);
}

TEST(MeshCheck, FlippedFaceWithoutRepairIsAnOrientationError) {
  RawSoup soup = cubeSoup();
  std::swap(soup.triangles[5][1], soup.triangles[5][2]);
  auto loaded = checkAndRepair(soup, noRepair());
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::InconsistentOrientation);
}

TEST(MeshCheck, InsideOutSolidIsTurnedRightWayOut) {
  RawSoup soup = cubeSoup();
  for (Triangle& t : soup.triangles) std::swap(t[1], t[2]);
  auto loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  ASSERT_NE(findDefect(loaded->report, "inverted-shells"), nullptr);
  EXPECT_EQ(findDefect(loaded->report, "inconsistent-orientation"), nullptr);
  EXPECT_NEAR(loaded->report.statistics.volumeMm3, 1000.0, 1e-9);
}

TEST(MeshCheck, InsideOutSolidWithoutRepairIsAnError) {
  RawSoup soup = cubeSoup();
  for (Triangle& t : soup.triangles) std::swap(t[1], t[2]);
  auto loaded = checkAndRepair(soup, noRepair());
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::InconsistentOrientation);
}

TEST(MeshCheck, TwoSeparateCubesAreTwoShellsNotAnError) {
  RawSoup soup = cubeSoup();
  append(soup, cubeSoup(Vec3(30, 0, 0)));
  auto loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const MeshDefect* d = findDefect(loaded->report, "several-shells");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->count, 2u);
  EXPECT_FALSE(d->repaired);
  EXPECT_FALSE(d->needsRepair);
  EXPECT_EQ(loaded->report.statistics.shells, 2u);
  EXPECT_NEAR(loaded->report.statistics.volumeMm3, 2000.0, 1e-9);
}

TEST(MeshCheck, CavityStaysInwardFacing) {
  RawSoup soup = cubeSoup(Vec3::Zero(), 20.0);
  RawSoup cavity = cubeSoup(Vec3(5, 5, 5), 10.0);
  for (Triangle& t : cavity.triangles) std::swap(t[1], t[2]);  // a cavity faces into the void
  append(soup, cavity);
  auto loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(findDefect(loaded->report, "inverted-shells"), nullptr);
  EXPECT_NEAR(loaded->report.statistics.volumeMm3, 8000.0 - 1000.0, 1e-9);
}

TEST(MeshCheck, OutwardFacingCavityIsTurnedInward) {
  RawSoup soup = cubeSoup(Vec3::Zero(), 20.0);
  append(soup, cubeSoup(Vec3(5, 5, 5), 10.0));
  auto loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const MeshDefect* d = findDefect(loaded->report, "inverted-shells");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->firstIndices, std::vector<std::int64_t>{1});
  EXPECT_NEAR(loaded->report.statistics.volumeMm3, 7000.0, 1e-9);
}

TEST(MeshCheck, OneSidedSurfaceCannotBeOriented) {
  // The six-vertex projective plane: closed, every edge on two faces, but without two sides.
  RawSoup soup;
  soup.vertices = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}, {10, 10, 3}, {3, 7, 11}};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1},
                    {1, 2, 4}, {2, 3, 5}, {3, 4, 1}, {4, 5, 2}, {5, 1, 3}};
  auto loaded = checkAndRepair(soup);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::InconsistentOrientation);
}

TEST(MeshCheck, NegativeWeldToleranceIsAnInvalidParameter) {
  LoadOptions options;
  options.weldToleranceMm = -1.0;
  auto loaded = checkAndRepair(cubeSoup(), options);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::InvalidParameter);
}

namespace {

// A tolerance that is a power of two, so that cell boundaries (multiples of it) fall exactly on coordinates.
constexpr double kWeldTolerance = 0.125;

LoadOptions weldingAt(double tolerance) {
  LoadOptions options;
  options.weldToleranceMm = tolerance;
  return options;
}

// The 10 mm cube whose top face (z = 10) is a fan of four triangles around vertex 8, placed at corner 6
// (10, 10, 10) plus `offset` in the top face: a closed solid with two vertices as close together as wanted.
RawSoup cubeWithTopFanNearCorner(const Vec3& offset) {
  RawSoup soup = cubeSoup();
  soup.vertices.push_back(soup.vertices[6] + offset);
  // The cube's top face was {4, 5, 6} and {4, 6, 7}: its boundary 4 -> 5 -> 6 -> 7 -> 4.
  soup.triangles[2] = {8, 4, 5};
  soup.triangles[3] = {8, 5, 6};
  soup.triangles.push_back({8, 6, 7});
  soup.triangles.push_back({8, 7, 4});
  return soup;
}

}  // namespace

TEST(MeshWeld, PointsStraddlingACellCornerWithinTheToleranceAreWelded) {
  // Corner 6 is moved just below (10, 10, 10) on every axis and its copy in two of its faces just above: the
  // two points lie in different weld cells along all three axes (10 is a multiple of every cell size), and
  // 0.104 mm apart, within the 0.125 mm tolerance.
  RawSoup soup = cubeSoup();
  soup.vertices[6] -= Vec3::Constant(0.03);
  soup.vertices.push_back(Vec3::Constant(10.03));
  soup.triangles[2] = {4, 5, 8};  // the top face {4, 5, 6} with the copy
  soup.triangles[11] = {1, 8, 5};  // the side face {1, 6, 5} with the copy
  auto loaded = checkAndRepair(soup, weldingAt(kWeldTolerance));
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->mesh.vertexCount(), 8u);
  EXPECT_TRUE(loaded->report.statistics.closed);
  EXPECT_NEAR(loaded->report.statistics.volumeMm3, 997.0, 0.01);  // corner 6 sits 0.03 mm inside on each axis
}

TEST(MeshWeld, PointWithinTheToleranceOfTwoKeptVerticesWeldsToTheEarlierOne) {
  // Corner 6 (kept first) and the fan's centre 8 (kept later) are 0.177 mm apart, not welded to each other.
  // The copy of corner 6 that face {8, 5, 6} uses is moved to their midpoint, 0.088 mm from both: it must
  // become corner 6 again. Welded to vertex 8 instead, that face would lose its area and the cube its top.
  // Vertex 8 lies in a cell visited before corner 6's by a search that looks at cells in coordinate order.
  RawSoup soup = cubeWithTopFanNearCorner(Vec3(-kWeldTolerance, -kWeldTolerance, 0.0));
  const Vec3 corner = soup.vertices[6];
  const Vec3 between = 0.5 * (soup.vertices[6] + soup.vertices[8]);
  soup.vertices.push_back(between);
  soup.triangles[3] = {8, 5, 9};
  ASSERT_LT((between - corner).norm(), kWeldTolerance);
  ASSERT_LT((between - soup.vertices[8]).norm(), kWeldTolerance);
  ASSERT_GT((soup.vertices[8] - corner).norm(), kWeldTolerance);

  auto loaded = checkAndRepair(soup, weldingAt(kWeldTolerance));
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const TriangleMesh& mesh = loaded->mesh;
  EXPECT_EQ(mesh.vertexCount(), 9u);
  ASSERT_EQ(mesh.faceCount(), 14u);
  EXPECT_EQ(mesh.vertices[static_cast<std::size_t>(mesh.triangles[3][2])], corner);
  EXPECT_TRUE(loaded->report.statistics.closed);
}

TEST(MeshWeld, PointsJustBeyondTheToleranceStayApart) {
  // The fan's centre 1 % farther from corner 6 than the tolerance: two vertices, the cube closed.
  const Vec3 offset = Vec3(-1.0, -1.0, 0.0).normalized() * (1.01 * kWeldTolerance);
  auto loaded = checkAndRepair(cubeWithTopFanNearCorner(offset), weldingAt(kWeldTolerance));
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->mesh.vertexCount(), 9u);
  EXPECT_EQ(loaded->mesh.faceCount(), 14u);
  EXPECT_TRUE(loaded->report.statistics.closed);
  EXPECT_NEAR(loaded->report.statistics.volumeMm3, 1000.0, 1e-9);
}

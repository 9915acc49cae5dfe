// Shells on load: nesting decided by several probes, crossing shells refused, flat shells refused, and
// the non-manifold vertex report correct at a vertex with a very large fan.
#include <gtest/gtest.h>

#include <cmath>

#include "multidir/core/common/units.h"
#include "multidir/core/mesh/mesh_io.h"
#include "support/mesh_fixtures.h"

using namespace multidir::core;
using multidir::test::append;
using multidir::test::cubeSoup;

namespace {

RawSoup reversed(RawSoup soup) {
  for (Triangle& t : soup.triangles) std::swap(t[1], t[2]);
  return soup;
}

// Two cones of `segments` sides each, apex to apex at the origin: every face of both meets the apex, so the
// apex joins two fans that share no edge (a non-manifold vertex with 4 x segments faces).
RawSoup doubleCone(int segments) {
  RawSoup soup;
  soup.vertices.push_back(Vec3::Zero());  // the shared apex
  for (int cone = 0; cone < 2; ++cone) {
    const double z = cone == 0 ? 10.0 : -10.0;
    const auto centre = static_cast<std::int32_t>(soup.vertices.size());
    soup.vertices.emplace_back(0.0, 0.0, z);
    const auto ring = static_cast<std::int32_t>(soup.vertices.size());
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * kPi * i / segments;
      soup.vertices.emplace_back(5.0 * std::cos(a), 5.0 * std::sin(a), z);
    }
    for (int i = 0; i < segments; ++i) {
      const std::int32_t p = ring + i, q = ring + (i + 1) % segments;
      if (cone == 0) {
        soup.triangles.push_back({0, q, p});       // side, outward
        soup.triangles.push_back({centre, p, q});  // top cap
      } else {
        soup.triangles.push_back({0, p, q});
        soup.triangles.push_back({centre, q, p});
      }
    }
  }
  return soup;
}

}  // namespace

TEST(MeshShells, OverlappingShellsAreRefusedNotTurnedInsideOut) {
  // Cube B's first vertex lies inside cube A, the rest of B outside: one probe took B for a cavity and
  // turned the correct cube inside out (volume 0 or negative, and "repaired").
  RawSoup soup = cubeSoup(Vec3::Zero(), 10.0);
  append(soup, cubeSoup(Vec3(5, 5, 5), 10.0));
  const Result<LoadedMesh> loaded = checkAndRepair(soup);
  ASSERT_FALSE(loaded.ok()) << "volume " << loaded->report.statistics.volumeMm3;
  EXPECT_EQ(loaded.error().code, ErrorCode::NotManifold);
  EXPECT_NE(loaded.error().message.find("shells 0 and 1"), std::string::npos) << loaded.error().describe();
  EXPECT_NE(loaded.error().message.find("cross each other"), std::string::npos) << loaded.error().describe();
  EXPECT_NE(loaded.error().message.find("boolean union"), std::string::npos) << loaded.error().describe();
}

TEST(MeshShells, OverlappingShellsAreRefusedWhicheverComesFirst) {
  RawSoup soup = cubeSoup(Vec3(5, 5, 5), 10.0);
  append(soup, cubeSoup(Vec3::Zero(), 10.0));
  EXPECT_FALSE(checkAndRepair(soup).ok());
}

TEST(MeshShells, PartInsideACavityFacesOutward) {
  RawSoup soup = cubeSoup(Vec3::Zero(), 50.0);
  append(soup, reversed(cubeSoup(Vec3(10, 10, 10), 30.0)));
  append(soup, reversed(cubeSoup(Vec3(20, 20, 20), 10.0)));  // inside out: must face outward again
  const Result<LoadedMesh> loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_NEAR(loaded->report.statistics.volumeMm3, 125000.0 - 27000.0 + 1000.0, 1e-6);
}

TEST(MeshShells, FlatClosedTetrahedronIsRefused) {
  // Four corners in one plane, four faces, every edge on two faces: closed, manifold, volume 0.
  RawSoup soup;
  soup.vertices = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, 0), Vec3(3, 3, 0)};
  soup.triangles = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  const Result<LoadedMesh> loaded = checkAndRepair(soup);
  ASSERT_FALSE(loaded.ok()) << "a flat tetrahedron passed with volume " << loaded->report.statistics.volumeMm3;
  EXPECT_EQ(loaded.error().code, ErrorCode::EmptyMesh);
  EXPECT_NE(loaded.error().message.find("encloses no volume"), std::string::npos) << loaded.error().describe();
}

TEST(MeshShells, FlatShellBesideARealSolidIsRefused) {
  RawSoup soup = cubeSoup();
  RawSoup flat;
  flat.vertices = {Vec3(20, 0, 0), Vec3(30, 0, 0), Vec3(20, 10, 0), Vec3(23, 3, 0)};
  flat.triangles = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  append(soup, flat);
  const Result<LoadedMesh> loaded = checkAndRepair(soup);
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().message.find("shell 1"), std::string::npos) << loaded.error().describe();
}

TEST(MeshShells, ThinButRealSolidIsKept) {
  // A 100 mm square plate 0.01 mm thick is a solid, however thin.
  RawSoup soup = cubeSoup();
  for (Vec3& v : soup.vertices) v = Vec3(v.x() * 10.0, v.y() * 10.0, v.z() * 0.001);
  const Result<LoadedMesh> loaded = checkAndRepair(soup);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_NEAR(loaded->report.statistics.volumeMm3, 100.0, 1e-9);
}

TEST(MeshShells, NonManifoldApexOfALargeDoubleConeIsNamed) {
  // 8k faces at one vertex: the report walks each vertex's fan once (linear), see bench/mesh_check_bench.
  const RawSoup soup = doubleCone(4096);
  const Result<LoadedMesh> loaded = checkAndRepair(soup);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::NotManifold);
  EXPECT_NE(loaded.error().message.find("1 vertices join surface parts"), std::string::npos)
      << loaded.error().describe();
  EXPECT_NE(loaded.error().message.find("(first: vertices 0)"), std::string::npos) << loaded.error().describe();
}

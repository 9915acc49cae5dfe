#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/geometry/clipping.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/search/plane_sweep.h"
#include "support/primitives.h"

using namespace multidir::core;
using multidir::test::makeBox;
using multidir::test::makeIcosphere;

namespace {

OverhangOptions cutPlaneBase() {
  OverhangOptions options;
  options.base = RegionBase::CutPlane;
  return options;
}

// Reference: clip each face by the half-space n.x > t (Sutherland-Hodgman) and integrate exactly.
struct AboveMeasures {
  double volume = 0, riskyAlongNormal = 0, riskyFlagged = 0;
};

// Area and centroid of the part of face f above n.x = t.
std::pair<double, Vec3> faceAbove(const TriangleMesh& mesh, std::size_t f, const Vec3& n, double t) {
  std::vector<Vec3> polygon;
  for (int k = 0; k < 3; ++k) {
    const Vec3& a = mesh.corner(f, k);
    const Vec3& b = mesh.corner(f, (k + 1) % 3);
    const double da = n.dot(a) - t, db = n.dot(b) - t;
    if (da > 0) polygon.push_back(a);
    if ((da > 0) != (db > 0)) polygon.push_back(a + (b - a) * (da / (da - db)));
  }
  double area = 0;
  Vec3 weighted = Vec3::Zero();
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const double part = (polygon[i] - polygon[0]).cross(polygon[i + 1] - polygon[0]).norm() / 2;
    area += part;
    weighted += part * (polygon[0] + polygon[i] + polygon[i + 1]) / 3;
  }
  return {area, area > 0 ? Vec3(weighted / area) : Vec3::Zero()};
}

std::vector<double> riskyShares(const TriangleMesh& mesh, const OverhangAnalysis& overhang) {
  std::vector<double> share(mesh.triangles.size(), 0.0);
  for (std::size_t f = 0; f < share.size(); ++f) share[f] = overhang.riskyFaceAreaMm2[f] / mesh.faceArea(f);
  return share;
}

AboveMeasures measureAboveByClippingFaces(const TriangleMesh& mesh, const Vec3& n, double t,
                                          const std::vector<double>& share, double sinAlpha) {
  AboveMeasures out;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto [area, centroid] = faceAbove(mesh, f, n, t);
    if (area == 0) continue;
    const Vec3 faceNormal = mesh.faceNormal(f);
    out.volume += n.dot(faceNormal) * area * (n.dot(centroid) - t);
    if (n.dot(faceNormal) + sinAlpha < 0) out.riskyAlongNormal += area;
    out.riskyFlagged += share[f] * area;
  }
  return out;
}

void expectSweepMatchesReference(const TriangleMesh& mesh, const Vec3& n, double step, double tolerance) {
  const BoundingBox box = boundingBox(mesh);
  const double radius = box.size().norm();
  OffsetGrid grid{n.dot(box.center()) - radius / 2, step, static_cast<int>(radius / step) + 1};
  const double sinAlpha = std::sin(degToRad(45.0));
  const auto overhang = analyzeOverhang(mesh, Vec3::UnitZ());
  ASSERT_TRUE(overhang.ok());
  const std::vector<double> share = riskyShares(mesh, *overhang);
  const SweepProfile profile = sweepPlanes(mesh, n, grid, share, sinAlpha);
  const double totalVolume = signedVolume(mesh);
  const double totalArea = surfaceArea(mesh);
  for (int j = 0; j < grid.count; ++j) {
    const AboveMeasures ref = measureAboveByClippingFaces(mesh, n, grid.offsetAt(j), share, sinAlpha);
    EXPECT_NEAR(profile.volumeAboveMm3[j], ref.volume, tolerance * totalVolume) << "offset " << j;
    EXPECT_NEAR(profile.riskyAreaAlongNormalMm2[j], ref.riskyAlongNormal, tolerance * totalArea) << "offset " << j;
    EXPECT_NEAR(profile.riskyAreaFlaggedMm2[j], ref.riskyFlagged, tolerance * totalArea) << "offset " << j;
  }
}

}  // namespace

TEST(PlaneSweep, VolumeAboveASphereCapMatchesTheClosedForm) {
  const double r = 20.0;
  const TriangleMesh sphere = makeIcosphere(Vec3::Zero(), r, 6);
  const double meshVolume = signedVolume(sphere);
  OffsetGrid grid{-r, 0.5, 81};
  const SweepProfile profile = sweepPlanes(sphere, Vec3::UnitZ(), grid, {}, std::sin(degToRad(45.0)));
  for (int j = 0; j < grid.count; ++j) {
    const double capHeight = r - grid.offsetAt(j);
    const double exactCap = kPi * capHeight * capHeight * (3 * r - capHeight) / 3;
    // Scaled to the polyhedron's own volume, the cap agrees within the faceting error.
    EXPECT_NEAR(profile.volumeAboveMm3[j], exactCap * meshVolume / (4.0 / 3.0 * kPi * r * r * r), 0.002 * meshVolume);
  }
  EXPECT_NEAR(profile.volumeAboveMm3.front(), meshVolume, 1e-9 * meshVolume);
  EXPECT_NEAR(profile.volumeAboveMm3.back(), 0.0, 1e-9 * meshVolume);
}

TEST(PlaneSweep, BoxCutByATiltedNormalMatchesFaceByFaceClipping) {
  expectSweepMatchesReference(makeBox(Vec3(0, 0, 0), Vec3(30, 20, 10)), Vec3(1, 2, 3).normalized(), 0.7, 1e-9);
}

TEST(PlaneSweep, SphereMatchesFaceByFaceClippingOnRandomNormals) {
  const TriangleMesh sphere = makeIcosphere(Vec3(3, -2, 25), 25.0, 4);
  std::mt19937 random(7);
  std::normal_distribution<double> gauss;
  for (int i = 0; i < 5; ++i) {
    const Vec3 n = Vec3(gauss(random), gauss(random), gauss(random)).normalized();
    expectSweepMatchesReference(sphere, n, 1.0, 1e-9);
  }
}

TEST(PlaneSweep, AxisAlignedNormalOnFacesParallelToThePlanesStaysExact) {
  // Every box face is either parallel to the planes (zero height span) or spans them: both degenerate cases.
  expectSweepMatchesReference(makeBox(Vec3(-5, -5, 0), Vec3(5, 5, 12)), Vec3::UnitZ(), 1.0, 1e-9);
}

TEST(PlaneSweep, EveryRiskyPartAboveThePlaneCountsHoweverCloseToThePlane) {
  // Above a cut plane only the cap rests on printed material: no band of air is free (docs/jg-definition.md).
  const TriangleMesh sphere = makeIcosphere(Vec3(0, 0, 20), 20.0, 3);
  const Vec3 n = Vec3(0, 1, 1).normalized();
  expectSweepMatchesReference(sphere, n, 1.0, 1e-9);
  // 17 mm below the centre along n, the sphere's faces near the cut face down steeply along n.
  const OffsetGrid grid{n.dot(Vec3(0, 0, 20)) - 17.0, 1.0, 1};
  const SweepProfile profile = sweepPlanes(sphere, n, grid, {}, std::sin(degToRad(45.0)));
  const auto clipped = clipByPlane(sphere, Plane{n, grid.offsetAt(0)}, 0);
  ASSERT_TRUE(clipped.ok());
  double riskyJustAbove = 0;  // risky faces within 1 mm above the plane: the old band hid them
  for (std::size_t f = 0; f < clipped->above.triangles.size(); ++f) {
    if (clipped->above.origins[f].isCap() || n.dot(clipped->above.faceNormal(f)) + std::sin(degToRad(45.0)) >= 0) continue;
    double low = INFINITY;
    for (int k = 0; k < 3; ++k) low = std::min(low, n.dot(clipped->above.corner(f, k)));
    if (low < grid.offsetAt(0) + 1.0) riskyJustAbove += clipped->above.faceArea(f);
  }
  EXPECT_GT(riskyJustAbove, 1.0);
  EXPECT_NEAR(profile.riskyAreaAlongNormalMm2[0], analyzeOverhang(clipped->above, n, cutPlaneBase())->riskyAreaMm2, 1e-9 * 5e3);
}

TEST(PlaneSweep, EmptyGridGivesEmptyProfile) {
  const SweepProfile profile = sweepPlanes(makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)), Vec3::UnitZ(), OffsetGrid{0, 1, 0}, {}, 0.7);
  EXPECT_TRUE(profile.volumeAboveMm3.empty());
}

#include "multidir/core/mesh/mesh_io.h"
#include "support/test_models.h"

TEST(PlaneSweep, EqualsClipThenMeasureOnRandomPlanesOfRealModels) {
  const double sinAlpha = std::sin(degToRad(45.0));
  std::mt19937 random(2020);
  std::normal_distribution<double> gauss;
  int planesChecked = 0;
  for (const char* name : {"kitten.off", "bunny.off", "fertility.off", "3holes.off"}) {
    const auto loaded = loadMesh(multidir::test::sharedModelPath(name));
    ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
    const TriangleMesh& mesh = loaded->mesh;
    const auto overhang = analyzeOverhang(mesh, Vec3::UnitY());
    ASSERT_TRUE(overhang.ok());
    const std::vector<double> share = riskyShares(mesh, *overhang);
    const double totalVolume = signedVolume(mesh), totalArea = surfaceArea(mesh);
    for (int trial = 0; trial < 8; ++trial) {
      const Vec3 n = Vec3(gauss(random), gauss(random), gauss(random)).normalized();
      double low = INFINITY, high = -INFINITY;
      for (const Vec3& v : mesh.vertices) {
        low = std::min(low, n.dot(v));
        high = std::max(high, n.dot(v));
      }
      const OffsetGrid grid{low + 0.37, 1.3, static_cast<int>((high - low) / 1.3)};
      const SweepProfile profile = sweepPlanes(mesh, n, grid, share, sinAlpha);
      for (int j = trial % 5; j < grid.count; j += 9) {
        const Plane plane{n, grid.offsetAt(j)};
        const auto clipped = clipByPlane(mesh, plane, 7);
        ASSERT_TRUE(clipped.ok()) << clipped.error().describe();
        const TriangleMesh& above = clipped->above;
        // The part above, printed along n on the plane, measured as a region: only its cap is supported.
        const double riskyAlongNormal = analyzeOverhang(above, n, cutPlaneBase())->riskyAreaMm2;
        double flagged = 0;
        for (std::size_t f = 0; f < above.triangles.size(); ++f)
          if (!above.origins[f].isCap()) flagged += share[above.origins[f].index] * above.faceArea(f);
        EXPECT_NEAR(profile.volumeAboveMm3[j], signedVolume(above), 1e-6 * totalVolume) << name;
        EXPECT_NEAR(profile.riskyAreaAlongNormalMm2[j], riskyAlongNormal, 1e-6 * totalArea) << name;
        EXPECT_NEAR(profile.riskyAreaFlaggedMm2[j], flagged, 1e-6 * totalArea) << name;
        ++planesChecked;
      }
    }
  }
  EXPECT_GT(planesChecked, 200);
}

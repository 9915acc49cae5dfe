#include "multidir/core/geometry/clipping.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <sstream>

#include "core/geometry/support_clip_shapes.h"
#include "multidir/core/geometry/connectivity.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "support/primitives.h"
#include "support/test_models.h"

namespace multidir::core {
namespace {

using test::makeBox;

TriangleMesh unitCube() { return makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)); }

Plane planeThrough(const Vec3& normal, const Vec3& point) { return Plane::throughPoint(normal.normalized(), point); }

double capArea(const TriangleMesh& mesh) {
  double area = 0.0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    if (mesh.origins[f].isCap()) area += mesh.faceArea(f);
  return area;
}

// Area of the faces that do not come from the cap of plane `planeId`.
double areaNotFromCap(const TriangleMesh& mesh, std::int32_t planeId) {
  double area = 0.0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    if (mesh.origins[f] != FaceOrigin::cap(planeId)) area += mesh.faceArea(f);
  return area;
}

std::size_t capFaceCount(const TriangleMesh& mesh) {
  return static_cast<std::size_t>(
      std::count_if(mesh.origins.begin(), mesh.origins.end(), [](const FaceOrigin& o) { return o.isCap(); }));
}

// Every property a clip promises, as the first broken one ("" when all hold). Shared by the examples and the
// property test over the real models.
std::string clipViolation(const TriangleMesh& input, const Plane& plane, std::int32_t planeId, const ClipResult& clip) {
  std::ostringstream why;
  std::set<std::pair<bool, std::int32_t>> inputOrigins;
  for (const FaceOrigin& o : input.origins) inputOrigins.insert({o.isCap(), o.index});
  const TriangleMesh* sides[2] = {&clip.below, &clip.above};
  const char* names[2] = {"below", "above"};
  for (int s = 0; s < 2; ++s) {
    const TriangleMesh& side = *sides[s];
    if (side.origins.size() != side.faceCount()) return std::string(names[s]) + ": origins do not match faces";
    if (side.empty()) {
      if (!side.vertices.empty()) return std::string(names[s]) + ": empty side keeps vertices";
      continue;
    }
    const EdgeCensus census = edgeCensus(side);
    if (!census.closedOriented()) {
      why << names[s] << ": not closed and oriented (boundary " << census.boundary << ", non-manifold "
          << census.nonManifold << ", misoriented " << census.misoriented << ", pinched vertices "
          << census.nonManifoldVertices << ")";
      return why.str();
    }
    std::vector<char> used(side.vertices.size(), 0);
    for (const Triangle& t : side.triangles)
      for (std::int32_t v : t) used[v] = 1;
    if (std::count(used.begin(), used.end(), 0) != 0) return std::string(names[s]) + ": unused vertices kept";
    const double sign = s == 0 ? 1.0 : -1.0;
    double projected = 0.0, area = 0.0;
    for (std::size_t f = 0; f < side.faceCount(); ++f) {
      const FaceOrigin origin = side.origins[f];
      if (origin == FaceOrigin::cap(planeId)) {
        for (int k = 0; k < 3; ++k)
          if (std::abs(plane.signedDistance(side.corner(f, k))) > 1e-9) {
            why << names[s] << ": cap vertex " << plane.signedDistance(side.corner(f, k)) << " mm off the plane";
            return why.str();
          }
        projected += 0.5 * sign * side.areaNormal(f).dot(plane.normal);
        area += side.faceArea(f);
      } else if (inputOrigins.count({origin.isCap(), origin.index}) == 0) {
        return std::string(names[s]) + ": a face with an origin the input does not have";
      }
    }
    // A cap that faces the wrong way or folds over itself projects to less than its area.
    if (std::abs(projected - area) > 1e-9 * std::max(1.0, area)) {
      why << names[s] << ": cap folds or faces inwards (projected " << projected << " of " << area << " mm^2)";
      return why.str();
    }
  }
  const double volume = signedVolume(input);
  const double sum = signedVolume(clip.below) + signedVolume(clip.above);
  if (std::abs(sum - volume) > 1e-9 * volume) {
    why << "volumes add up to " << sum << " instead of " << volume;
    return why.str();
  }
  const double area = surfaceArea(input);
  const double pieces = areaNotFromCap(clip.below, planeId) + areaNotFromCap(clip.above, planeId);
  // A vertex a hair from the plane is moved onto it along the surface (no slivers, volume kept); that changes
  // the area around it by a second-order amount, far below 1e-6 of the whole.
  if (std::abs(pieces - area) > 1e-6 * area) {
    why << "surface pieces cover " << pieces << " mm^2 instead of " << area;
    return why.str();
  }
  const double capBelow = surfaceArea(clip.below) - areaNotFromCap(clip.below, planeId);
  const double capAbove = surfaceArea(clip.above) - areaNotFromCap(clip.above, planeId);
  if (std::abs(capBelow - capAbove) > 1e-9 * std::max(1.0, capBelow)) return "the two caps differ";
  return "";
}

ClipResult clipOrFail(const TriangleMesh& mesh, const Plane& plane, std::int32_t planeId = 7) {
  Result<ClipResult> clip = clipByPlane(mesh, plane, planeId);
  EXPECT_TRUE(clip.ok()) << (clip.ok() ? "" : clip.error().describe());
  if (!clip.ok()) return {};
  EXPECT_EQ(clipViolation(mesh, plane, planeId, clip.value()), "");
  return std::move(clip.value());
}

TEST(Clipping, CubeByAxisPlaneGivesTwoClosedBoxes) {
  const ClipResult clip = clipOrFail(unitCube(), planeThrough(Vec3::UnitZ(), Vec3(0, 0, 0.3)));
  EXPECT_NEAR(signedVolume(clip.below), 0.3, 1e-12);
  EXPECT_NEAR(signedVolume(clip.above), 0.7, 1e-12);
  EXPECT_NEAR(capArea(clip.below), 1.0, 1e-12);
  EXPECT_NEAR(boundingBox(clip.below).max.z(), 0.3, 1e-15);
  EXPECT_NEAR(boundingBox(clip.above).min.z(), 0.3, 1e-15);
}

TEST(Clipping, CubeByDiagonalPlaneGivesTwoClosedSolids) {
  // Through the centre, tilted off every axis: cuts six faces, the section is a hexagon-like polygon.
  const ClipResult clip = clipOrFail(unitCube(), planeThrough(Vec3(1, 2, 3), Vec3(0.5, 0.5, 0.5)));
  EXPECT_NEAR(signedVolume(clip.below), 0.5, 1e-12);  // symmetric about the centre
  EXPECT_NEAR(signedVolume(clip.above), 0.5, 1e-12);
  EXPECT_GT(capFaceCount(clip.below), 0u);
}

TEST(Clipping, CubeByPlaneThroughThreeCornersCutsOffATetrahedron) {
  const ClipResult clip = clipOrFail(unitCube(), planeThrough(Vec3(1, 1, 1), Vec3(1, 0, 0)));
  EXPECT_NEAR(signedVolume(clip.below), 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(capArea(clip.below), std::sqrt(3.0) / 2.0, 1e-12);  // the triangle of three face diagonals
  // The corner, the three corners in the plane, and where the three faces' diagonals cross it: collinear
  // points on the cap's edges, all used by the cap.
  EXPECT_EQ(clip.below.vertexCount(), 7u);
}

TEST(Clipping, CubeByPlaneThroughTwoOppositeEdgesGivesTwoPrisms) {
  const ClipResult clip = clipOrFail(unitCube(), planeThrough(Vec3(1, -1, 0), Vec3(0, 0, 0)));
  EXPECT_NEAR(signedVolume(clip.below), 0.5, 1e-12);
  EXPECT_NEAR(signedVolume(clip.above), 0.5, 1e-12);
  EXPECT_NEAR(capArea(clip.above), std::sqrt(2.0), 1e-12);
  EXPECT_EQ(clip.below.vertexCount(), 6u);  // a triangular prism: no new vertex on the cut edges
}

TEST(Clipping, PlaneContainingTheTopFaceKeepsItBelowAndLeavesAboveEmpty) {
  const TriangleMesh cube = unitCube();
  const ClipResult clip = clipOrFail(cube, planeThrough(Vec3::UnitZ(), Vec3(0, 0, 1)));
  EXPECT_TRUE(clip.above.empty());
  EXPECT_EQ(clip.below.faceCount(), cube.faceCount());
  EXPECT_EQ(capFaceCount(clip.below), 0u);
}

TEST(Clipping, PlaneContainingTheBottomFaceGivesItToAbove) {
  const TriangleMesh cube = unitCube();
  const ClipResult clip = clipOrFail(cube, planeThrough(Vec3::UnitZ(), Vec3(0, 0, 0)));
  EXPECT_TRUE(clip.below.empty());
  EXPECT_EQ(clip.above.faceCount(), cube.faceCount());
  EXPECT_EQ(capFaceCount(clip.above), 0u);
}

TEST(Clipping, VerticesWithinTheToleranceAreSnappedOntoThePlane) {
  const TriangleMesh cube = unitCube();
  const ClipResult clip = clipOrFail(cube, planeThrough(Vec3::UnitZ(), Vec3(0, 0, 1.0 - 1e-12)));
  EXPECT_TRUE(clip.above.empty());
  EXPECT_EQ(clip.below.faceCount(), cube.faceCount());
  EXPECT_NEAR(boundingBox(clip.below).max.z(), 1.0 - 1e-12, 1e-15);
}

TEST(Clipping, PlaneMissingTheMeshLeavesOneSideEmpty) {
  const TriangleMesh cube = unitCube();
  const ClipResult under = clipOrFail(cube, planeThrough(Vec3(1, 1, 0), Vec3(-5, 0, 0)));
  EXPECT_TRUE(under.below.empty());
  EXPECT_TRUE(under.below.vertices.empty());
  EXPECT_EQ(under.above.faceCount(), cube.faceCount());
  const ClipResult over = clipOrFail(cube, planeThrough(Vec3(1, 1, 0), Vec3(5, 0, 0)));
  EXPECT_TRUE(over.above.empty());
  EXPECT_EQ(over.below.faceCount(), cube.faceCount());
}

TEST(Clipping, PiecesOfSplitFacesKeepTheirOriginAndCapFacesNameThePlane) {
  TriangleMesh cube = unitCube();
  for (std::size_t f = 0; f < cube.faceCount(); ++f) cube.origins[f] = FaceOrigin::surface(100 + static_cast<int>(f));
  cube.origins[3] = FaceOrigin::cap(2);  // a cap of an earlier clip stays that cap
  const ClipResult clip = clipByPlane(cube, planeThrough(Vec3(1, 2, 3), Vec3(0.5, 0.5, 0.5)), 9).value();
  std::set<std::int32_t> surfaceOrigins;
  bool earlierCapKept = false;
  for (const TriangleMesh* side : {&clip.below, &clip.above})
    for (const FaceOrigin& o : side->origins) {
      if (o.isCap()) {
        EXPECT_TRUE(o.index == 9 || o.index == 2);
        earlierCapKept |= o.index == 2;
      } else {
        surfaceOrigins.insert(o.index);
      }
    }
  EXPECT_TRUE(earlierCapKept);
  EXPECT_EQ(surfaceOrigins.size(), cube.faceCount() - 1);
  EXPECT_EQ(*surfaceOrigins.begin(), 100);
}

TEST(Clipping, BothSidesShareTheSameCutPoints) {
  const ClipResult clip =
      clipOrFail(test::makeIcosphere(Vec3(1, 2, 3), 5.0, 2), planeThrough(Vec3(1, 1, 2), Vec3(1, 2, 3.5)));
  auto capPoints = [](const TriangleMesh& side) {
    std::set<std::array<double, 3>> points;
    for (std::size_t f = 0; f < side.faceCount(); ++f)
      if (side.origins[f].isCap())
        for (int k = 0; k < 3; ++k)
          points.insert({side.corner(f, k).x(), side.corner(f, k).y(), side.corner(f, k).z()});
    return points;
  };
  const auto below = capPoints(clip.below);
  EXPECT_GT(below.size(), 10u);
  EXPECT_EQ(below, capPoints(clip.above));  // bit for bit
}

TEST(Clipping, CapsFaceOutOfEachSide) {
  const Plane plane = planeThrough(Vec3(0, 1, 1), Vec3(0.5, 0.5, 0.5));
  const ClipResult clip = clipOrFail(test::makeIcosphere(Vec3(0.5, 0.5, 0.5), 2.0, 1), plane);
  for (std::size_t f = 0; f < clip.below.faceCount(); ++f) {
    if (!clip.below.origins[f].isCap()) continue;
    EXPECT_GT(clip.below.faceNormal(f).dot(plane.normal), 1.0 - 1e-9);
  }
  for (std::size_t f = 0; f < clip.above.faceCount(); ++f) {
    if (!clip.above.origins[f].isCap()) continue;
    EXPECT_LT(clip.above.faceNormal(f).dot(plane.normal), -1.0 + 1e-9);
  }
}

// Area of a regular polygon with `segments` sides inscribed in a circle of radius r.
double polygonArea(double r, int segments) { return 0.5 * segments * r * r * std::sin(2.0 * kPi / segments); }

TEST(Clipping, TubeSectionIsARingWithAHole) {
  const TriangleMesh tube = test::makeTube(Vec3(0, 0, 0), 3.0, 5.0, 0.0, 10.0, 32);
  const ClipResult clip = clipOrFail(tube, planeThrough(Vec3::UnitZ(), Vec3(0, 0, 4.0)));
  EXPECT_NEAR(capArea(clip.below), polygonArea(5.0, 32) - polygonArea(3.0, 32), 1e-9);
  EXPECT_EQ(eulerCharacteristic(clip.below), 0);  // still a torus
  EXPECT_EQ(eulerCharacteristic(clip.above), 0);
}

TEST(Clipping, TiltedCutThroughATubeStillHasAHole) {
  const TriangleMesh tube = test::makeTube(Vec3(0, 0, 0), 3.0, 5.0, 0.0, 10.0, 48);
  const ClipResult clip = clipOrFail(tube, planeThrough(Vec3(0.2, 0.1, 1.0), Vec3(0, 0, 5.0)));
  EXPECT_EQ(eulerCharacteristic(clip.below), 0);
}

TEST(Clipping, USectionIsTwoIslands) {
  const ClipResult clip = clipOrFail(test::makeU(), planeThrough(Vec3::UnitZ(), Vec3(0, 0, 25.0)));
  EXPECT_NEAR(capArea(clip.below), 2 * 10.0 * 10.0, 1e-9);
  EXPECT_EQ(faceComponents(clip.above).count, 2);
  EXPECT_EQ(faceComponents(clip.below).count, 1);
}

TEST(Clipping, TubeInsideATubeGivesAnIslandInsideAHole) {
  const TriangleMesh tubes = test::merge(test::makeTube(Vec3(0, 0, 0), 8.0, 10.0, 0.0, 10.0, 40),
                                         test::makeTube(Vec3(0.5, -0.5, 0), 3.0, 5.0, -1.0, 12.0, 40));
  const ClipResult clip = clipOrFail(tubes, planeThrough(Vec3(0.05, 0.02, 1.0), Vec3(0, 0, 5.0)));
  EXPECT_EQ(faceComponents(clip.below).count, 2);
  EXPECT_EQ(faceComponents(clip.above).count, 2);
  // Projected onto the plane, the caps are two rings.
  const Vec3 n = Vec3(0.05, 0.02, 1.0).normalized();
  const double rings = polygonArea(10.0, 40) - polygonArea(8.0, 40) + polygonArea(5.0, 40) - polygonArea(3.0, 40);
  EXPECT_NEAR(capArea(clip.below) * n.z(), rings, 1e-9);
}

// A block whose top is a saddle around its centre vertex: up along x, down along y. The plane z = 0 through
// the centre leaves above two lumps that meet only at that vertex.
TriangleMesh makeSaddleBlock() {
  TriangleMesh mesh;
  mesh.vertices.push_back(Vec3(0, 0, 0));
  const double ring[8][3] = {{1, 0, 1},  {1, 1, 1},   {0, 1, -1},  {-1, 1, -1},
                             {-1, 0, 1}, {-1, -1, 1}, {0, -1, -1}, {1, -1, -1}};
  for (const auto& r : ring) mesh.vertices.push_back(Vec3(r[0], r[1], r[2]));
  for (const auto& r : ring) mesh.vertices.push_back(Vec3(r[0], r[1], -2));
  mesh.vertices.push_back(Vec3(0, 0, -2));
  for (int i = 0; i < 8; ++i) {
    const int j = (i + 1) % 8;
    mesh.triangles.push_back({0, 1 + i, 1 + j});
    mesh.triangles.push_back({9 + i, 9 + j, 1 + j});
    mesh.triangles.push_back({9 + i, 1 + j, 1 + i});
    mesh.triangles.push_back({17, 9 + j, 9 + i});
  }
  mesh.resetOrigins();
  return mesh;
}

TEST(Clipping, SideThatPinchesAtAVertexGetsTheVertexOncePerLump) {
  const TriangleMesh block = makeSaddleBlock();
  ASSERT_TRUE(edgeCensus(block).closedOriented());
  const ClipResult clip = clipOrFail(block, planeThrough(Vec3::UnitZ(), Vec3(0, 0, 0)));
  EXPECT_EQ(faceComponents(clip.above).count, 2);
  EXPECT_EQ(faceComponents(clip.below).count, 1);
}

TEST(Clipping, GrooveTouchingThePlaneKeepsBothSidesManifold) {
  using test::makeExtrudedProfile;
  const TriangleMesh block = makeExtrudedProfile({Vec3(0, 0, 0), Vec3(30, 0, 0), Vec3(30, 0, 20), Vec3(20, 0, 20),
                                                  Vec3(15, 0, 10), Vec3(10, 0, 20), Vec3(0, 0, 20)},
                                                 10.0);
  const ClipResult clip = clipOrFail(block, planeThrough(Vec3::UnitZ(), Vec3(0, 0, 10)));
  // Above z = 10 the profile is 30 x 10 minus the groove's 50 mm^2, 10 mm deep.
  EXPECT_NEAR(signedVolume(clip.above), (300.0 - 50.0) * 10.0, 1e-9);
  EXPECT_EQ(faceComponents(clip.below).count, 1);
}

TEST(Clipping, RejectsAPlaneWhoseNormalIsNotAUnitVector) {
  const TriangleMesh cube = unitCube();
  for (const Vec3& normal : {Vec3(0, 0, 2), Vec3(0, 0, 0), Vec3(0, std::nan(""), 1)}) {
    Result<ClipResult> clip = clipByPlane(cube, Plane{normal, 0.5}, 1);
    ASSERT_FALSE(clip.ok());
    EXPECT_EQ(clip.error().code, ErrorCode::InvalidParameter);
    EXPECT_EQ(clip.error().where, "plane.normal");
  }
}

TEST(Clipping, RejectsANegativeTolerance) {
  ClipOptions options;
  options.planeToleranceMm = -1.0;
  Result<ClipResult> clip = clipByPlane(unitCube(), Plane{Vec3::UnitZ(), 0.5}, 1, options);
  ASSERT_FALSE(clip.ok());
  EXPECT_EQ(clip.error().code, ErrorCode::InvalidParameter);
}

TEST(Clipping, RejectsAnOpenMeshNamingAFace) {
  TriangleMesh cube = unitCube();
  cube.triangles.pop_back();
  cube.origins.pop_back();
  Result<ClipResult> clip = clipByPlane(cube, Plane{Vec3::UnitZ(), 0.5}, 1);
  ASSERT_FALSE(clip.ok());
  EXPECT_EQ(clip.error().code, ErrorCode::OpenBoundary);
  EXPECT_NE(clip.error().where.find("face"), std::string::npos);
}

TEST(Clipping, RejectsAMeshWithAFlippedFace) {
  TriangleMesh cube = unitCube();
  std::swap(cube.triangles[4][1], cube.triangles[4][2]);
  Result<ClipResult> clip = clipByPlane(cube, Plane{Vec3::UnitZ(), 0.5}, 1);
  ASSERT_FALSE(clip.ok());
  EXPECT_EQ(clip.error().code, ErrorCode::InconsistentOrientation);
}

TEST(Clipping, RejectsAnInsideOutSolid) {
  TriangleMesh cube = unitCube();
  for (Triangle& t : cube.triangles) std::swap(t[1], t[2]);
  Result<ClipResult> clip = clipByPlane(cube, Plane{Vec3::UnitZ(), 0.5}, 1);
  ASSERT_FALSE(clip.ok());
  EXPECT_EQ(clip.error().code, ErrorCode::InconsistentOrientation);
}

TEST(Clipping, RejectsBrokenIndicesAndMissingOriginsEvenWithoutTheClosedCheck) {
  ClipOptions unchecked;
  unchecked.checkClosed = false;
  TriangleMesh badIndex = unitCube();
  badIndex.triangles[5][2] = 8;
  EXPECT_EQ(clipByPlane(badIndex, Plane{Vec3::UnitZ(), 0.5}, 1, unchecked).error().code, ErrorCode::InvalidParameter);
  TriangleMesh noOrigins = unitCube();
  noOrigins.origins.clear();
  EXPECT_EQ(clipByPlane(noOrigins, Plane{Vec3::UnitZ(), 0.5}, 1, unchecked).error().code, ErrorCode::InvalidParameter);
  EXPECT_EQ(clipByPlane(TriangleMesh{}, Plane{Vec3::UnitZ(), 0.5}, 1).error().code, ErrorCode::EmptyMesh);
}

TEST(Clipping, ClippingAClippedSideAgainWorks) {
  const TriangleMesh tube = test::makeTube(Vec3(0, 0, 0), 3.0, 5.0, 0.0, 10.0, 24);
  const ClipResult first = clipOrFail(tube, planeThrough(Vec3(0.3, 0.1, 1), Vec3(0, 0, 6)), 1);
  const ClipResult second = clipOrFail(first.below, planeThrough(Vec3(1, 0.2, 0.1), Vec3(1, 0, 0)), 2);
  EXPECT_GT(capFaceCount(second.above), 0u);
  bool hasBothCaps = false;
  for (const FaceOrigin& o : second.above.origins) hasBothCaps |= o == FaceOrigin::cap(1);
  EXPECT_TRUE(hasBothCaps);
}

// Random planes through the bounding box, planes through vertices, and planes containing a face, on every
// closed shared model: every clip keeps every promise.
TEST(Clipping, EveryPromiseHoldsOnRealModelsForOverAThousandPlanes) {
  std::mt19937_64 random(20240611);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  auto randomNormal = [&] {
    Vec3 n(gauss(random), gauss(random), gauss(random));
    while (n.norm() < 1e-3) n = Vec3(gauss(random), gauss(random), gauss(random));
    return n.normalized();
  };
  int clips = 0, failures = 0, crossed = 0;
  for (const std::string& name : test::closedSharedModels()) {
    Result<LoadedMesh> loaded = loadMesh(test::sharedModelPath(name));
    ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
    const TriangleMesh& mesh = loaded->mesh;
    const BoundingBox box = boundingBox(mesh);
    std::uniform_int_distribution<std::size_t> vertexPick(0, mesh.vertexCount() - 1);
    std::uniform_int_distribution<std::size_t> facePick(0, mesh.faceCount() - 1);
    for (int i = 0; i < 120; ++i) {
      Plane plane;
      if (i < 80) {
        const Vec3 point = box.min + box.size().cwiseProduct(Vec3(unit(random), unit(random), unit(random)));
        plane = Plane::throughPoint(randomNormal(), point);
      } else if (i < 105) {
        plane = Plane::throughPoint(randomNormal(), mesh.vertices[vertexPick(random)]);
      } else {
        const std::size_t f = facePick(random);
        plane = Plane::throughPoint(mesh.faceNormal(f), mesh.corner(f, 0));
      }
      Result<ClipResult> clip = clipByPlane(mesh, plane, i);
      ++clips;
      const std::string violation =
          clip.ok() ? clipViolation(mesh, plane, i, clip.value()) : "error: " + clip.error().describe();
      if (!violation.empty() && failures++ < 5) ADD_FAILURE() << name << " plane " << i << ": " << violation;
      if (clip.ok() && !clip->below.empty() && !clip->above.empty()) ++crossed;
    }
  }
  EXPECT_GE(clips, 1000);
  EXPECT_EQ(failures, 0);
  EXPECT_GT(crossed, clips / 2);  // most planes do cut the model
}

}  // namespace
}  // namespace multidir::core

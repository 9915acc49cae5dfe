#include <gtest/gtest.h>

#include <cmath>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "support/primitives.h"

using namespace multidir::core;
using multidir::test::makeBox;
using multidir::test::makeIcosphere;
using multidir::test::makeInvertedPyramid;

TEST(Overhang, BoxOnThePlatformHasNoRiskyArea) {
  const TriangleMesh box = makeBox(Vec3(0, 0, 0), Vec3(10, 20, 30));
  const auto result = analyzeOverhang(box, Vec3::UnitZ());
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result->riskyFaces, 0u);
  EXPECT_DOUBLE_EQ(result->riskyAreaMm2, 0.0);
}

TEST(Overhang, BoxPrintedSidewaysStillHasNoRiskyArea) {
  const TriangleMesh box = makeBox(Vec3(0, 0, 0), Vec3(10, 20, 30));
  const auto result = analyzeOverhang(box, Vec3::UnitX());
  ASSERT_TRUE(result.ok());
  EXPECT_DOUBLE_EQ(result->riskyAreaMm2, 0.0);
}

TEST(Overhang, FloatingBoxBottomIsRiskyWhenSomethingElseTouchesThePlatform) {
  TriangleMesh mesh = makeBox(Vec3(0, 0, 5), Vec3(10, 10, 15));
  // A second box below it takes the platform, so the upper box's bottom (100 mm^2) hangs in the air.
  TriangleMesh pillar = makeBox(Vec3(20, 20, 0), Vec3(21, 21, 1));
  const auto base = static_cast<std::int32_t>(mesh.vertices.size());
  for (const Vec3& v : pillar.vertices) mesh.vertices.push_back(v);
  for (Triangle t : pillar.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  mesh.resetOrigins();
  const auto result = analyzeOverhang(mesh, Vec3::UnitZ());
  ASSERT_TRUE(result.ok());
  EXPECT_NEAR(result->riskyAreaMm2, 100.0, 1e-9);
  EXPECT_EQ(result->riskyFaces, 2u);
}

TEST(Overhang, InvertedPyramidSlantedFacesAreRiskyWhenSteeperThanAlpha) {
  // Side 20, height 5: each slanted face leans 26.6 degrees from horizontal, so it faces down steeply
  // (normal 63.4 degrees below the horizon) and is risky at alpha 45.
  const double side = 20.0, height = 5.0;
  const TriangleMesh pyramid = makeInvertedPyramid(side, height);
  const double slantHeight = std::hypot(side / 2, height);
  const double slantedArea = 4 * 0.5 * side * slantHeight;
  OverhangOptions noBand;
  noBand.supportedBandMm = 0.0;
  const auto result = analyzeOverhang(pyramid, Vec3::UnitZ(), noBand);
  ASSERT_TRUE(result.ok());
  EXPECT_NEAR(result->riskyAreaMm2, slantedArea, 1e-9 * slantedArea);
}

TEST(Overhang, ThePlatformSupportsTheBandAboveIt) {
  // Below height b, each slanted face is a copy of itself scaled by b/height around the apex: only
  // 1 - (b/height)^2 of the slanted area remains to count.
  const double side = 20.0, height = 5.0, band = 1.0;
  const double slantedArea = 4 * 0.5 * side * std::hypot(side / 2, height);
  OverhangOptions options;
  options.supportedBandMm = band;
  const auto result = analyzeOverhang(makeInvertedPyramid(side, height), Vec3::UnitZ(), options);
  ASSERT_TRUE(result.ok());
  const double expected = slantedArea * (1 - (band / height) * (band / height));
  EXPECT_NEAR(result->riskyAreaMm2, expected, 1e-9 * expected);
  EXPECT_EQ(result->riskyFaces, 4u);
}

TEST(Overhang, InvertedPyramidSlantedFacesAreSafeWhenGentlerThanAlpha) {
  // Height 30 on side 20: faces are 71.6 degrees from horizontal, their normals 18.4 degrees below the
  // horizon, within alpha 45.
  const TriangleMesh pyramid = makeInvertedPyramid(20.0, 30.0);
  const auto result = analyzeOverhang(pyramid, Vec3::UnitZ());
  ASSERT_TRUE(result.ok());
  EXPECT_DOUBLE_EQ(result->riskyAreaMm2, 0.0);
}

TEST(Overhang, SphereRiskyAreaMatchesTheClosedFormForSeveralAngles) {
  // Risky where n.d < -sin(alpha): a polar cap of the sphere of area 2 pi r^2 (1 - sin(alpha)).
  const double radius = 25.0;
  const TriangleMesh sphere = makeIcosphere(Vec3(0, 0, radius), radius, 6);
  for (double alphaDeg : {30.0, 45.0, 60.0}) {
    OverhangOptions options;
    options.alphaMaxDegrees = alphaDeg;
    const auto result = analyzeOverhang(sphere, Vec3::UnitZ(), options);
    ASSERT_TRUE(result.ok());
    // Zones of a sphere have area 2 pi r times their height: the risky cap reaches r (1 - sin alpha) up from
    // the bottom, of which the lowest band is supported by the platform.
    const double expected = 2 * kPi * radius * (radius * (1 - std::sin(degToRad(alphaDeg))) - options.supportedBandMm);
    EXPECT_NEAR(result->riskyAreaMm2, expected, 0.01 * expected) << "alpha " << alphaDeg;
  }
}

TEST(Overhang, DirectionNeedNotBeUnitLength) {
  const TriangleMesh pyramid = makeInvertedPyramid(20.0, 5.0);
  const auto unit = analyzeOverhang(pyramid, Vec3::UnitZ());
  const auto scaled = analyzeOverhang(pyramid, Vec3(0, 0, 7.5));
  ASSERT_TRUE(unit.ok() && scaled.ok());
  EXPECT_DOUBLE_EQ(unit->riskyAreaMm2, scaled->riskyAreaMm2);
}

TEST(Overhang, NegativeBandIsRefused) {
  OverhangOptions options;
  options.supportedBandMm = -1.0;
  const auto result = analyzeOverhang(makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)), Vec3::UnitZ(), options);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().where, "supported band");
}

TEST(Overhang, AbsurdAlphaIsRefusedWithItsName) {
  OverhangOptions options;
  options.alphaMaxDegrees = 95.0;
  const auto result = analyzeOverhang(makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)), Vec3::UnitZ(), options);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::InvalidParameter);
  EXPECT_EQ(result.error().where, "alpha");
}

TEST(Overhang, ZeroDirectionIsRefused) {
  const auto result = analyzeOverhang(makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)), Vec3::Zero());
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::InvalidParameter);
}

TEST(Direction, AxisNamesAndTriplesParse) {
  EXPECT_TRUE(parseDirection("y")->isApprox(Vec3::UnitY()));
  EXPECT_TRUE(parseDirection("-z")->isApprox(-Vec3::UnitZ()));
  EXPECT_TRUE(parseDirection("+x")->isApprox(Vec3::UnitX()));
  EXPECT_TRUE(parseDirection("0,0,2")->isApprox(Vec3::UnitZ()));
}

TEST(Direction, GarbageIsRefusedWithAHint) {
  for (const char* text : {"", "up", "1,2", "0,0,0", "1,2,3,4", "nan,0,1"}) {
    const auto result = parseDirection(text);
    EXPECT_FALSE(result.ok()) << text;
    if (!result.ok()) {
      EXPECT_NE(result.error().message.find("0,1,0"), std::string::npos);
    }
  }
}

TEST(MeshMeasure, IcosphereIsClosedWithTheRightVolume) {
  const TriangleMesh sphere = makeIcosphere(Vec3(1, 2, 3), 10.0, 5);
  EXPECT_TRUE(edgeCensus(sphere).closedOriented());
  EXPECT_EQ(eulerCharacteristic(sphere), 2);
  EXPECT_NEAR(signedVolume(sphere), 4.0 / 3.0 * kPi * 1000.0, 0.005 * 4.0 / 3.0 * kPi * 1000.0);
}

namespace {
OverhangOptions onACutPlane() {
  OverhangOptions options;
  options.base = RegionBase::CutPlane;
  return options;
}
}  // namespace

TEST(Overhang, OnACutPlaneTheCapRestsOnTheMaterialBelow) {
  // A box printed on its base plane: its bottom lies in the plane (the cap) and needs nothing.
  const auto result = analyzeOverhang(makeBox(Vec3(0, 0, 40), Vec3(10, 20, 50)), Vec3::UnitZ(), onACutPlane());
  ASSERT_TRUE(result.ok());
  EXPECT_DOUBLE_EQ(result->riskyAreaMm2, 0.0);
}

TEST(Overhang, OnACutPlaneNoBandAboveThePlaneIsFree) {
  // The inverted pyramid's slanted faces start at its apex, the lowest level: on the platform the 1 mm band
  // above the apex would be free; above a cut plane nothing but the cap is, so all of them count.
  const double side = 20.0, height = 5.0;
  const TriangleMesh pyramid = makeInvertedPyramid(side, height);
  const double slantedArea = 4 * 0.5 * side * std::hypot(side / 2, height);
  const auto onPlane = analyzeOverhang(pyramid, Vec3::UnitZ(), onACutPlane());
  const auto onBed = analyzeOverhang(pyramid, Vec3::UnitZ());
  ASSERT_TRUE(onPlane.ok() && onBed.ok());
  EXPECT_NEAR(onPlane->riskyAreaMm2, slantedArea, 1e-9 * slantedArea);
  EXPECT_LT(onBed->riskyAreaMm2, onPlane->riskyAreaMm2 - 1.0);
}

TEST(Overhang, InPlaneToleranceCoversFloatRoundingAndScalesWithTheCoordinates) {
  const TriangleMesh small = makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const TriangleMesh far = makeBox(Vec3(1000, 0, 0), Vec3(1001, 1, 1));
  // A height along an oblique direction sums three float-rounded coordinates: at most 3 * 6e-8 of them.
  EXPECT_GT(inPlaneToleranceMm(small), 4 * 3 * 6e-8);
  EXPECT_GT(inPlaneToleranceMm(far), 4 * 3 * 6e-8 * 1001);
  EXPECT_NEAR(inPlaneToleranceMm(far) / inPlaneToleranceMm(makeBox(Vec3(100, 0, 0), Vec3(101, 1, 1))), 1001.0 / 101.0, 1e-9);
  EXPECT_LT(inPlaneToleranceMm(far), 0.05);  // far below a layer
}

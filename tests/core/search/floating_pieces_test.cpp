// The search's Criterion II pre-check: "certainly floating" must never be said of a cut whose part below
// stands, or the search would lose plans; it must catch most real refusals, or it would not save clips.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "multidir/core/geometry/clipping.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "search/floating_pieces.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir::core;
using multidir::core::detail::certainlyLeavesFloatingPiece;
using multidir::core::detail::clipMarginMm;

namespace {

constexpr double kPlatformToleranceMm = 0.01;

double lowestAlong(const TriangleMesh& mesh, const Vec3& up) {
  double low = INFINITY;
  for (const Vec3& v : mesh.vertices) low = std::min(low, up.dot(v));
  return low;
}

// What the search checks after clipping: every connected solid below reaches the platform.
bool clippedPartStands(const TriangleMesh& below, const Vec3& up, double platformMm) {
  const FaceComponents components = faceComponents(below);
  std::vector<double> lowest(components.count, INFINITY);
  for (std::size_t f = 0; f < below.triangles.size(); ++f)
    for (std::int32_t v : below.triangles[f])
      lowest[components.componentOfFace[f]] = std::min(lowest[components.componentOfFace[f]], up.dot(below.vertices[v]));
  for (double low : lowest)
    if (low - platformMm > kPlatformToleranceMm) return false;
  return true;
}

// A box with a box-shaped cavity inside (a second shell facing inwards).
TriangleMesh hollowBox() {
  TriangleMesh outer = multidir::test::makeBox(Vec3(0, 0, 0), Vec3(40, 40, 40));
  const TriangleMesh inner = multidir::test::makeBox(Vec3(10, 10, 10), Vec3(30, 30, 30));
  const auto offset = static_cast<std::int32_t>(outer.vertices.size());
  outer.vertices.insert(outer.vertices.end(), inner.vertices.begin(), inner.vertices.end());
  for (const Triangle& t : inner.triangles) outer.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
  outer.resetOrigins();
  return outer;
}

}  // namespace

TEST(FloatingPieces, AHookCutBelowTheTopOfItsDropLeavesTheDropFloating) {
  const TriangleMesh hook = multidir::test::makeHook(10);
  EXPECT_TRUE(certainlyLeavesFloatingPiece(hook, Plane{Vec3::UnitZ(), 40.0}, Vec3::UnitZ(), kPlatformToleranceMm,
                                           clipMarginMm(hook)));
}

TEST(FloatingPieces, AHookCutLowOnItsStemLeavesNothingFloating) {
  const TriangleMesh hook = multidir::test::makeHook(10);
  EXPECT_FALSE(certainlyLeavesFloatingPiece(hook, Plane{Vec3::UnitZ(), 10.0}, Vec3::UnitZ(), kPlatformToleranceMm,
                                            clipMarginMm(hook)));
}

TEST(FloatingPieces, ACavityFloorJoinedToTheWallsByTheCapIsNotCalledFloating) {
  // Below z = 20 the cavity's floor is a surface of its own, clear of the platform, but the cap (a square
  // ring) joins it to the outer walls: the part below is one standing solid.
  const TriangleMesh hollow = hollowBox();
  const Plane plane{Vec3::UnitZ(), 20.0};
  auto clipped = clipByPlane(hollow, plane, 0);
  ASSERT_TRUE(clipped.ok()) << clipped.error().message;
  ASSERT_TRUE(clippedPartStands(clipped->below, Vec3::UnitZ(), 0.0));
  EXPECT_FALSE(certainlyLeavesFloatingPiece(hollow, plane, Vec3::UnitZ(), kPlatformToleranceMm, clipMarginMm(hollow)));
}

// On real models and random planes: whenever the pre-check says "floating", the clip agrees; and it finds
// most of the clips that do leave a piece floating.
void expectSoundAndUseful(const char* model) {
  const TriangleMesh mesh = multidir::test::loadSharedModel(model);
  const Vec3 up = Vec3::UnitY();
  const double platform = lowestAlong(mesh, up);
  const double margin = clipMarginMm(mesh);
  std::mt19937 random(7);
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int floating = 0, caught = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 normal = Vec3(gaussian(random), gaussian(random), gaussian(random)).normalized();
    double low = INFINITY, high = -INFINITY;
    for (const Vec3& v : mesh.vertices) low = std::min(low, normal.dot(v)), high = std::max(high, normal.dot(v));
    const Plane plane{normal, low + (high - low) * (0.05 + 0.9 * unit(random))};
    auto clipped = clipByPlane(mesh, plane, 0);
    ASSERT_TRUE(clipped.ok()) << clipped.error().message;
    if (clipped->below.empty()) continue;
    const bool stands = clippedPartStands(clipped->below, up, platform);
    const bool said = certainlyLeavesFloatingPiece(mesh, plane, up, platform + kPlatformToleranceMm, margin);
    EXPECT_FALSE(stands && said) << model << ": plane " << trial << " was called floating but stands";
    floating += !stands;
    caught += !stands && said;
  }
  ASSERT_GT(floating, 20) << "the random planes should refuse some cuts";
  EXPECT_GE(caught, floating * 8 / 10) << model << ": caught " << caught << " of " << floating;
}

TEST(FloatingPieces, NeverWrongAndCatchesMostRefusalsOnTheKnight) { expectSoundAndUseful("knight.off"); }
TEST(FloatingPieces, NeverWrongAndCatchesMostRefusalsOnTheFertilityStatue) { expectSoundAndUseful("fertility.off"); }

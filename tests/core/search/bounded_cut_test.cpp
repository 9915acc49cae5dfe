// The engine's cut with a bound on the risky area of the regions cut so far (polishing's trials: a trial whose
// regions already hold the incumbent plan's J_G cannot win, so it stops before measuring the part below).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "multidir/core/mesh/mesh_io.h"
#include "search/search_engine.h"
#include "support/up_y_machine.h"

using namespace multidir::core;
using multidir::core::detail::SearchEngine;

namespace {

TriangleMesh kitten() {
  auto loaded = loadMesh(std::string(MULTIDIR_SHARED_MODELS_DIR) + "/kitten.off");
  EXPECT_TRUE(loaded.ok()) << loaded.error().describe();
  return loaded.ok() ? loaded->mesh : TriangleMesh{};
}

using multidir::test::upY;

// A plane through the kitten's head, tilted off up: the region above it has risky area along its normal.
Plane headPlane() { return Plane{Vec3(0.3, 1.0, 0.2).normalized(), 40.0}; }

// An engine on the kitten printed along +Y (it keeps references to the model, machine, options and job).
class BoundedCut : public ::testing::Test {
 protected:
  const TriangleMesh model = kitten();
  const MachineSpec machine = upY();
  const SearchOptions options;
  JobContext job;
  SearchEngine engine{model, machine, options, job};
};

}  // namespace

TEST_F(BoundedCut, IsRefusedOnceTheRegionsCutSoFarHoldTheBound) {
  const auto unbounded = engine.cut(engine.root(), headPlane());
  ASSERT_TRUE(unbounded.ok()) << unbounded.error().describe();
  const double regionRisky = (*unbounded)->prefixJgMm2;
  ASSERT_GT(regionRisky, 0.0) << "the test needs a region with risky area";
  EXPECT_FALSE(engine.cut(engine.root(), headPlane(), regionRisky).ok());
  EXPECT_FALSE(engine.cut(engine.root(), headPlane(), 0.5 * regionRisky).ok());
}

TEST_F(BoundedCut, BelowTheBoundIsTheSameNodeAsWithoutIt) {
  const auto unbounded = engine.cut(engine.root(), headPlane());
  ASSERT_TRUE(unbounded.ok()) << unbounded.error().describe();
  const double justAbove = std::nextafter((*unbounded)->prefixJgMm2, std::numeric_limits<double>::infinity());
  const auto bounded = engine.cut(engine.root(), headPlane(), justAbove);
  ASSERT_TRUE(bounded.ok()) << bounded.error().describe();
  const detail::SearchNode& a = **unbounded;
  const detail::SearchNode& b = **bounded;
  EXPECT_EQ(b.plane.normal, a.plane.normal);
  EXPECT_EQ(b.plane.offset, a.plane.offset);
  EXPECT_EQ(b.prefixJgMm2, a.prefixJgMm2);
  EXPECT_EQ(b.riskyUpAreaMm2, a.riskyUpAreaMm2);
  EXPECT_EQ(b.volumeMm3, a.volumeMm3);
  EXPECT_EQ(b.remaining->faceCount(), a.remaining->faceCount());
  EXPECT_EQ(b.riskyUpShare, a.riskyUpShare);
  EXPECT_EQ(b.addedFaces, a.addedFaces);
  EXPECT_EQ(b.removedParentFaces, a.removedParentFaces);
}

TEST_F(BoundedCut, RefusesWhatTheUnboundedCutRefusesWithTheSameError) {
  // A millimetre below the kitten's top: the region above is too thin to print (checked with the region's
  // measures, which a bounded cut takes first).
  double top = -std::numeric_limits<double>::infinity();
  for (const Vec3& v : model.vertices) top = std::max(top, v.y());
  const Plane thin{Vec3::UnitY(), top - 1.0};
  const auto unbounded = engine.cut(engine.root(), thin);
  const auto bounded = engine.cut(engine.root(), thin, 1.0);
  ASSERT_FALSE(unbounded.ok());
  ASSERT_FALSE(bounded.ok());
  EXPECT_EQ(bounded.error().message, unbounded.error().message);
}

// detail::weldVertices: the earliest kept point within the tolerance, and the same answer on any number of
// threads.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "mesh/vertex_weld.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

struct Weld {
  std::vector<std::int32_t> map;
  std::vector<Vec3> welded;
  std::size_t merged = 0;
  std::vector<std::int64_t> firstMerged;
};

Weld weld(const std::vector<Vec3>& points, double tolerance, int threads) {
  Weld w;
  const std::vector<char> used(points.size(), 1);
  w.map = detail::weldVertices(points, used, tolerance, threads, w.welded, w.merged, w.firstMerged, 5);
  return w;
}

// The rule itself, point by point in order: to the earliest kept point within the tolerance, else kept.
std::vector<std::int32_t> referenceWeld(const std::vector<Vec3>& points, double tolerance) {
  std::vector<std::int32_t> map(points.size(), -1);
  std::vector<std::size_t> kept;
  for (std::size_t v = 0; v < points.size(); ++v) {
    for (std::size_t k = 0; k < kept.size() && map[v] < 0; ++k)
      if ((points[kept[k]] - points[v]).squaredNorm() <= tolerance * tolerance) map[v] = static_cast<std::int32_t>(k);
    if (map[v] < 0) {
      map[v] = static_cast<std::int32_t>(kept.size());
      kept.push_back(v);
    }
  }
  return map;
}

// A real model as an STL holds it, every corner three times or more, and a few hundred corners moved within
// the tolerance so that some points have several others near them.
std::vector<Vec3> kittenCornersWithNearCopies(double tolerance) {
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  std::vector<Vec3> points;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offset(-0.5 * tolerance, 0.5 * tolerance);
  for (std::size_t f = 0; f < kitten.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      Vec3 p = kitten.corner(f, k);
      if (f % 97 == 0) p += Vec3(offset(random), offset(random), offset(random));
      points.push_back(p);
    }
  return points;
}

}  // namespace

TEST(VertexWeld, GivesTheSameResultOnOneThreadAsOnFour) {
  const double tolerance = 1e-3;
  const std::vector<Vec3> points = kittenCornersWithNearCopies(tolerance);
  const Weld one = weld(points, tolerance, 1), four = weld(points, tolerance, 4);
  EXPECT_EQ(one.map, four.map);
  EXPECT_EQ(one.welded, four.welded);
  EXPECT_EQ(one.merged, four.merged);
  EXPECT_EQ(one.firstMerged, four.firstMerged);
  EXPECT_GT(one.merged, 2 * one.welded.size());  // every corner of a closed mesh repeats
}

TEST(VertexWeld, WeldsEachPointToTheEarliestKeptPointWithinTheTolerance) {
  // Clumps of points a fraction of the tolerance apart, so that chains of near points form and the order of
  // the choices matters; on a real model's corners.
  const double tolerance = 1e-3;
  std::vector<Vec3> points = kittenCornersWithNearCopies(tolerance);
  points.resize(6000);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> offset(-0.8 * tolerance, 0.8 * tolerance);
  for (std::size_t i = 0; i < 3000; ++i)
    points.push_back(points[i * 2] + Vec3(offset(random), offset(random), offset(random)));
  const std::vector<std::int32_t> expected = referenceWeld(points, tolerance);
  for (const int threads : {1, 3}) {
    const Weld w = weld(points, tolerance, threads);
    EXPECT_EQ(w.map, expected) << threads << " threads";
    EXPECT_EQ(w.merged, points.size() - w.welded.size());
  }
}

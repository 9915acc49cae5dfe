#include "multidir/core/geometry/polygon_triangulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "multidir/core/common/units.h"

namespace multidir::core {
namespace {

double signedArea(const std::vector<Vec2>& p, const Triangle& t) {
  const Vec2 a = p[t[1]] - p[t[0]], b = p[t[2]] - p[t[0]];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

double loopArea(const std::vector<Vec2>& p, const std::vector<std::int32_t>& loop) {
  double area = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2& a = p[loop[i]];
    const Vec2& b = p[loop[(i + 1) % loop.size()]];
    area += 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  return area;
}

// "" when the triangles close the loops: each loop edge used once in its direction, every other edge twice in
// opposite directions, no triangle repeating a vertex.
std::string topologyViolation(const PolygonWithHoles& polygon, const std::vector<Triangle>& triangles) {
  std::map<std::pair<int, int>, int> uses;
  for (const Triangle& t : triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return "a triangle repeats a vertex";
    for (int k = 0; k < 3; ++k) ++uses[{t[k], t[(k + 1) % 3]}];
  }
  auto takeLoop = [&](const std::vector<std::int32_t>& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) --uses[{loop[i], loop[(i + 1) % loop.size()]}];
  };
  takeLoop(polygon.outer);
  for (const auto& hole : polygon.holes) takeLoop(hole);
  for (const auto& [edge, count] : uses) {
    if (count < 0 || count > 1) {
      std::ostringstream why;
      why << "edge " << edge.first << "->" << edge.second << " used " << count << " times too many";
      return why.str();
    }
    if (count == 1 && uses.count({edge.second, edge.first}) == 0) return "an inner edge has no twin";
    if (count == 1 && uses[{edge.second, edge.first}] != 1) return "an inner edge is not paired";
  }
  return "";
}

std::vector<Triangle> triangulateOrFail(const std::vector<Vec2>& points, const PolygonWithHoles& polygon) {
  Result<std::vector<Triangle>> result = triangulatePolygon(points, polygon);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().describe());
  if (!result.ok()) return {};
  EXPECT_EQ(topologyViolation(polygon, result.value()), "");
  return result.value();
}

double regionArea(const std::vector<Vec2>& points, const PolygonWithHoles& polygon) {
  double area = loopArea(points, polygon.outer);
  for (const auto& hole : polygon.holes) area += loopArea(points, hole);
  return area;
}

void expectNoFlatOrInvertedTriangle(const std::vector<Vec2>& points, const std::vector<Triangle>& triangles) {
  for (const Triangle& t : triangles) EXPECT_GT(signedArea(points, t), 1e-12);
}

PolygonWithHoles loops(std::vector<std::int32_t> outer, std::vector<std::vector<std::int32_t>> holes = {}) {
  return PolygonWithHoles{std::move(outer), std::move(holes)};
}

TEST(PolygonTriangulation, SquareGivesTwoCounterClockwiseTriangles) {
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  const auto triangles = triangulateOrFail(points, loops({0, 1, 2, 3}));
  EXPECT_EQ(triangles.size(), 2u);
  expectNoFlatOrInvertedTriangle(points, triangles);
}

TEST(PolygonTriangulation, CollinearPointsAreAllUsedWithoutFlatTriangles) {
  // A square with three extra points on its bottom edge and two on its left edge.
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(0.25, 0), Vec2(0.5, 0), Vec2(0.75, 0), Vec2(1, 0),
                                    Vec2(1, 1), Vec2(0, 1),    Vec2(0, 0.6), Vec2(0, 0.3)};
  const PolygonWithHoles polygon = loops({0, 1, 2, 3, 4, 5, 6, 7, 8});
  const auto triangles = triangulateOrFail(points, polygon);
  EXPECT_EQ(triangles.size(), 7u);
  expectNoFlatOrInvertedTriangle(points, triangles);
}

TEST(PolygonTriangulation, NonConvexCombIsCoveredExactly) {
  std::vector<Vec2> points;
  std::vector<std::int32_t> outer;
  // Ten teeth pointing up from a base strip.
  points.emplace_back(0, 0);
  points.emplace_back(20, 0);
  for (int i = 9; i >= 0; --i) {
    points.emplace_back(2 * i + 2, 1);
    points.emplace_back(2 * i + 1.5, 5);
    points.emplace_back(2 * i + 1, 1);
    points.emplace_back(2 * i + 0.5, 5 + 0.1 * i);
  }
  points.emplace_back(0, 1);
  for (std::size_t i = 0; i < points.size(); ++i) outer.push_back(static_cast<std::int32_t>(i));
  const PolygonWithHoles polygon = loops(outer);
  ASSERT_GT(loopArea(points, outer), 0.0);
  const auto triangles = triangulateOrFail(points, polygon);
  double area = 0.0;
  for (const Triangle& t : triangles) area += signedArea(points, t);
  EXPECT_NEAR(area, regionArea(points, polygon), 1e-9);
  expectNoFlatOrInvertedTriangle(points, triangles);
}

TEST(PolygonTriangulation, SquareHoleIsBridgedAndLeftUncovered) {
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(4, 0), Vec2(4, 4), Vec2(0, 4),
                                    Vec2(1, 1), Vec2(1, 3), Vec2(3, 3), Vec2(3, 1)};
  const PolygonWithHoles polygon = loops({0, 1, 2, 3}, {{4, 5, 6, 7}});
  const auto triangles = triangulateOrFail(points, polygon);
  EXPECT_EQ(triangles.size(), 8u);
  double area = 0.0;
  for (const Triangle& t : triangles) area += signedArea(points, t);
  EXPECT_NEAR(area, 12.0, 1e-12);
  expectNoFlatOrInvertedTriangle(points, triangles);
}

TEST(PolygonTriangulation, ManyHolesInARowAreAllBridged) {
  std::vector<Vec2> points = {Vec2(0, 0), Vec2(41, 0), Vec2(41, 3), Vec2(0, 3)};
  PolygonWithHoles polygon = loops({0, 1, 2, 3});
  for (int h = 0; h < 20; ++h) {
    const auto base = static_cast<std::int32_t>(points.size());
    // Holes clockwise, their leftmost points aligned so bridges meet collinear candidates.
    points.emplace_back(2 * h + 1, 1);
    points.emplace_back(2 * h + 1, 2);
    points.emplace_back(2 * h + 2, 2);
    points.emplace_back(2 * h + 2, 1);
    polygon.holes.push_back({base, base + 1, base + 2, base + 3});
  }
  const auto triangles = triangulateOrFail(points, polygon);
  double area = 0.0;
  for (const Triangle& t : triangles) area += signedArea(points, t);
  EXPECT_NEAR(area, 41 * 3 - 20, 1e-9);
  expectNoFlatOrInvertedTriangle(points, triangles);
}

TEST(PolygonTriangulation, HoleTouchingTheOuterLoopAtASharedVertexIsJoinedThere) {
  // Outer square with vertex 1 in the middle of its bottom edge; a triangular hole hanging from it.
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(2, 0), Vec2(4, 0), Vec2(4, 4), Vec2(0, 4), Vec2(1, 1), Vec2(3, 1)};
  const PolygonWithHoles polygon = loops({0, 1, 2, 3, 4}, {{1, 5, 6}});
  const auto triangles = triangulateOrFail(points, polygon);
  double area = 0.0;
  for (const Triangle& t : triangles) area += signedArea(points, t);
  EXPECT_NEAR(area, 16.0 - 1.0, 1e-12);
  expectNoFlatOrInvertedTriangle(points, triangles);
}

TEST(PolygonTriangulation, RandomStarPolygonsWithHolesAreCoveredExactly) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> radius(0.6, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec2> points;
    PolygonWithHoles polygon;
    const int n = 5 + trial % 60;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * kPi * i / n;
      const double r = 10 * radius(random);
      points.emplace_back(r * std::cos(a), r * std::sin(a));
      polygon.outer.push_back(i);
    }
    // A small clockwise hole near the centre on some trials.
    if (trial % 2 == 0) {
      const auto base = static_cast<std::int32_t>(points.size());
      for (int i = 0; i < 5; ++i) {
        const double a = -2 * kPi * i / 5;
        points.emplace_back(2 * std::cos(a) + 0.3, 2 * std::sin(a));
      }
      polygon.holes.push_back({base, base + 1, base + 2, base + 3, base + 4});
    }
    const auto triangles = triangulateOrFail(points, polygon);
    double area = 0.0;
    for (const Triangle& t : triangles) area += signedArea(points, t);
    EXPECT_NEAR(area, regionArea(points, polygon), 1e-9) << "trial " << trial;
    for (const Triangle& t : triangles) EXPECT_GT(signedArea(points, t), 0.0) << "trial " << trial;
  }
}

TEST(PolygonTriangulation, NearlyCollinearAndNearlyCoincidentPointsStillCloseTheLoop) {
  // A long thin sliver whose points wander 1e-13 off a line, with a near-duplicate point.
  std::vector<Vec2> points;
  std::vector<std::int32_t> outer;
  for (int i = 0; i <= 20; ++i) points.emplace_back(i, (i % 3 == 0 ? 1e-13 : -1e-13));
  points.emplace_back(20 + 1e-14, 1e-3);
  for (int i = 19; i >= 0; --i) points.emplace_back(i, 1e-3 + (i % 2 == 0 ? 1e-13 : 0.0));
  for (std::size_t i = 0; i < points.size(); ++i) outer.push_back(static_cast<std::int32_t>(i));
  const PolygonWithHoles polygon = loops(outer);
  const auto triangles = triangulateOrFail(points, polygon);
  EXPECT_EQ(triangles.size(), points.size() - 2);
  double area = 0.0;
  for (const Triangle& t : triangles) area += signedArea(points, t);
  EXPECT_NEAR(area, regionArea(points, polygon), 1e-12);
}

TEST(PolygonTriangulation, LoopWithoutAreaStillGetsTriangles) {
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)};
  const auto triangles = triangulateOrFail(points, loops({0, 1, 2}));
  EXPECT_EQ(triangles.size(), 1u);
}

TEST(PolygonTriangulation, AvoidsDiagonalsItIsAskedToAvoid) {
  // A rectangle with midpoints 1 and 4 on its long sides: the diagonal 1-4 is the natural cut, but forbidden.
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(0, 1)};
  // Starting at 1, plain ear clipping cuts 1-3 and then 1-4.
  const PolygonWithHoles polygon = loops({1, 2, 3, 4, 5, 0});
  const auto unconstrained = triangulateOrFail(points, polygon);
  auto hasDiagonal14 = [](const std::vector<Triangle>& triangles) {
    for (const Triangle& t : triangles)
      for (int k = 0; k < 3; ++k)
        if (std::minmax(t[k], t[(k + 1) % 3]) == std::minmax(1, 4)) return true;
    return false;
  };
  ASSERT_TRUE(hasDiagonal14(unconstrained));
  Result<std::vector<Triangle>> result = triangulatePolygon(points, polygon, {{{4, 1}}});
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(topologyViolation(polygon, result.value()), "");
  EXPECT_FALSE(hasDiagonal14(result.value()));
  expectNoFlatOrInvertedTriangle(points, result.value());
}

TEST(PolygonTriangulation, RejectsBadLoops) {
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1)};
  EXPECT_EQ(triangulatePolygon(points, loops({0, 1})).error().code, ErrorCode::InvalidParameter);
  EXPECT_EQ(triangulatePolygon(points, loops({0, 1, 3})).error().code, ErrorCode::InvalidParameter);
  EXPECT_EQ(triangulatePolygon(points, loops({0, 1, 1, 2})).error().code, ErrorCode::InvalidParameter);
  const std::vector<Vec2> nan = {Vec2(0, 0), Vec2(1, 0), Vec2(std::nan(""), 1)};
  EXPECT_EQ(triangulatePolygon(nan, loops({0, 1, 2})).error().code, ErrorCode::InvalidParameter);
}

}  // namespace
}  // namespace multidir::core

// Caps of cuts through dense meshes: their triangles are (constrained) Delaunay, so that a later plane crossing
// a cap makes cut points spread as the cap's own corners are, never closer than a binary STL's floats can
// tell apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "multidir/core/geometry/clipping.h"
#include "multidir/core/geometry/polygon_triangulation.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/mesh/mesh_resolution.h"
#include "plan/stl_image.h"
#include "support/test_models.h"

namespace multidir::core {
namespace {

// The knight subdivided three times: 64,000 faces, so a cut's cross-section is a loop of many close points.
const TriangleMesh& denseKnight() {
  static const TriangleMesh mesh = [] {
    Result<TriangleMesh> fine = subdivided(test::loadSharedModel("knight.off"), 3);
    if (!fine) throw std::runtime_error(fine.error().describe());
    return std::move(fine).value();
  }();
  return mesh;
}

// Two planes found by random search over the dense knight (seeded, 300 pairs): with the cap of the first
// left as ear clipping made it, the second cut made cut points five of which fell onto others in float.
const Plane kFirstPlane{Vec3(0.113158, 0.122028, -0.986055).normalized(), -61.062195};
const Plane kSecondPlane{Vec3(0.812326, -0.420754, -0.403846).normalized(), 4.545424};

// Whether d lies strictly inside the circle through a, b, c (in either orientation), by more than rounding.
bool strictlyInsideCircumcircle(Vec2 a, Vec2 b, Vec2 c, const Vec2& d) {
  auto cross = [](const Vec2& p, const Vec2& q) { return p.x() * q.y() - p.y() * q.x(); };
  if (cross(b - a, c - a) < 0.0) std::swap(b, c);
  const Vec2 pa = a - d, pb = b - d, pc = c - d;
  const double t1 = pa.squaredNorm() * cross(pb, pc);
  const double t2 = pb.squaredNorm() * cross(pc, pa);
  const double t3 = pc.squaredNorm() * cross(pa, pb);
  return t1 + t2 + t3 > 1e-6 * (std::abs(t1) + std::abs(t2) + std::abs(t3));
}

struct CapCheck {
  std::size_t interiorEdges = 0;
  std::size_t notDelaunay = 0;
};

// Every edge two cap faces of plane `planeId` share, and how many of them are not locally Delaunay: the
// corner of one face opposite the edge lies inside the other face's circumcircle (in the plane's own 2D
// coordinates).
CapCheck checkCap(const TriangleMesh& mesh, const Plane& plane, std::int32_t planeId) {
  const Vec3 u = plane.normal.unitOrthogonal(), v = plane.normal.cross(u);
  auto flat = [&](std::int32_t vertex) {
    const Vec3& p = mesh.vertices[static_cast<std::size_t>(vertex)];
    return Vec2(p.dot(u), p.dot(v));
  };
  // Undirected edge -> the cap faces on it and their corners opposite it.
  std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::pair<std::size_t, std::int32_t>>> faces;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    if (mesh.origins[f] != FaceOrigin::cap(planeId)) continue;
    const Triangle& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      faces[{std::min(a, b), std::max(a, b)}].push_back({f, t[static_cast<std::size_t>((k + 2) % 3)]});
    }
  }
  CapCheck check;
  for (const auto& [edge, sides] : faces) {
    if (sides.size() != 2) continue;
    ++check.interiorEdges;
    for (int s = 0; s < 2; ++s) {
      const Triangle& t = mesh.triangles[sides[static_cast<std::size_t>(s)].first];
      const std::int32_t across = sides[static_cast<std::size_t>(1 - s)].second;
      if (strictlyInsideCircumcircle(flat(t[0]), flat(t[1]), flat(t[2]), flat(across))) {
        ++check.notDelaunay;
        break;
      }
    }
  }
  return check;
}

}  // namespace

TEST(CapDelaunay, CapsOfACutThroughADenseMeshAreLocallyDelaunay) {
  const Result<ClipResult> clip = clipByPlane(denseKnight(), kFirstPlane, 1);
  ASSERT_TRUE(clip.ok()) << clip.error().describe();
  for (const TriangleMesh* side : {&clip->below, &clip->above}) {
    const CapCheck check = checkCap(*side, kFirstPlane, 1);
    ASSERT_GT(check.interiorEdges, 100u) << "the cut must cross the knight through many faces";
    EXPECT_EQ(check.notDelaunay, 0u) << "of " << check.interiorEdges << " interior cap edges";
  }
}

TEST(CapDelaunay, SecondCutAcrossADenseCapKeepsEveryCornerApartInFloat) {
  // Ear clipping left fans of long thin triangles in the first cap; the second plane crossed them at points
  // that crowded closer than float precision (5 corners of each side would merge in a binary STL). On a
  // million-face knight this happened at every offset of some normals, and the search lost those planes.
  const Result<ClipResult> first = clipByPlane(denseKnight(), kFirstPlane, 1);
  ASSERT_TRUE(first.ok()) << first.error().describe();
  ASSERT_EQ(detail::cornersMergedAtFloatPrecision(first->below), 0u);
  ASSERT_EQ(detail::cornersMergedAtFloatPrecision(first->above), 0u);
  const TriangleMesh& larger = first->below.faceCount() > first->above.faceCount() ? first->below : first->above;
  const Result<ClipResult> second = clipByPlane(larger, kSecondPlane, 2);
  ASSERT_TRUE(second.ok()) << second.error().describe();
  ASSERT_FALSE(second->below.empty());
  ASSERT_FALSE(second->above.empty());
  auto hasFirstCap = [](const TriangleMesh& mesh) {
    return std::find(mesh.origins.begin(), mesh.origins.end(), FaceOrigin::cap(1)) != mesh.origins.end();
  };
  ASSERT_TRUE(hasFirstCap(second->below) && hasFirstCap(second->above)) << "the second cut crosses the first cap";
  EXPECT_EQ(detail::cornersMergedAtFloatPrecision(second->below), 0u);
  EXPECT_EQ(detail::cornersMergedAtFloatPrecision(second->above), 0u);
}

}  // namespace multidir::core

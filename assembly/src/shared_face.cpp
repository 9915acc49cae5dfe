// The face two parts share at a joint, and rays through a part (docs/apart.md).
#include "shared_face.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace multidir::assembly {

using core::TriangleMesh;

namespace {

double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

}  // namespace

bool inTriangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
  const double d1 = cross2(a, b, p), d2 = cross2(b, c, p), d3 = cross2(c, a, p);
  return !((d1 < 0 || d2 < 0 || d3 < 0) && (d1 > 0 || d2 > 0 || d3 > 0));
}

double segmentDistance(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

namespace {

std::vector<std::size_t> capFaces(const TriangleMesh& mesh, std::int32_t planeId) {
  std::vector<std::size_t> faces;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if (mesh.origins[f].isCap() && mesh.origins[f].index == planeId) faces.push_back(f);
  return faces;
}

}  // namespace

SharedFace sharedFace(const core::ApartPlan& plan, const core::ApartJoint& joint, const Frame& frame) {
  auto at = [&](const Vec3& p) { return Point2((p - frame.origin).dot(frame.u), (p - frame.origin).dot(frame.v)); };
  const TriangleMesh& upper = plan.parts[static_cast<std::size_t>(joint.upper)].mesh;
  const TriangleMesh& lower = plan.parts[static_cast<std::size_t>(joint.lower)].mesh;
  std::vector<std::array<Point2, 3>> lowerCap;
  for (std::size_t f : capFaces(lower, joint.planeId))
    lowerCap.push_back({at(lower.corner(f, 0)), at(lower.corner(f, 1)), at(lower.corner(f, 2))});
  SharedFace shared;
  std::map<std::pair<std::int32_t, std::int32_t>, int> edgeUses;
  for (std::size_t f : capFaces(upper, joint.planeId)) {
    const std::array<Point2, 3> t{at(upper.corner(f, 0)), at(upper.corner(f, 1)), at(upper.corner(f, 2))};
    const Point2 centroid = (t[0] + t[1] + t[2]) / 3.0;
    const bool onLower = std::any_of(lowerCap.begin(), lowerCap.end(),
                                     [&](const auto& o) { return inTriangle(centroid, o[0], o[1], o[2]); });
    if (!onLower) continue;
    shared.triangles.push_back(t);
    shared.areaMm2 += upper.faceArea(f);
    for (const Point2& p : t) {
      shared.low = shared.low.cwiseMin(p);
      shared.high = shared.high.cwiseMax(p);
    }
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = upper.triangles[f][static_cast<std::size_t>(k)];
      const std::int32_t b = upper.triangles[f][static_cast<std::size_t>((k + 1) % 3)];
      ++edgeUses[{std::min(a, b), std::max(a, b)}];
    }
  }
  for (const auto& [edge, uses] : edgeUses)
    if (uses == 1)
      shared.boundary.push_back({at(upper.vertices[static_cast<std::size_t>(edge.first)]),
                                 at(upper.vertices[static_cast<std::size_t>(edge.second)])});
  return shared;
}

double depthAlong(const TriangleMesh& part, std::int32_t planeId, const Vec3& origin, const Vec3& direction) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < part.triangles.size(); ++f) {
    if (part.origins[f].isCap() && part.origins[f].index == planeId) continue;
    if (auto t = rayHit(origin, direction, part.corner(f, 0), part.corner(f, 1), part.corner(f, 2)))
      nearest = std::min(nearest, *t);
  }
  return nearest;
}


bool SharedFace::contains(const Point2& p) const {
  return std::any_of(triangles.begin(), triangles.end(), [&](const auto& t) { return inTriangle(p, t[0], t[1], t[2]); });
}

double SharedFace::distanceToBoundary(const Point2& p) const {
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& e : boundary) nearest = std::min(nearest, segmentDistance(p, e[0], e[1]));
  return nearest;
}

}  // namespace multidir::assembly

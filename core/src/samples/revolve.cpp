#include "multidir/core/samples/revolve.h"

#include <cmath>
#include <string>

#include "multidir/core/common/units.h"

namespace multidir::core::samples {
namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Whether closed segments pq and rs share a point (touching counts).
bool segmentsMeet(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
  const double d1 = cross2(q - p, r - p);
  const double d2 = cross2(q - p, s - p);
  const double d3 = cross2(s - r, p - r);
  const double d4 = cross2(s - r, q - r);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto onSegment = [](const Vec2& a, const Vec2& b, const Vec2& x, double side) {
    return side == 0.0 && x.x() >= std::min(a.x(), b.x()) && x.x() <= std::max(a.x(), b.x()) &&
           x.y() >= std::min(a.y(), b.y()) && x.y() <= std::max(a.y(), b.y());
  };
  return onSegment(p, q, r, d1) || onSegment(p, q, s, d2) || onSegment(r, s, p, d3) || onSegment(r, s, q, d4);
}

Error invalid(const std::string& message) { return Error{ErrorCode::InvalidParameter, message, "profile"}; }

Status checkProfile(const std::vector<Vec2>& profile, int segments) {
  const std::size_t n = profile.size();
  if (n < 3) return invalid("a profile needs at least 3 points (got " + std::to_string(n) + ")");
  if (segments < 3) return invalid("a revolution needs at least 3 segments (got " + std::to_string(segments) + ")");
  for (std::size_t i = 0; i < n; ++i)
    if (!profile[i].allFinite()) return invalid("point " + std::to_string(i) + " is not finite");
  if (profile.front().x() != 0.0 || profile.back().x() != 0.0)
    return invalid("the first and the last point must lie on the axis (r = 0)");
  for (std::size_t i = 1; i + 1 < n; ++i)
    if (!(profile[i].x() > 0.0))
      return invalid("point " + std::to_string(i) + " has r <= 0; only the two ends may touch the axis");
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (profile[i] == profile[i + 1])
      return invalid("points " + std::to_string(i) + " and " + std::to_string(i + 1) + " are equal");
  // Edges of the closed polygon: i runs from point i to point i + 1; edge n - 1 is the closing one along
  // the axis. Non-neighbouring edges must not meet.
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 2; b < n; ++b) {
      if (a == 0 && b == n - 1) continue;
      if (segmentsMeet(profile[a], profile[(a + 1) % n], profile[b], profile[(b + 1) % n]))
        return invalid("edges " + std::to_string(a) + " and " + std::to_string(b) + " of the profile cross");
    }
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < n; ++i) twiceArea += cross2(profile[i], profile[(i + 1) % n]);
  if (!(twiceArea > 0.0))
    return invalid("the profile runs clockwise in the (r, z) plane; list its points in the reverse order");
  return Done{};
}

}  // namespace

Result<TriangleMesh> revolveProfile(const std::vector<Vec2>& profile, int segments) {
  if (Status s = checkProfile(profile, segments); !s) return s.error();
  const std::size_t rings = profile.size() - 2;
  const auto ringStart = [](std::size_t ring, int s) { return std::int32_t(1 + ring * std::size_t(s)); };

  TriangleMesh mesh;
  mesh.vertices.reserve(2 + rings * std::size_t(segments));
  mesh.vertices.emplace_back(0.0, 0.0, profile.front().y());
  for (std::size_t ring = 0; ring < rings; ++ring) {
    const Vec2& rz = profile[ring + 1];
    for (int s = 0; s < segments; ++s) {
      const double angle = 2.0 * kPi * s / segments;
      mesh.vertices.emplace_back(rz.x() * std::cos(angle), rz.x() * std::sin(angle), rz.y());
    }
  }
  const auto bottom = std::int32_t(0);
  const auto top = static_cast<std::int32_t>(mesh.vertices.size());
  mesh.vertices.emplace_back(0.0, 0.0, profile.back().y());

  // Angles grow counter-clockwise around +Z and the profile runs counter-clockwise in (r, z), so
  // (ring i at s, ring i at s + 1, ring i + 1 at s + 1) faces outward.
  for (int s = 0; s < segments; ++s) {
    const int next = (s + 1) % segments;
    mesh.triangles.push_back({bottom, ringStart(0, segments) + next, ringStart(0, segments) + s});
    for (std::size_t ring = 0; ring + 1 < rings; ++ring) {
      const std::int32_t a = ringStart(ring, segments) + s;
      const std::int32_t b = ringStart(ring, segments) + next;
      const std::int32_t c = ringStart(ring + 1, segments) + next;
      const std::int32_t d = ringStart(ring + 1, segments) + s;
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
    mesh.triangles.push_back({ringStart(rings - 1, segments) + s, ringStart(rings - 1, segments) + next, top});
  }
  mesh.resetOrigins();
  return mesh;
}

}  // namespace multidir::core::samples

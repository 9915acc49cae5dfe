#include "multidir/core/search/contact_patch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "multidir/core/common/units.h"

namespace multidir::core {
namespace {

using Point2 = Eigen::Vector2d;

double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

double distanceToSegment(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// The hull corners within kContactToleranceMm of the lowest along `up` (unit), and that lowest height.
std::vector<std::int32_t> touchingCorners(const ConvexHull& hull, const Vec3& up, double& lowest) {
  lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : hull.vertices) lowest = std::min(lowest, up.dot(p));
  std::vector<std::int32_t> touching;
  for (std::size_t v = 0; v < hull.vertices.size(); ++v)
    if (up.dot(hull.vertices[v]) <= lowest + kContactToleranceMm) touching.push_back(static_cast<std::int32_t>(v));
  return touching;
}

ContactPatch patchOf(const ConvexHull& hull, const Vec3& up, const std::vector<std::int32_t>& touching, double lowest,
                     const Vec3& centreOfMass) {
  ContactPatch patch;
  patch.up = up;
  // A right-handed frame (u, v, up): counter-clockwise in (u, v) is counter-clockwise seen from above.
  const Vec3 u = up.unitOrthogonal();
  const Vec3 v = up.cross(u);
  std::vector<Point2> corners;
  corners.reserve(touching.size());
  for (std::int32_t i : touching) corners.emplace_back(u.dot(hull.vertices[i]), v.dot(hull.vertices[i]));
  const std::vector<Point2> outline = convexHull2d(std::move(corners));
  for (std::size_t i = 0; i < outline.size(); ++i) {
    patch.outline.push_back(outline[i].x() * u + outline[i].y() * v + lowest * up);
    if (outline.size() >= 3) patch.areaMm2 += 0.5 * cross2(Point2::Zero(), outline[i], outline[(i + 1) % outline.size()]);
  }
  const Point2 centre(u.dot(centreOfMass), v.dot(centreOfMass));
  double distance = std::numeric_limits<double>::infinity();
  bool inside = outline.size() >= 3 && patch.areaMm2 > 0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Point2& a = outline[i];
    const Point2& b = outline[(i + 1) % outline.size()];
    distance = std::min(distance, distanceToSegment(centre, a, b));
    if (cross2(a, b, centre) <= 0) inside = false;
  }
  patch.stabilityMarginMm = inside ? distance : -distance;
  return patch;
}

}  // namespace

Vec3 solidCentreOfMass(const TriangleMesh& solid) {
  Vec3 sum = Vec3::Zero();
  double volume = 0;
  for (std::size_t f = 0; f < solid.faceCount(); ++f) {
    const Vec3& a = solid.corner(f, 0);
    const Vec3& b = solid.corner(f, 1);
    const Vec3& c = solid.corner(f, 2);
    const double tetrahedron = a.dot(b.cross(c)) / 6.0;
    volume += tetrahedron;
    sum += tetrahedron * (a + b + c) / 4.0;
  }
  return volume != 0 ? Vec3(sum / volume) : Vec3::Zero();
}

ContactPatch contactPatch(const ConvexHull& hull, const Vec3& up, const Vec3& centreOfMass) {
  const Vec3 unitUp = up.normalized();
  double lowest = 0;
  const std::vector<std::int32_t> touching = touchingCorners(hull, unitUp, lowest);
  return patchOf(hull, unitUp, touching, lowest, centreOfMass);
}

std::vector<ContactPatch> standingPatches(const ConvexHull& hull, const Vec3& centreOfMass, double mergeDegrees) {
  const std::size_t n = hull.triangles.size();
  std::vector<Vec3> normals(n);
  std::vector<double> areas(n);
  std::vector<std::vector<std::int32_t>> trianglesAt(hull.vertices.size());
  for (std::size_t f = 0; f < n; ++f) {
    const Triangle& t = hull.triangles[f];
    const Vec3 an = (hull.vertices[t[1]] - hull.vertices[t[0]]).cross(hull.vertices[t[2]] - hull.vertices[t[0]]);
    areas[f] = 0.5 * an.norm();
    normals[f] = an.normalized();
    for (std::int32_t v : t) trianglesAt[v].push_back(static_cast<std::int32_t>(f));
  }
  // Largest faces first, so a patch is found from its bulk, not from a sliver at its rim.
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return areas[a] > areas[b]; });
  std::vector<char> covered(n, 0);
  std::vector<char> touches(hull.vertices.size(), 0);
  std::vector<ContactPatch> patches;
  for (std::size_t f : order) {
    // A face of no area has a normal that rounding decides: it is no plane to stand on.
    if (covered[f] || !(areas[f] > 0) || !normals[f].allFinite()) continue;
    const Vec3 up = -normals[f];
    double lowest = 0;
    const std::vector<std::int32_t> touching = touchingCorners(hull, up, lowest);
    // Every face lying in this patch gives the same pose: it is not tried again.
    for (std::int32_t v : touching) touches[v] = 1;
    for (std::int32_t v : touching)
      for (std::int32_t g : trianglesAt[v]) {
        const Triangle& t = hull.triangles[g];
        if (touches[t[0]] && touches[t[1]] && touches[t[2]]) covered[g] = 1;
      }
    for (std::int32_t v : touching) touches[v] = 0;
    ContactPatch patch = patchOf(hull, up, touching, lowest, centreOfMass);
    if (patch.stands()) patches.push_back(std::move(patch));
  }
  std::stable_sort(patches.begin(), patches.end(), [](const ContactPatch& a, const ContactPatch& b) {
    constexpr double kTie = 1e-9;
    if (std::abs(a.areaMm2 - b.areaMm2) > kTie * std::max(1.0, a.areaMm2)) return a.areaMm2 > b.areaMm2;
    return a.stabilityMarginMm > b.stabilityMarginMm;
  });
  const double cosMerge = std::cos(mergeDegrees * kPi / 180.0);
  std::vector<ContactPatch> distinct;
  for (ContactPatch& patch : patches) {
    const bool repeat = std::any_of(distinct.begin(), distinct.end(),
                                    [&](const ContactPatch& kept) { return kept.up.dot(patch.up) >= cosMerge; });
    if (!repeat) distinct.push_back(std::move(patch));
  }
  return distinct;
}

}  // namespace multidir::core

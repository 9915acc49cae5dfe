// The shapes of holes and dowels, their volumes, and the wall a hole leaves: no CGAL here.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry_kernels.h"
#include "multidir/assembly/dowels.h"

namespace multidir::assembly {

using core::TriangleMesh;

namespace {

core::Error bad(const std::string& field, const std::string& rule) {
  return core::Error{core::ErrorCode::InvalidParameter, field + " " + rule, field};
}

// A solid of revolution about the local z axis of `frame` from a profile (r, z) that starts and ends on the
// axis (r = 0), going outward then up: closed, faces outward.
TriangleMesh revolved(const std::vector<Eigen::Vector2d>& profile, const Frame& frame, int segments) {
  TriangleMesh mesh;
  std::vector<std::vector<std::int32_t>> rings;
  for (const Eigen::Vector2d& rz : profile) {
    std::vector<std::int32_t> ring;
    if (rz.x() <= 0) {
      mesh.vertices.push_back(frame.at(0, 0, rz.y()));
      ring.assign(static_cast<std::size_t>(segments), static_cast<std::int32_t>(mesh.vertices.size() - 1));
    } else {
      for (int j = 0; j < segments; ++j) {
        const double angle = 2.0 * core::kPi * j / segments;
        ring.push_back(static_cast<std::int32_t>(mesh.vertices.size()));
        mesh.vertices.push_back(frame.at(rz.x() * std::cos(angle), rz.x() * std::sin(angle), rz.y()));
      }
    }
    rings.push_back(std::move(ring));
  }
  for (std::size_t k = 0; k + 1 < rings.size(); ++k)
    for (int j = 0; j < segments; ++j) {
      const std::size_t jn = static_cast<std::size_t>((j + 1) % segments), jj = static_cast<std::size_t>(j);
      const std::int32_t a = rings[k][jj], b = rings[k][jn], c = rings[k + 1][jn], d = rings[k + 1][jj];
      if (a != b && a != c && b != c) mesh.triangles.push_back({a, b, c});
      if (a != c && a != d && c != d) mesh.triangles.push_back({a, c, d});
    }
  mesh.resetOrigins();
  return mesh;
}

// A regular polygon whose sides touch the circle of radius r: a hole made of it holds a round dowel of r.
double circumscribed(double r, int segments) { return r / std::cos(core::kPi / segments); }

double polygonArea(double circumradius, int segments) {
  return 0.5 * segments * circumradius * circumradius * std::sin(2.0 * core::kPi / segments);
}

// How far outside its face a hole's tool reaches, so the boolean never meets the face in a plane.
constexpr double kToolMarginMm = 0.5;

Frame holeFrame(const Dowel& dowel, bool intoUpper) {
  return Frame(dowel.centre, intoUpper ? dowel.axis : Vec3(-dowel.axis));
}

}  // namespace

double Dowel::holeRadiusMm(const DowelOptions& options) const { return 0.5 * diameterMm + options.radialClearanceMm; }
double Dowel::holeDepthMm(const DowelOptions& options) const { return 0.5 * lengthMm + options.depthClearanceMm; }

core::Status validate(const DowelOptions& o) {
  if (!(o.diameterShare > 0 && o.diameterShare <= 1)) return bad("diameter share", "must be above 0 and at most 1");
  if (!(o.minDiameterMm >= 1 && o.minDiameterMm <= o.maxDiameterMm && o.maxDiameterMm <= 50))
    return bad("dowel diameter", "must satisfy 1 <= min <= max <= 50 mm");
  if (!(o.lengthRatio >= 1 && o.lengthRatio <= 10)) return bad("dowel length ratio", "must be between 1 and 10");
  if (!(o.keyStepMm >= 0 && o.keyStepMm <= 10)) return bad("key step", "must be between 0 and 10 mm");
  if (!(o.radialClearanceMm >= 0 && o.radialClearanceMm <= 2))
    return bad("radial clearance", "must be between 0 and 2 mm");
  if (!(o.depthClearanceMm >= 0 && o.depthClearanceMm <= 5)) return bad("depth clearance", "must be between 0 and 5 mm");
  if (!(o.chamferMm >= 0 && o.chamferMm <= 5)) return bad("chamfer", "must be between 0 and 5 mm");
  if (!(o.minWallMm >= 0.4 && o.minWallMm <= 20)) return bad("minimum wall", "must be between 0.4 and 20 mm");
  if (!(o.dowelsPerJoint >= 1 && o.dowelsPerJoint <= 8)) return bad("dowels per joint", "must be between 1 and 8");
  if (!(o.segments >= 8 && o.segments <= 256)) return bad("segments", "must be between 8 and 256");
  return core::Done{};
}

TriangleMesh holeTool(const Dowel& dowel, bool intoUpper, const DowelOptions& options) {
  const int n = options.segments;
  const double r = circumscribed(dowel.holeRadiusMm(options), n);
  const double c = options.chamferMm, m = kToolMarginMm, depth = dowel.holeDepthMm(options);
  // The chamfer's 45-degree cone continues through the face to the margin, so the face is cut in a ring.
  return revolved({{0, -m}, {r + c + m, -m}, {r, c}, {r, depth}, {0, depth}}, holeFrame(dowel, intoUpper), n);
}

TriangleMesh dowelSolid(const Dowel& dowel, const DowelOptions& options) {
  const double r = 0.5 * dowel.diameterMm, half = 0.5 * dowel.lengthMm;
  return revolved({{0, -half}, {r, -half}, {r, half}, {0, half}}, Frame(dowel.centre, dowel.axis), options.segments);
}

double holeVolumeMm3(const Dowel& dowel, const DowelOptions& options) {
  const int n = options.segments;
  const double r = circumscribed(dowel.holeRadiusMm(options), n);
  const double c = options.chamferMm, depth = dowel.holeDepthMm(options);
  const double mouth = polygonArea(r + c, n), bore = polygonArea(r, n);
  // Frustum of the chamfer (similar polygons), then the bore.
  return c / 3.0 * (mouth + bore + std::sqrt(mouth * bore)) + (depth - c) * bore;
}

double holeWallMm(const TriangleMesh& undrilled, std::int32_t jointPlaneId, const Dowel& dowel, bool intoUpper,
                  const DowelOptions& options) {
  const Frame frame = holeFrame(dowel, intoUpper);
  const int n = options.segments;
  const double r = circumscribed(dowel.holeRadiusMm(options), n);
  const double c = options.chamferMm, depth = dowel.holeDepthMm(options);
  // Points on the hole's surface inside the part: rings every 0.25 mm down the chamfer and the bore, and the
  // bottom disc.
  std::vector<Vec3> samples;
  const int levels = std::max(2, static_cast<int>(std::ceil(depth / 0.25)));
  for (int k = 0; k <= levels; ++k) {
    const double z = depth * k / levels;
    const double radius = z < c ? r + c - z : r;
    for (int j = 0; j < n; ++j) {
      const double angle = 2.0 * core::kPi * j / n;
      samples.push_back(frame.at(radius * std::cos(angle), radius * std::sin(angle), z));
    }
  }
  for (int k = 0; k < 4; ++k) {
    const double radius = r * k / 4.0;
    for (int j = 0; j < n; ++j) {
      const double angle = 2.0 * core::kPi * j / n;
      samples.push_back(frame.at(radius * std::cos(angle), radius * std::sin(angle), depth));
    }
  }
  double wall = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < undrilled.triangles.size(); ++f) {
    if (undrilled.origins[f].isCap() && undrilled.origins[f].index == jointPlaneId) continue;
    const Vec3 &a = undrilled.corner(f, 0), &b = undrilled.corner(f, 1), &cc = undrilled.corner(f, 2);
    for (const Vec3& p : samples) wall = std::min(wall, (closestPointOnTriangle(p, a, b, cc) - p).norm());
  }
  return wall;
}

}  // namespace multidir::assembly

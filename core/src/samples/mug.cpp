#include <algorithm>
#include <cmath>

#include "multidir/core/samples/coarsen.h"
#include "multidir/core/samples/implicit_surface.h"
#include "multidir/core/samples/sample_shapes.h"
#include "multidir/core/samples/sdf.h"

namespace multidir::core::samples {
namespace {

constexpr double kOuterRadius = 30.0;
constexpr double kWall = 4.0;
constexpr double kHeight = 80.0;
constexpr double kHandleCentreX = kOuterRadius + 6.0;
constexpr double kHandleCentreZ = 42.0;
constexpr double kHandleRadius = 20.0;
constexpr double kHandleThickness = 4.5;  // tube radius
// Polygonized on a fine grid (so thin parts keep their shape), then coarsened to edges of about
// kMinEdgeMm..kMaxEdgeMm: marching tetrahedra alone would give several times more triangles.
constexpr double kMinEdgeMm = 1.2;
constexpr double kMaxEdgeMm = 3.0;
constexpr double kCellSizeMm = 1.25;

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// The cup is the (r, z) polyline bottom-centre -> bottom-edge -> rim thickened by half the wall: a wall
// of even thickness with a rounded rim and a rounded outer bottom edge, standing flat on z = 0.
double cupDistance(const Vec3& p) {
  const Vec2 rz(std::hypot(p.x(), p.y()), p.z());
  const double half = 0.5 * kWall;
  const Vec2 centre(0.0, half);
  const Vec2 corner(kOuterRadius - half, half);
  const Vec2 rim(kOuterRadius - half, kHeight - half);
  return std::min(distanceToSegment(rz, centre, corner), distanceToSegment(rz, corner, rim)) - half;
}

// A torus in the XZ plane cut at the middle of the wall, so the handle never pokes into the cup.
double handleDistance(const Vec3& p) {
  const double torus = sdfTorusY(p, Vec3(kHandleCentreX, 0.0, kHandleCentreZ), kHandleRadius, kHandleThickness);
  return std::max(torus, (kOuterRadius - 0.5 * kWall) - p.x());
}

double mugDistance(const Vec3& p) { return smoothUnion(cupDistance(p), handleDistance(p), 2.5); }

}  // namespace

Result<TriangleMesh> makeMug() {
  const double margin = 2.0 * kCellSizeMm;
  BoundingBox box;
  box.min = Vec3(-kOuterRadius - margin, -kOuterRadius - margin, -1.5 * kCellSizeMm);
  box.max = Vec3(kHandleCentreX + kHandleRadius + kHandleThickness + margin, kOuterRadius + margin, kHeight + margin);
  Result<TriangleMesh> fine = polygonize(mugDistance, box, kCellSizeMm);
  if (!fine) return fine.error();
  CoarsenOptions coarsen;
  coarsen.minEdgeMm = kMinEdgeMm;
  coarsen.maxEdgeMm = kMaxEdgeMm;
  return collapseShortEdges(*fine, coarsen);
}

}  // namespace multidir::core::samples

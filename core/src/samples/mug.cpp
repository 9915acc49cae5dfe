#include <algorithm>
#include <cmath>

#include "multidir/core/samples/sample_shapes.h"
#include "multidir/core/samples/sdf.h"
#include "samples/polygonize_coarsen.h"

namespace multidir::core::samples {
namespace {

constexpr double kOuterRadius = 30.0;
constexpr double kWall = 4.0;
constexpr double kHeight = 80.0;
constexpr double kHandleCentreX = kOuterRadius + 6.0;
constexpr double kHandleCentreZ = 42.0;
constexpr double kHandleRadius = 20.0;
constexpr double kHandleThickness = 4.5;  // tube radius
// The fine grid's cell (see polygonizeStandingSample).
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
  BoundingBox extent;
  extent.min = Vec3(-kOuterRadius, -kOuterRadius, 0.0);
  extent.max = Vec3(kHandleCentreX + kHandleRadius + kHandleThickness, kOuterRadius, kHeight);
  return polygonizeStandingSample(mugDistance, extent, kCellSizeMm);
}

}  // namespace multidir::core::samples

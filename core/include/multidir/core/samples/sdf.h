#pragma once
// Signed distance functions for the implicit sample models: negative inside, positive outside, in mm.
// The primitives are exact distances; the smooth union and the intersection are not, but they keep the
// sign right and stay within the Lipschitz bound 1, which is all polygonize() needs.
#include <algorithm>
#include <cmath>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::samples {

inline double sdfSphere(const Vec3& p, const Vec3& center, double radius) { return (p - center).norm() - radius; }

// A segment from a to b thickened by radius (a cylinder with hemispherical ends).
inline double sdfCapsule(const Vec3& p, const Vec3& a, const Vec3& b, double radius) {
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm() - radius;
}

// A torus around the axis through center along +Y (its ring lies in the plane y = center.y).
inline double sdfTorusY(const Vec3& p, const Vec3& center, double majorRadius, double minorRadius) {
  const Vec3 q = p - center;
  const double ring = std::hypot(q.x(), q.z()) - majorRadius;
  return std::hypot(ring, q.y()) - minorRadius;
}

// Polynomial smooth minimum: the union of two solids with a fillet about blendMm wide where they meet.
inline double smoothUnion(double a, double b, double blendMm) {
  if (blendMm <= 0.0) return std::min(a, b);
  const double h = std::clamp(0.5 + 0.5 * (b - a) / blendMm, 0.0, 1.0);
  return b + (a - b) * h - blendMm * h * (1.0 - h);
}

// Intersection with the half-space z >= 0: flattens a solid's bottom so it stands on the platform.
inline double aboveFloor(double sdf, const Vec3& p) { return std::max(sdf, -p.z()); }

}  // namespace multidir::core::samples

#pragma once
// Small geometric kernels the dowel code shares: a right-handed frame about an axis, the closest point of a
// triangle (Ericson, Real-Time Collision Detection, 5.1.5) and a ray's hit on a triangle (core's line kernel).
#include <cmath>
#include <optional>

#include "multidir/core/geometry/line_triangle.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::assembly {

using core::Vec3;

// Local (x, y, z) -> origin + x u + y v + z w, with w the given unit axis and (u, v, w) right-handed.
struct Frame {
  Vec3 origin, u, v, w;
  Frame(const Vec3& o, const Vec3& axis) : origin(o), w(axis.normalized()) {
    const Vec3 helper = std::abs(w.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    u = w.cross(helper).normalized();
    v = w.cross(u);
  }
  Vec3 at(double x, double y, double z) const { return origin + x * u + y * v + z * w; }
};

inline Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// Distance along the unit direction to the triangle, when the ray from `origin` meets it at t > 0.
inline std::optional<double> rayHit(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b,
                                    const Vec3& c) {
  const std::optional<double> t = core::lineTriangleParameter(origin, direction, a, b, c);
  if (!t || *t <= 0.0) return std::nullopt;
  return t;
}

}  // namespace multidir::assembly

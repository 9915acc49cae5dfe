#pragma once
// Where a line crosses a triangle (Moller-Trumbore): the one kernel behind the supports' segment casts, the
// inside test of connected solids and the dowels' depth probes, so that all three agree on what a hit is.
#include <cmath>
#include <optional>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

// The parameter t at which origin + t * direction crosses triangle abc (edges and corners count as inside), for
// any sign of t; nothing when the line misses it or runs parallel to its plane (touching is no crossing). The
// caller bounds t: [0, 1] for a segment given as its delta, t > 0 for a ray.
inline std::optional<double> lineTriangleParameter(const Vec3& origin, const Vec3& direction, const Vec3& a,
                                                   const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = direction.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-18) return std::nullopt;
  const double inv = 1.0 / det;
  const Vec3 s = origin - a;
  const double u = s.dot(p) * inv;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Vec3 q = s.cross(e1);
  const double v = direction.dot(q) * inv;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  return e2.dot(q) * inv;
}

}  // namespace multidir::core

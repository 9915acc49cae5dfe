#pragma once
// An oriented plane {x : normal . x = offset}. "Above" is the side the normal points to.
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

struct Plane {
  Vec3 normal = Vec3::UnitZ();  // unit length
  double offset = 0.0;          // mm, along normal

  static Plane throughPoint(const Vec3& unitNormal, const Vec3& point) { return {unitNormal, unitNormal.dot(point)}; }
  double signedDistance(const Vec3& p) const { return normal.dot(p) - offset; }
  Vec3 project(const Vec3& p) const { return p - signedDistance(p) * normal; }
};

}  // namespace multidir::core

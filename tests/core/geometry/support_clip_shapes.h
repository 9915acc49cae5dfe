#pragma once
// Solids whose cross-sections have holes, islands, or islands inside holes, for the clipping tests.
#include <cmath>

#include "multidir/core/common/units.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "support/primitives.h"

namespace multidir::test {

// A thick-walled tube around the z axis through `center`: radii rInner < rOuter, from zMin to zMax,
// `segments` sides. Any plane z = c in (zMin, zMax) cuts it in an annulus: an outer loop and a hole.
inline core::TriangleMesh makeTube(const core::Vec3& center, double rInner, double rOuter, double zMin, double zMax,
                                   int segments) {
  core::TriangleMesh mesh;
  const auto ring = [&](double r, double z) {
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * core::kPi * i / segments;
      mesh.vertices.push_back(center + core::Vec3(r * std::cos(a), r * std::sin(a), z));
    }
  };
  ring(rOuter, zMin);  // ob: 0
  ring(rOuter, zMax);  // ot: segments
  ring(rInner, zMin);  // ib: 2 segments
  ring(rInner, zMax);  // it: 3 segments
  const int n = segments;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const int ob0 = i, ob1 = j, ot0 = n + i, ot1 = n + j, ib0 = 2 * n + i, ib1 = 2 * n + j, it0 = 3 * n + i,
              it1 = 3 * n + j;
    mesh.triangles.push_back({ob0, ob1, ot1});
    mesh.triangles.push_back({ob0, ot1, ot0});
    mesh.triangles.push_back({ib0, it1, ib1});
    mesh.triangles.push_back({ib0, it0, it1});
    mesh.triangles.push_back({ot0, ot1, it1});
    mesh.triangles.push_back({ot0, it1, it0});
    mesh.triangles.push_back({ob0, ib1, ob1});
    mesh.triangles.push_back({ob0, ib0, ib1});
  }
  mesh.resetOrigins();
  return mesh;
}

// Both meshes as one (two shells), origins renumbered in sequence.
inline core::TriangleMesh merge(const core::TriangleMesh& a, const core::TriangleMesh& b) {
  core::TriangleMesh mesh = a;
  const auto offset = static_cast<std::int32_t>(a.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (core::Triangle t : b.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  mesh.resetOrigins();
  return mesh;
}

// A U standing on its base: base 0..30 in x, 0..10 high; two arms 10 wide rising to z = 40; depth 10 in y.
// A plane z = c with 10 < c < 40 cuts it in two separate islands.
inline core::TriangleMesh makeU() {
  using core::Vec3;
  return makeExtrudedProfile({Vec3(0, 0, 0), Vec3(30, 0, 0), Vec3(30, 0, 40), Vec3(20, 0, 40), Vec3(20, 0, 10),
                              Vec3(10, 0, 10), Vec3(10, 0, 40), Vec3(0, 0, 40)},
                             10.0);
}

}  // namespace multidir::test

#pragma once
// Small closed solids built in code for tests, each with outward normals.
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::test {

// Axis-aligned box from `min` to `max` (12 triangles).
core::TriangleMesh makeBox(const core::Vec3& min, const core::Vec3& max);

// Square pyramid standing on its apex: apex at the origin, square base of side `side` at height `height`
// (+Z up), so its four slanted faces look downward.
core::TriangleMesh makeInvertedPyramid(double side, double height);

// Sphere of `radius` around `center`: an icosahedron subdivided `levels` times, vertices on the sphere.
core::TriangleMesh makeIcosphere(const core::Vec3& center, double radius, int levels);

}  // namespace multidir::test

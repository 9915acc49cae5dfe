#pragma once
// Small closed solids built in code for tests, each with outward normals.
#include <vector>

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

namespace multidir::test {

// A prism: the simple polygon `profile` (counter-clockwise, in the x-z plane, z up) swept along +y by depth.
core::TriangleMesh makeExtrudedProfile(const std::vector<core::Vec3>& profileXZ, double depth);

// A T standing on its stem: stem stemWidth x depth x stemHeight, bar barWidth x depth x barHeight on top.
// The bar's two undersides overhang (risky along +Z).
core::TriangleMesh makeTBar(double stemWidth, double stemHeight, double barWidth, double barHeight, double depth);

// A hook: a stem, an arm reaching out at the top and a drop hanging from the arm's end that stops in mid-air.
// Cutting the arm off with a plane below the drop's top leaves the drop floating.
core::TriangleMesh makeHook(double depth);

}  // namespace multidir::test

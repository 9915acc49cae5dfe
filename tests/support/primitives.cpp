#include "support/primitives.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace multidir::test {

using core::Triangle;
using core::TriangleMesh;
using core::Vec3;

TriangleMesh makeBox(const Vec3& min, const Vec3& max) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(i & 1 ? max.x() : min.x(), i & 2 ? max.y() : min.y(), i & 4 ? max.z() : min.z());
  // Each quad listed counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  mesh.resetOrigins();
  return mesh;
}

TriangleMesh makeInvertedPyramid(double side, double height) {
  TriangleMesh mesh;
  const double h = side / 2;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(-h, -h, height), Vec3(h, -h, height), Vec3(h, h, height),
                   Vec3(-h, h, height)};
  // Top face (normal +Z) and four slanted faces whose normals point down and out.
  mesh.triangles = {{1, 2, 3}, {1, 3, 4}, {0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 1, 4}};
  mesh.resetOrigins();
  return mesh;
}

TriangleMesh makeIcosphere(const Vec3& center, double radius, int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> unit = {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0),
                            Vec3(0, -1, t), Vec3(0, 1, t), Vec3(0, -1, -t), Vec3(0, 1, -t),
                            Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)};
  for (Vec3& v : unit) v.normalize();
  std::vector<Triangle> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      unit.push_back((unit[a] + unit[b]).normalized());
      return midpoint[key] = static_cast<int>(unit.size()) - 1;
    };
    std::vector<Triangle> finer;
    for (const Triangle& f : faces) {
      const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  TriangleMesh mesh;
  for (const Vec3& u : unit) mesh.vertices.push_back(center + radius * u);
  mesh.triangles = std::move(faces);
  mesh.resetOrigins();
  return mesh;
}

}  // namespace multidir::test

#include "multidir/core/geometry/polygon_triangulation.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::test {

TriangleMesh makeExtrudedProfile(const std::vector<Vec3>& profileXZ, double depth) {
  const auto n = static_cast<std::int32_t>(profileXZ.size());
  std::vector<core::Vec2> points;
  core::PolygonWithHoles polygon;
  for (std::int32_t i = 0; i < n; ++i) {
    points.emplace_back(profileXZ[i].x(), profileXZ[i].z());
    polygon.outer.push_back(i);
  }
  auto cap = core::triangulatePolygon(points, polygon);
  if (!cap.ok()) throw std::runtime_error("profile triangulation failed: " + cap.error().describe());
  TriangleMesh mesh;
  for (const Vec3& p : profileXZ) mesh.vertices.emplace_back(p.x(), 0.0, p.z());
  for (const Vec3& p : profileXZ) mesh.vertices.emplace_back(p.x(), depth, p.z());
  for (Triangle t : *cap) {
    // Front cap counter-clockwise in x-z (normal -y) whatever winding the triangulator chose.
    const core::Vec2 e1 = points[t[1]] - points[t[0]], e2 = points[t[2]] - points[t[0]];
    if (e1.x() * e2.y() - e1.y() * e2.x() < 0) std::swap(t[1], t[2]);
    mesh.triangles.push_back({t[0], t[1], t[2]});
    mesh.triangles.push_back({t[0] + n, t[2] + n, t[1] + n});
  }
  for (std::int32_t i = 0; i < n; ++i) {
    const std::int32_t j = (i + 1) % n;
    mesh.triangles.push_back({i, i + n, j + n});
    mesh.triangles.push_back({i, j + n, j});
  }
  // The winding above depends on the profile's handedness in x-z seen from -y: fix it by the volume.
  if (core::signedVolume(mesh) < 0)
    for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
  mesh.resetOrigins();
  return mesh;
}

TriangleMesh makeTBar(double stemWidth, double stemHeight, double barWidth, double barHeight, double depth) {
  const double s = stemWidth / 2, b = barWidth / 2, top = stemHeight + barHeight;
  return makeExtrudedProfile({Vec3(-s, 0, 0), Vec3(s, 0, 0), Vec3(s, 0, stemHeight), Vec3(b, 0, stemHeight),
                              Vec3(b, 0, top), Vec3(-b, 0, top), Vec3(-b, 0, stemHeight), Vec3(-s, 0, stemHeight)},
                             depth);
}

TriangleMesh makeHook(double depth) {
  return makeExtrudedProfile({Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(10, 0, 50), Vec3(50, 0, 50), Vec3(50, 0, 20),
                              Vec3(60, 0, 20), Vec3(60, 0, 60), Vec3(0, 0, 60)},
                             depth);
}

}  // namespace multidir::test

#include "support/primitives.h"

#include <cmath>
#include <map>
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

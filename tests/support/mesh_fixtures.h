#pragma once
// Small hand-made meshes for mesh I/O and check tests (header-only: tests/CMakeLists.txt compiles only
// test_models.cpp from support/).
#include "multidir/core/mesh/mesh_io.h"

namespace multidir::test {

// An axis-aligned cube [origin, origin + size]^3: 8 vertices, 12 triangles, outward, CCW.
inline core::RawSoup cubeSoup(const core::Vec3& origin = core::Vec3::Zero(), double size = 10.0) {
  core::RawSoup soup;
  for (int i = 0; i < 8; ++i) {
    const double x = (i == 1 || i == 2 || i == 5 || i == 6) ? size : 0.0;
    const double y = (i == 2 || i == 3 || i == 6 || i == 7) ? size : 0.0;
    const double z = i >= 4 ? size : 0.0;
    soup.vertices.push_back(origin + core::Vec3(x, y, z));
  }
  soup.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                    {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  return soup;
}

inline core::TriangleMesh cubeMesh(const core::Vec3& origin = core::Vec3::Zero(), double size = 10.0) {
  const core::RawSoup soup = cubeSoup(origin, size);
  core::TriangleMesh mesh;
  mesh.vertices = soup.vertices;
  mesh.triangles = soup.triangles;
  mesh.resetOrigins();
  return mesh;
}

// Appends `other` to `soup` (indices shifted).
inline void append(core::RawSoup& soup, const core::RawSoup& other) {
  const auto offset = static_cast<std::int32_t>(soup.vertices.size());
  soup.vertices.insert(soup.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (core::Triangle t : other.triangles) {
    for (std::int32_t& v : t) v += offset;
    soup.triangles.push_back(t);
  }
}

// The same triangles with three vertices of their own each, as an STL holds them.
inline core::RawSoup unshared(const core::RawSoup& soup) {
  core::RawSoup out;
  for (const core::Triangle& t : soup.triangles) {
    const auto first = static_cast<std::int32_t>(out.vertices.size());
    for (std::int32_t v : t) out.vertices.push_back(soup.vertices[static_cast<std::size_t>(v)]);
    out.triangles.push_back({first, first + 1, first + 2});
  }
  return out;
}

}  // namespace multidir::test

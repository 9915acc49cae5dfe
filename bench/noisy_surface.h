#pragma once
// Scan-like measurement noise for the scaling runs: every vertex moved along its normal by a pseudo-random
// amount in [-amplitude, amplitude], the same on every run (a hash of the vertex index, no state).
#include <cstdint>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::bench {

inline double pseudoRandom(std::size_t index) {
  std::uint64_t h = index * 0x9e3779b97f4a7c15ull;
  h ^= h >> 31;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 29;
  return static_cast<double>(h % 2000001) / 1000000.0 - 1.0;
}

inline void addNoise(core::TriangleMesh& mesh, double amplitudeMm) {
  std::vector<core::Vec3> normals(mesh.vertices.size(), core::Vec3::Zero());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (std::int32_t v : mesh.triangles[f]) normals[static_cast<std::size_t>(v)] += mesh.areaNormal(f);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    mesh.vertices[v] += amplitudeMm * pseudoRandom(v) * normals[v].normalized();
}

}  // namespace multidir::bench

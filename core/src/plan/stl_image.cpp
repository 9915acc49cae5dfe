#include "plan/stl_image.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <set>
#include <unordered_map>

namespace multidir::core::detail {
namespace {

struct FloatCorner {
  std::array<float, 3> xyz;
  bool operator==(const FloatCorner& o) const { return std::memcmp(xyz.data(), o.xyz.data(), sizeof xyz) == 0; }
};

struct FloatCornerHash {
  std::size_t operator()(const FloatCorner& c) const {
    std::array<std::uint32_t, 3> bits{};
    std::memcpy(bits.data(), c.xyz.data(), sizeof bits);
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t b : bits) h = (h ^ b) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

FloatCorner toFloat(const Vec3& p) {
  FloatCorner c{{static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())}};
  for (float& v : c.xyz)
    if (v == 0.0f) v = 0.0f;  // -0 and +0 are one corner, as the loader's weld sees them
  return c;
}

}  // namespace

std::size_t cornersMergedAtFloatPrecision(const TriangleMesh& mesh) {
  // Vertices already at the same point (a pinch split in two by the clip) are one corner either way.
  std::unordered_map<FloatCorner, Vec3, FloatCornerHash> seen;
  seen.reserve(mesh.vertices.size());
  std::size_t merged = 0;
  for (const Vec3& v : mesh.vertices) {
    const auto [it, inserted] = seen.emplace(toFloat(v), v);
    if (!inserted && it->second != v) ++merged;
  }
  return merged;
}

StlImage stlImage(const TriangleMesh& mesh) {
  StlImage image;
  std::unordered_map<FloatCorner, std::int32_t, FloatCornerHash> index;
  std::vector<std::int32_t> map(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const FloatCorner c = toFloat(mesh.vertices[v]);
    const auto [it, inserted] = index.emplace(c, static_cast<std::int32_t>(image.mesh.vertices.size()));
    if (inserted)
      image.mesh.vertices.emplace_back(c.xyz[0], c.xyz[1], c.xyz[2]);
    else
      ++image.mergedCorners;
    map[v] = it->second;
  }
  // The loader drops faces with a repeated corner, then every repeat of a face already kept.
  std::set<std::array<std::int32_t, 3>> seen;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle t = {map[static_cast<std::size_t>(mesh.triangles[f][0])],
                        map[static_cast<std::size_t>(mesh.triangles[f][1])],
                        map[static_cast<std::size_t>(mesh.triangles[f][2])]};
    std::array<std::int32_t, 3> sorted = t;
    std::sort(sorted.begin(), sorted.end());
    if (sorted[0] == sorted[1] || sorted[1] == sorted[2] || !seen.insert(sorted).second) {
      ++image.droppedFaces;
      continue;
    }
    image.mesh.triangles.push_back(t);
    image.mesh.origins.push_back(mesh.origins[f]);
  }
  return image;
}

}  // namespace multidir::core::detail

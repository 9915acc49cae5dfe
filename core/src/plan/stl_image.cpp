#include "plan/stl_image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <vector>

#include "detail/flat_index.h"
#include "detail/huge_pages.h"

namespace multidir::core::detail {
namespace {

// A vertex rounded to float, as its bits (so -0 and +0 compare after toFloat made them one).
using FloatBits = std::array<std::uint32_t, 3>;

FloatBits toFloat(const Vec3& p) {
  std::array<float, 3> xyz{static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
  for (float& v : xyz)
    if (v == 0.0f) v = 0.0f;  // -0 and +0 are one corner, as the loader's weld sees them
  FloatBits bits{};
  std::memcpy(bits.data(), xyz.data(), sizeof bits);
  return bits;
}

// For every vertex of `subset` (indices into mesh.vertices, ascending), the first of the subset with the same
// float corner, by position in `subset`, through a flat hash in subset order (sorting the corners cost three
// times as much at half a million vertices).
std::vector<std::int32_t> firstWithSameFloatCorner(const TriangleMesh& mesh, const std::vector<std::int32_t>& subset) {
  std::vector<FloatBits> corners;
  reserveInHugePages(corners, subset.size());
  for (const std::int32_t v : subset) corners.push_back(toFloat(mesh.vertices[static_cast<std::size_t>(v)]));
  FlatIndex index(corners.size());
  std::vector<std::int32_t> first(subset.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const FloatBits& bits = corners[i];
    const std::uint64_t hash =
        (static_cast<std::uint64_t>(bits[0]) * 0x9e3779b97f4a7c15ull) ^
        (static_cast<std::uint64_t>(bits[1]) * 0xc2b2ae3d27d4eb4full) ^ (static_cast<std::uint64_t>(bits[2]) << 17);
    std::int32_t& slot =
        index.find(hash, [&](std::int32_t w) { return corners[static_cast<std::size_t>(w)] == bits; });
    if (slot < 0) slot = static_cast<std::int32_t>(i);
    first[i] = slot;
  }
  return first;
}

std::vector<std::int32_t> allVertices(const TriangleMesh& mesh) {
  std::vector<std::int32_t> all(mesh.vertices.size());
  for (std::size_t v = 0; v < all.size(); ++v) all[v] = static_cast<std::int32_t>(v);
  return all;
}

// Vertices of `subset` that fall onto another one of it at a different position when rounded to float.
std::size_t mergedAmong(const TriangleMesh& mesh, const std::vector<std::int32_t>& subset) {
  // Vertices already at the same point (a pinch split in two by the clip) are one corner either way.
  const std::vector<std::int32_t> first = firstWithSameFloatCorner(mesh, subset);
  std::size_t merged = 0;
  for (std::size_t i = 0; i < subset.size(); ++i)
    if (mesh.vertices[static_cast<std::size_t>(subset[i])] !=
        mesh.vertices[static_cast<std::size_t>(subset[static_cast<std::size_t>(first[i])])])
      ++merged;
  return merged;
}

}  // namespace

std::size_t cornersMergedAtFloatPrecision(const TriangleMesh& mesh) { return mergedAmong(mesh, allVertices(mesh)); }

std::size_t cornersMergedAtFloatPrecisionNearPlane(const TriangleMesh& mesh, const Plane& plane,
                                                   double planeToleranceMm) {
  // Rounding a double to float moves each coordinate by at most |x| 2^-24, so two points with one float image
  // are at most 2 sqrt(3) M 2^-24 apart (M: the largest coordinate). Every vertex the clip made or moved lies
  // on the plane (to rounding), so any pair with one of them has both within this band (with a margin of 2);
  // pairs of two unchanged vertices cannot merge, by the precondition.
  double largest = 0.0;
  for (const Vec3& v : mesh.vertices) largest = std::max(largest, v.cwiseAbs().maxCoeff());
  const double band = planeToleranceMm + 4.0 * std::sqrt(3.0) * std::ldexp(largest, -24);
  std::vector<std::int32_t> near;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (std::abs(plane.normal.dot(mesh.vertices[v]) - plane.offset) <= band) near.push_back(static_cast<std::int32_t>(v));
  return mergedAmong(mesh, near);
}

StlImage stlImage(const TriangleMesh& mesh) {
  StlImage image;
  const std::vector<std::int32_t> first = firstWithSameFloatCorner(mesh, allVertices(mesh));
  // The image has at most the mesh's vertices and faces: room for them once, in huge pages, instead of a
  // doubling series of fresh buffers (docs/architecture.md, "Million-triangle models").
  reserveInHugePages(image.mesh.vertices, mesh.vertices.size());
  reserveInHugePages(image.mesh.triangles, mesh.triangles.size());
  reserveInHugePages(image.mesh.origins, mesh.triangles.size());
  std::vector<std::int32_t> map(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const auto representative = static_cast<std::size_t>(first[v]);
    if (representative == v) {
      map[v] = static_cast<std::int32_t>(image.mesh.vertices.size());
      const FloatBits bits = toFloat(mesh.vertices[v]);
      std::array<float, 3> xyz{};
      std::memcpy(xyz.data(), bits.data(), sizeof xyz);
      image.mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else {
      map[v] = map[representative];  // a lower index, so already numbered
      ++image.mergedCorners;
    }
  }
  // The loader drops faces with a repeated corner, then every repeat of a face already kept.
  std::vector<std::pair<std::array<std::int32_t, 3>, std::uint32_t>> byCorners;
  reserveInHugePages(byCorners, mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    std::array<std::int32_t, 3> sorted{};
    for (int k = 0; k < 3; ++k) sorted[k] = map[static_cast<std::size_t>(mesh.triangles[f][k])];
    std::sort(sorted.begin(), sorted.end());
    byCorners.emplace_back(sorted, static_cast<std::uint32_t>(f));
  }
  std::sort(byCorners.begin(), byCorners.end());
  std::vector<char> repeats(mesh.triangles.size(), 0);
  for (std::size_t i = 1; i < byCorners.size(); ++i)
    if (byCorners[i].first == byCorners[i - 1].first) repeats[byCorners[i].second] = 1;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle t = {map[static_cast<std::size_t>(mesh.triangles[f][0])],
                        map[static_cast<std::size_t>(mesh.triangles[f][1])],
                        map[static_cast<std::size_t>(mesh.triangles[f][2])]};
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || repeats[f]) {
      ++image.droppedFaces;
      continue;
    }
    image.mesh.triangles.push_back(t);
    image.mesh.origins.push_back(mesh.origins[f]);
  }
  return image;
}

}  // namespace multidir::core::detail

#pragma once
// A uniform grid over the triangles of one or more closed, outward-oriented shells (overlapping shells are
// fine: support struts overlap each other and the region): how far a point is from the surface, and whether
// it lies inside any shell. Single-threaded: queries reuse a visit stamp per triangle.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::slicing::audit {

class TriangleGrid {
 public:
  // `meshes` are copied; `cellMm` > 0 (a few triangles per cell is right; the caller picks it from the size).
  TriangleGrid(const std::vector<const core::TriangleMesh*>& meshes, double cellMm);

  bool empty() const { return m_corners.empty(); }
  // The distance from p to the nearest triangle when it is at most `radiusMm`, else +infinity.
  double distanceWithin(const core::Vec3& p, double radiusMm) const;
  // The winding number of the shells about p (>= 1 inside some shell, 0 outside), counted along a ray
  // towards +z; a ray through an edge or corner is moved by a few nanometres and cast again.
  int winding(const core::Vec3& p) const;

 private:
  using Key = std::int64_t;
  Key key(int i, int j, int k) const;
  void cellOf(const core::Vec3& p, int& i, int& j, int& k) const;
  // +1 or -1 when the upward ray from p crosses triangle t above p, 0 when it misses; false when the ray
  // passes too close to an edge to say.
  bool crossing(std::size_t t, const core::Vec3& p, int& sign) const;

  double m_cell;
  core::Vec3 m_origin;
  int m_topK = 0;  // the highest cell layer that holds a triangle
  std::vector<std::array<core::Vec3, 3>> m_corners;
  std::unordered_map<Key, std::vector<std::uint32_t>> m_cells;
  mutable std::vector<std::uint32_t> m_stamp;
  mutable std::uint32_t m_query = 0;
};

}  // namespace multidir::slicing::audit

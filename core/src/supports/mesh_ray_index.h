#pragma once
// Segment queries against a triangle mesh through a uniform grid of its faces: where a segment first
// meets the surface. Supports use it to keep struts out of the model.
#include <optional>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

class MeshRayIndex {
 public:
  // Keeps a reference to `mesh`, which must outlive the index. About 2 faces per cell, at most 128 cells a side.
  explicit MeshRayIndex(const TriangleMesh& mesh);

  // The smallest t in [0, 1] where the segment from `from` to `to` meets a face, if any. Not thread-safe
  // (a per-query stamp avoids testing a face twice).
  std::optional<double> firstHit(const Vec3& from, const Vec3& to) const;

 private:
  bool cellRange(const Vec3& p, Eigen::Vector3i& cell) const;
  const TriangleMesh& m_mesh;
  Vec3 m_origin = Vec3::Zero();
  Vec3 m_cellSize = Vec3::Ones();
  Eigen::Vector3i m_dims = Eigen::Vector3i::Ones();
  std::vector<std::int32_t> m_cellStart;  // CSR: faces of cell c are m_faces[m_cellStart[c] .. m_cellStart[c+1])
  std::vector<std::int32_t> m_faces;
  mutable std::vector<std::uint32_t> m_stamp;
  mutable std::uint32_t m_query = 0;
};

}  // namespace multidir::core::detail

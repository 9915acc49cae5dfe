#include "supports/mesh_ray_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "multidir/core/geometry/line_triangle.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core::detail {
namespace {

// The segment parameter t in [0, 1] where origin + t * delta crosses triangle abc.
std::optional<double> segmentTriangle(const Vec3& origin, const Vec3& delta, const Vec3& a, const Vec3& b,
                                      const Vec3& c) {
  const std::optional<double> t = lineTriangleParameter(origin, delta, a, b, c);
  if (!t || *t < 0.0 || *t > 1.0) return std::nullopt;
  return t;
}

}  // namespace

MeshRayIndex::MeshRayIndex(const TriangleMesh& mesh) : m_mesh(mesh) {
  const BoundingBox box = boundingBox(mesh);
  const Vec3 size = box.size().cwiseMax(1e-6);
  // Cells about as many as faces / 2, cubes as far as the box allows.
  const double cells = std::max(1.0, static_cast<double>(mesh.triangles.size()) / 2.0);
  const double edge = std::cbrt(size.prod() / cells);
  for (int k = 0; k < 3; ++k) m_dims[k] = std::clamp(static_cast<int>(std::ceil(size[k] / edge)), 1, 128);
  m_origin = box.min - Vec3::Constant(1e-6);
  m_cellSize = (size + Vec3::Constant(2e-6)).cwiseQuotient(m_dims.cast<double>());

  const std::size_t cellCount = static_cast<std::size_t>(m_dims.prod());
  std::vector<std::int32_t> counts(cellCount + 1, 0);
  auto forCells = [&](std::size_t f, auto&& visit) {
    Vec3 lo = mesh.corner(f, 0), hi = lo;
    for (int k = 1; k < 3; ++k) {
      lo = lo.cwiseMin(mesh.corner(f, k));
      hi = hi.cwiseMax(mesh.corner(f, k));
    }
    Eigen::Vector3i a, b;
    cellRange(lo, a);
    cellRange(hi, b);
    for (int x = a.x(); x <= b.x(); ++x)
      for (int y = a.y(); y <= b.y(); ++y)
        for (int z = a.z(); z <= b.z(); ++z) visit(static_cast<std::size_t>((z * m_dims.y() + y) * m_dims.x() + x));
  };
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) forCells(f, [&](std::size_t c) { ++counts[c + 1]; });
  for (std::size_t c = 0; c < cellCount; ++c) counts[c + 1] += counts[c];
  m_cellStart = counts;
  m_faces.resize(static_cast<std::size_t>(counts[cellCount]));
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    forCells(f, [&](std::size_t c) { m_faces[static_cast<std::size_t>(counts[c]++)] = static_cast<std::int32_t>(f); });
  m_stamp.assign(mesh.triangles.size(), 0);
}

bool MeshRayIndex::cellRange(const Vec3& p, Eigen::Vector3i& cell) const {
  bool inside = true;
  for (int k = 0; k < 3; ++k) {
    const double c = std::floor((p[k] - m_origin[k]) / m_cellSize[k]);
    if (c < 0 || c >= m_dims[k]) inside = false;
    cell[k] = static_cast<int>(std::clamp(c, 0.0, static_cast<double>(m_dims[k] - 1)));
  }
  return inside;
}

std::optional<double> MeshRayIndex::firstHit(const Vec3& from, const Vec3& to) const {
  if (m_mesh.triangles.empty()) return std::nullopt;
  if (++m_query == 0) {
    std::fill(m_stamp.begin(), m_stamp.end(), 0);
    m_query = 1;
  }
  const Vec3 delta = to - from;
  // Clip the segment to the grid's box; outside it there are no faces.
  double t0 = 0.0, t1 = 1.0;
  const Vec3 boxMax = m_origin + m_cellSize.cwiseProduct(m_dims.cast<double>());
  for (int k = 0; k < 3; ++k) {
    if (std::abs(delta[k]) < 1e-300) {
      if (from[k] < m_origin[k] || from[k] > boxMax[k]) return std::nullopt;
      continue;
    }
    double a = (m_origin[k] - from[k]) / delta[k], b = (boxMax[k] - from[k]) / delta[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  if (t0 > t1) return std::nullopt;

  // Walk the cells the segment passes (Amanatides and Woo), stopping once a hit lies before the next cell.
  Eigen::Vector3i cell;
  cellRange(from + t0 * delta, cell);
  Eigen::Vector3i step;
  Vec3 tMax, tDelta;
  for (int k = 0; k < 3; ++k) {
    if (delta[k] > 0) {
      step[k] = 1;
      tMax[k] = (m_origin[k] + (cell[k] + 1) * m_cellSize[k] - from[k]) / delta[k];
      tDelta[k] = m_cellSize[k] / delta[k];
    } else if (delta[k] < 0) {
      step[k] = -1;
      tMax[k] = (m_origin[k] + cell[k] * m_cellSize[k] - from[k]) / delta[k];
      tDelta[k] = -m_cellSize[k] / delta[k];
    } else {
      step[k] = 0;
      tMax[k] = std::numeric_limits<double>::infinity();
      tDelta[k] = std::numeric_limits<double>::infinity();
    }
  }
  std::optional<double> best;
  for (int guard = 0; guard < 3 * 128 + 3; ++guard) {
    const std::size_t c = static_cast<std::size_t>((cell.z() * m_dims.y() + cell.y()) * m_dims.x() + cell.x());
    for (std::int32_t i = m_cellStart[c]; i < m_cellStart[c + 1]; ++i) {
      const std::int32_t f = m_faces[static_cast<std::size_t>(i)];
      if (m_stamp[static_cast<std::size_t>(f)] == m_query) continue;
      m_stamp[static_cast<std::size_t>(f)] = m_query;
      const auto t =
          segmentTriangle(from, delta, m_mesh.corner(static_cast<std::size_t>(f), 0),
                          m_mesh.corner(static_cast<std::size_t>(f), 1), m_mesh.corner(static_cast<std::size_t>(f), 2));
      if (t && (!best || *t < *best)) best = t;
    }
    int axis = 0;
    if (tMax[1] < tMax[axis]) axis = 1;
    if (tMax[2] < tMax[axis]) axis = 2;
    if (best && *best <= tMax[axis]) break;
    if (tMax[axis] > t1) break;
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= m_dims[axis]) break;
    tMax[axis] += tDelta[axis];
  }
  return best;
}

}  // namespace multidir::core::detail

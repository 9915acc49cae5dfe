#include "triangle_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace multidir::slicing::audit {

namespace {

using core::Vec3;

// The point of triangle abc nearest to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

TriangleGrid::TriangleGrid(const std::vector<const core::TriangleMesh*>& meshes, double cellMm) : m_cell(cellMm) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  for (const core::TriangleMesh* mesh : meshes)
    for (std::size_t f = 0; f < mesh->faceCount(); ++f) {
      m_corners.push_back({mesh->corner(f, 0), mesh->corner(f, 1), mesh->corner(f, 2)});
      for (int k = 0; k < 3; ++k) lo = lo.cwiseMin(mesh->corner(f, k));
    }
  m_origin = m_corners.empty() ? Vec3::Zero() : lo;
  m_topK = 0;
  const double halfDiagonal = 0.5 * std::sqrt(3.0) * m_cell;
  for (std::size_t t = 0; t < m_corners.size(); ++t) {
    const auto& c = m_corners[t];
    const Vec3 tlo = c[0].cwiseMin(c[1]).cwiseMin(c[2]);
    const Vec3 thi = c[0].cwiseMax(c[1]).cwiseMax(c[2]);
    Vec3 normal = (c[1] - c[0]).cross(c[2] - c[0]);
    const double length = normal.norm();
    if (length > 0.0) normal /= length;
    int i0, j0, k0, i1, j1, k1;
    cellOf(tlo, i0, j0, k0);
    cellOf(thi, i1, j1, k1);
    m_topK = std::max(m_topK, k1);
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j)
        for (int k = k0; k <= k1; ++k) {
          // Only the cells the triangle's plane passes through (a large tilted cap spans many cells of its
          // bounding box but crosses few).
          const Vec3 centre = m_origin + m_cell * Vec3(i + 0.5, j + 0.5, k + 0.5);
          if (length > 0.0 && std::abs(normal.dot(centre - c[0])) > halfDiagonal) continue;
          m_cells[key(i, j, k)].push_back(static_cast<std::uint32_t>(t));
        }
  }
  m_stamp.assign(m_corners.size(), 0);
}

TriangleGrid::Key TriangleGrid::key(int i, int j, int k) const {
  return (static_cast<Key>(i) & 0x1FFFFF) | ((static_cast<Key>(j) & 0x1FFFFF) << 21) |
         ((static_cast<Key>(k) & 0x1FFFFF) << 42);
}

void TriangleGrid::cellOf(const Vec3& p, int& i, int& j, int& k) const {
  const Vec3 q = (p - m_origin) / m_cell;
  i = static_cast<int>(std::floor(q.x()));
  j = static_cast<int>(std::floor(q.y()));
  k = static_cast<int>(std::floor(q.z()));
}

double TriangleGrid::distanceWithin(const Vec3& p, double radiusMm) const {
  double best = std::numeric_limits<double>::infinity();
  if (m_corners.empty()) return best;
  ++m_query;
  int i0, j0, k0, i1, j1, k1;
  cellOf(p - Vec3::Constant(radiusMm), i0, j0, k0);
  cellOf(p + Vec3::Constant(radiusMm), i1, j1, k1);
  for (int i = i0; i <= i1; ++i)
    for (int j = j0; j <= j1; ++j)
      for (int k = k0; k <= k1; ++k) {
        const auto found = m_cells.find(key(i, j, k));
        if (found == m_cells.end()) continue;
        for (const std::uint32_t t : found->second) {
          if (m_stamp[t] == m_query) continue;
          m_stamp[t] = m_query;
          const auto& c = m_corners[t];
          const double d = (closestOnTriangle(p, c[0], c[1], c[2]) - p).norm();
          if (d <= radiusMm) best = std::min(best, d);
        }
      }
  return best;
}

bool TriangleGrid::crossing(std::size_t t, const Vec3& p, int& sign) const {
  sign = 0;
  const auto& c = m_corners[t];
  // 2D edge functions of the triangle projected along z, about p.
  const auto edge = [&p](const Vec3& a, const Vec3& b) {
    return (a.x() - p.x()) * (b.y() - p.y()) - (a.y() - p.y()) * (b.x() - p.x());
  };
  const double e0 = edge(c[0], c[1]), e1 = edge(c[1], c[2]), e2 = edge(c[2], c[0]);
  const double scale = 1e-12 * (1.0 + std::abs(e0) + std::abs(e1) + std::abs(e2));
  const bool allPositive = e0 > 0.0 && e1 > 0.0 && e2 > 0.0;
  const bool allNegative = e0 < 0.0 && e1 < 0.0 && e2 < 0.0;
  if (!allPositive && !allNegative) {
    // Outside in 2D, unless on an edge: then the caller casts again from a moved point.
    const bool nearEdge = (std::abs(e0) <= scale && e1 * e2 >= 0.0) || (std::abs(e1) <= scale && e0 * e2 >= 0.0) ||
                          (std::abs(e2) <= scale && e0 * e1 >= 0.0);
    return !nearEdge;
  }
  const double total = e0 + e1 + e2;
  // The crossing's height: barycentric weights of the corners opposite each edge.
  const double z = (e1 * c[0].z() + e2 * c[1].z() + e0 * c[2].z()) / total;
  if (z <= p.z()) return true;
  // Counter-clockwise seen from above (an outward normal with +z): the ray leaves the solid there.
  sign = allPositive ? 1 : -1;
  return true;
}

int TriangleGrid::winding(const Vec3& p) const {
  if (m_corners.empty()) return 0;
  for (int attempt = 0; attempt < 4; ++attempt) {
    const Vec3 q = p + Vec3(3.1e-9, 1.7e-9, 0.0) * attempt;
    ++m_query;
    int i, j, k;
    cellOf(q, i, j, k);
    int sum = 0;
    bool clean = true;
    for (int layer = std::max(k, 0); layer <= m_topK && clean; ++layer) {
      const auto found = m_cells.find(key(i, j, layer));
      if (found == m_cells.end()) continue;
      for (const std::uint32_t t : found->second) {
        if (m_stamp[t] == m_query) continue;
        m_stamp[t] = m_query;
        int sign = 0;
        if (!crossing(t, q, sign)) {
          clean = false;
          break;
        }
        sum += sign;
      }
    }
    if (clean) return sum;
  }
  return 0;
}

}  // namespace multidir::slicing::audit

#include "multidir/core/search/plane_sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "search/grid_polynomial_sum.h"

namespace multidir::core {

using detail::GridPolynomialSum;

PlaneSweeper::PlaneSweeper(const TriangleMesh& solid, const std::vector<double>& riskyShare, double sinAlphaMax)
    : m_solid(solid),
      m_area(solid.triangles.size(), 0.0),
      m_unitNormal(solid.triangles.size(), Vec3::Zero()),
      m_riskyArea(solid.triangles.size(), 0.0),
      m_sinAlpha(sinAlphaMax) {
  for (std::size_t f = 0; f < solid.triangles.size(); ++f) {
    const Vec3 areaNormal = solid.areaNormal(f);
    const double doubleArea = areaNormal.norm();
    if (!(doubleArea > 0.0)) continue;
    m_area[f] = 0.5 * doubleArea;
    m_unitNormal[f] = areaNormal / doubleArea;
    if (f < riskyShare.size()) m_riskyArea[f] = riskyShare[f] * m_area[f];
  }
}

struct PlaneSweeper::Sums {
  explicit Sums(const OffsetGrid& grid) : volume(grid), riskyAlongNormal(grid), riskyFlagged(grid) {}
  GridPolynomialSum volume, riskyAlongNormal, riskyFlagged;
  SweepProfile profile(double top) const {
    SweepProfile out;
    out.volumeAboveMm3 = volume.values();
    out.riskyAreaAlongNormalMm2 = riskyAlongNormal.values();
    out.riskyAreaFlaggedMm2 = riskyFlagged.values();
    out.topMm = top;
    return out;
  }
};

// Face f's pieces, from its corner heights along the normal and their grid indices (in any order).
void PlaneSweeper::addFace(Sums& sums, const Vec3& unitNormal, std::size_t f, double ha, double hb, double hc, int ja,
                           int jb, int jc) const {
  const double area = m_area[f];
  if (area == 0.0) return;
  if (ha > hb) std::swap(ha, hb), std::swap(ja, jb);
  if (hb > hc) std::swap(hb, hc), std::swap(jb, jc);
  if (ha > hb) std::swap(ha, hb), std::swap(ja, jb);
  const double lower = hb - ha, span = hc - ha, upper = hc - hb;
  const double cosine = unitNormal.dot(m_unitNormal[f]);  // n . n_f

  // Area `part` of the face above the plane at offset t, summed into `sum`.
  auto addArea = [&](GridPolynomialSum& sum, double part) {
    sum.addConstantBelow(ja, part);
    if (lower > 0) sum.addPiece(ja, jb, ha, {part, 0, -part / (lower * span), 0});
    if (upper > 0) sum.addPiece(jb, jc, hc, {0, 0, part / (span * upper), 0});
  };
  if (cosine + m_sinAlpha < 0.0) addArea(sums.riskyAlongNormal, area);
  if (m_riskyArea[f] > 0.0) addArea(sums.riskyFlagged, m_riskyArea[f]);

  // cosine * integral over the face's part above t of (h - t) dA: its share of the volume above.
  const double w = cosine * area;
  const double mean = (ha + hb + hc) / 3.0;
  sums.volume.addPiece(0, ja, ha, {w * (mean - ha), -w, 0, 0});
  if (lower > 0) sums.volume.addPiece(ja, jb, ha, {w * (mean - ha), -w, 0, w / (3.0 * lower * span)});
  if (upper > 0) sums.volume.addPiece(jb, jc, hc, {0, 0, 0, -w / (3.0 * span * upper)});
}

SweepProfile PlaneSweeper::sweep(const Vec3& unitNormal, const OffsetGrid& grid) const {
  Sums sums(grid);
  // Each vertex's height and grid index once per normal: a vertex is shared by about six faces.
  std::vector<double> height(m_solid.vertices.size());
  std::vector<int> index(m_solid.vertices.size());
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < height.size(); ++v) {
    height[v] = unitNormal.dot(m_solid.vertices[v]);
    index[v] = sums.volume.indexAtOrAbove(height[v]);
    top = std::max(top, height[v]);
  }
  for (std::size_t f = 0; f < m_solid.triangles.size(); ++f) {
    const Triangle& t = m_solid.triangles[f];
    addFace(sums, unitNormal, f, height[t[0]], height[t[1]], height[t[2]], index[t[0]], index[t[1]], index[t[2]]);
  }
  return sums.profile(top);
}

SweepProfile PlaneSweeper::sweepFaces(const Vec3& unitNormal, const OffsetGrid& grid,
                                      const std::vector<std::int32_t>& faces) const {
  Sums sums(grid);
  for (const std::int32_t f : faces) {
    const Triangle& t = m_solid.triangles[f];
    const double ha = unitNormal.dot(m_solid.vertices[t[0]]);
    const double hb = unitNormal.dot(m_solid.vertices[t[1]]);
    const double hc = unitNormal.dot(m_solid.vertices[t[2]]);
    addFace(sums, unitNormal, static_cast<std::size_t>(f), ha, hb, hc, sums.volume.indexAtOrAbove(ha),
            sums.volume.indexAtOrAbove(hb), sums.volume.indexAtOrAbove(hc));
  }
  return sums.profile(0.0);
}

SweepProfile sweepPlanes(const TriangleMesh& solid, const Vec3& unitNormal, const OffsetGrid& grid,
                         const std::vector<double>& riskyShare, double sinAlphaMax) {
  return PlaneSweeper(solid, riskyShare, sinAlphaMax).sweep(unitNormal, grid);
}

}  // namespace multidir::core

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

SweepProfile PlaneSweeper::sweep(const Vec3& unitNormal, const OffsetGrid& grid) const {
  GridPolynomialSum volume(grid), riskyAlongNormal(grid), riskyFlagged(grid);

  // Each vertex's height and grid index once per normal: a vertex is shared by about six faces.
  std::vector<double> height(m_solid.vertices.size());
  std::vector<int> index(m_solid.vertices.size());
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < height.size(); ++v) {
    height[v] = unitNormal.dot(m_solid.vertices[v]);
    index[v] = volume.indexAtOrAbove(height[v]);
    top = std::max(top, height[v]);
  }

  for (std::size_t f = 0; f < m_solid.triangles.size(); ++f) {
    const double area = m_area[f];
    if (area == 0.0) continue;
    const Triangle& t = m_solid.triangles[f];
    double ha = height[t[0]], hb = height[t[1]], hc = height[t[2]];
    int ja = index[t[0]], jb = index[t[1]], jc = index[t[2]];
    if (ha > hb) std::swap(ha, hb), std::swap(ja, jb);
    if (hb > hc) std::swap(hb, hc), std::swap(jb, jc);
    if (ha > hb) std::swap(ha, hb), std::swap(ja, jb);
    const double lower = hb - ha, span = hc - ha, upper = hc - hb;
    const double cosine = unitNormal.dot(m_unitNormal[f]);  // n . n_f

    // Area `part` of the face above the plane at offset t, summed into `sum` whose grid indices of the
    // corner heights are ja, jb, jc.
    auto addArea = [&](GridPolynomialSum& sum, double part, int ja, int jb, int jc) {
      sum.addConstantBelow(ja, part);
      if (lower > 0) sum.addPiece(ja, jb, ha, {part, 0, -part / (lower * span), 0});
      if (upper > 0) sum.addPiece(jb, jc, hc, {0, 0, part / (span * upper), 0});
    };
    if (cosine + m_sinAlpha < 0.0) addArea(riskyAlongNormal, area, ja, jb, jc);
    if (m_riskyArea[f] > 0.0) addArea(riskyFlagged, m_riskyArea[f], ja, jb, jc);

    // cosine * integral over the face's part above t of (h - t) dA: its share of the volume above.
    const double w = cosine * area;
    const double mean = (ha + hb + hc) / 3.0;
    volume.addPiece(0, ja, ha, {w * (mean - ha), -w, 0, 0});
    if (lower > 0) volume.addPiece(ja, jb, ha, {w * (mean - ha), -w, 0, w / (3.0 * lower * span)});
    if (upper > 0) volume.addPiece(jb, jc, hc, {0, 0, 0, -w / (3.0 * span * upper)});
  }

  SweepProfile profile;
  profile.volumeAboveMm3 = volume.values();
  profile.riskyAreaAlongNormalMm2 = riskyAlongNormal.values();
  profile.riskyAreaFlaggedMm2 = riskyFlagged.values();
  profile.topMm = top;
  return profile;
}

SweepProfile sweepPlanes(const TriangleMesh& solid, const Vec3& unitNormal, const OffsetGrid& grid,
                         const std::vector<double>& riskyShare, double sinAlphaMax) {
  return PlaneSweeper(solid, riskyShare, sinAlphaMax).sweep(unitNormal, grid);
}

}  // namespace multidir::core

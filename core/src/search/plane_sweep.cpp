#include "multidir/core/search/plane_sweep.h"

#include <algorithm>
#include <cmath>

#include "search/grid_polynomial_sum.h"

namespace multidir::core {

using detail::GridPolynomialSum;

SweepProfile sweepPlanes(const TriangleMesh& solid, const Vec3& unitNormal, const OffsetGrid& grid,
                         const std::vector<double>& riskyShare, double sinAlphaMax, double supportedBandMm) {
  // R(M+, plane at t) counts what lies above t + band: the same sums on a grid shifted by the band.
  OffsetGrid shifted = grid;
  shifted.firstMm += supportedBandMm;
  GridPolynomialSum volume(grid), riskyAlongNormal(shifted), riskyFlagged(grid);
  constexpr double kInf = INFINITY;

  for (std::size_t f = 0; f < solid.triangles.size(); ++f) {
    const Vec3 areaNormal = solid.areaNormal(f);
    const double doubleArea = areaNormal.norm();
    if (doubleArea <= 0.0) continue;
    const double area = 0.5 * doubleArea;
    const double cosine = unitNormal.dot(areaNormal) / doubleArea;  // n . n_f
    const bool alongNormal = cosine + sinAlphaMax < 0.0;
    const double share = f < riskyShare.size() ? riskyShare[f] : 0.0;

    std::array<double, 3> h = {unitNormal.dot(solid.corner(f, 0)), unitNormal.dot(solid.corner(f, 1)),
                               unitNormal.dot(solid.corner(f, 2))};
    std::sort(h.begin(), h.end());
    const double ha = h[0], hb = h[1], hc = h[2];
    const double lower = hb - ha, span = hc - ha, upper = hc - hb;
    const double mean = (ha + hb + hc) / 3.0;

    // `part` of the face's area above the plane at offset t.
    auto addArea = [&](GridPolynomialSum& sum, double part) {
      sum.addPiece(-kInf, ha, ha, {part, 0, 0, 0});
      if (lower > 0) sum.addPiece(ha, hb, ha, {part, 0, -part / (lower * span), 0});
      if (upper > 0) sum.addPiece(hb, hc, hc, {0, 0, part / (span * upper), 0});
    };
    if (alongNormal) addArea(riskyAlongNormal, area);
    if (share > 0) addArea(riskyFlagged, share * area);

    // cosine * integral over the face's part above t of (h - t) dA: its share of the volume above.
    const double w = cosine * area;
    volume.addPiece(-kInf, ha, ha, {w * (mean - ha), -w, 0, 0});
    if (lower > 0) volume.addPiece(ha, hb, ha, {w * (mean - ha), -w, 0, w / (3.0 * lower * span)});
    if (upper > 0) volume.addPiece(hb, hc, hc, {0, 0, 0, -w / (3.0 * span * upper)});
  }

  SweepProfile profile;
  profile.volumeAboveMm3 = volume.values();
  profile.riskyAreaAlongNormalMm2 = riskyAlongNormal.values();
  profile.riskyAreaFlaggedMm2 = riskyFlagged.values();
  return profile;
}

}  // namespace multidir::core

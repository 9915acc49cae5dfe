#include "multidir/core/search/plane_sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "search/grid_polynomial_sum.h"

namespace multidir::core {

using detail::GridPolynomialSum;

namespace {

// std::min and std::max of doubles, by value: through their references GCC compiled the corners' sort into
// branches and stack loads (a quarter of the sweep's time, the branches mispredicted half the time); these
// become minsd and maxsd. The same results: (b < a ? b : a) is std::min's definition, (a < b ? b : a) std::max's.
inline double lesser(double a, double b) { return b < a ? b : a; }
inline double greater(double a, double b) { return a < b ? b : a; }

}  // namespace

PlaneSweeper::PlaneSweeper(const TriangleMesh& solid, const std::vector<double>& riskyShare, double sinAlphaMax)
    : m_solid(solid), m_faces(solid.triangles.size()), m_sinAlpha(sinAlphaMax) {
  for (std::size_t f = 0; f < solid.triangles.size(); ++f) {
    const Vec3 areaNormal = solid.areaNormal(f);
    const double doubleArea = areaNormal.norm();
    if (!(doubleArea > 0.0)) continue;
    FaceData& face = m_faces[f];
    face.area = 0.5 * doubleArea;
    face.unitNormal = areaNormal / doubleArea;
    if (f < riskyShare.size()) face.riskyArea = riskyShare[f] * face.area;
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
void PlaneSweeper::addFace(Sums& sums, const Vec3& unitNormal, std::size_t f, double h0, double h1, double h2, int j0,
                           int j1, int j2) const {
  const FaceData& face = m_faces[f];
  if (face.area == 0.0) return;
  // Sorted without branches (which corner is lowest is a coin toss per face): grid indices grow with the
  // height, so the indices sort the same way.
  const double ha = lesser(lesser(h0, h1), h2), hc = greater(greater(h0, h1), h2);
  const double hb = greater(lesser(h0, h1), lesser(greater(h0, h1), h2));
  const int ja = std::min(std::min(j0, j1), j2), jc = std::max(std::max(j0, j1), j2);
  const int jb = j0 + j1 + j2 - ja - jc;
  const double lower = hb - ha, span = hc - ha, upper = hc - hb;
  const double cosine = unitNormal.dot(face.unitNormal);  // n . n_f

  // Area `part` of the face above the plane at offset t, summed into `sum`.
  auto addArea = [&](GridPolynomialSum& sum, double part) {
    sum.addConstantBelow(ja, part);
    if (lower > 0) sum.addPiece(ja, jb, ha, {part, 0, -part / (lower * span), 0});
    if (upper > 0) sum.addPiece(jb, jc, hc, {0, 0, part / (span * upper), 0});
  };
  if (cosine + m_sinAlpha < 0.0) addArea(sums.riskyAlongNormal, face.area);
  if (face.riskyArea > 0.0) addArea(sums.riskyFlagged, face.riskyArea);

  // cosine * integral over the face's part above t of (h - t) dA: its share of the volume above. Below the
  // middle corner that is w (mean - t), plus a cubic term from the lowest corner up.
  const double w = cosine * face.area;
  const double mean = (ha + hb + hc) / 3.0;
  sums.volume.addLinearBelow(jb, w * mean, -w);
  if (lower > 0) sums.volume.addPiece(ja, jb, ha, {0, 0, 0, w / (3.0 * lower * span)});
  if (upper > 0) sums.volume.addPiece(jb, jc, hc, {0, 0, 0, -w / (3.0 * span * upper)});
}

std::vector<double> PlaneSweeper::levels(const Vec3& unitNormal) const {
  std::vector<double> height(m_solid.vertices.size());
  for (std::size_t v = 0; v < height.size(); ++v) height[v] = unitNormal.dot(m_solid.vertices[v]);
  return height;
}

SweepProfile PlaneSweeper::sweep(const Vec3& unitNormal, const OffsetGrid& grid) const {
  return sweep(unitNormal, grid, levels(unitNormal));
}

SweepProfile PlaneSweeper::sweep(const Vec3& unitNormal, const OffsetGrid& grid,
                                 const std::vector<double>& height) const {
  Sums sums(grid);
  // Each vertex's grid index once per normal: a vertex is shared by about six faces.
  std::vector<int> index(height.size());
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < height.size(); ++v) {
    index[v] = sums.volume.indexAtOrAbove(height[v]);
    top = std::max(top, height[v]);
  }
  for (std::size_t f = 0; f < m_solid.triangles.size(); ++f) {
    const Triangle& t = m_solid.triangles[f];
    addFace(sums, unitNormal, f, height[t[0]], height[t[1]], height[t[2]], index[t[0]], index[t[1]], index[t[2]]);
  }
  return sums.profile(top);
}

PlaneSweeper::FaceSet PlaneSweeper::faceSet(const std::vector<std::int32_t>& faces) const {
  FaceSet set;
  set.faces = faces;
  set.corners.reserve(faces.size());
  std::vector<std::int32_t> position(m_solid.vertices.size(), -1);
  for (const std::int32_t f : faces) {
    std::array<std::int32_t, 3> corners{};
    for (int c = 0; c < 3; ++c) {
      const std::int32_t v = m_solid.triangles[f][c];
      if (position[v] < 0) {
        position[v] = static_cast<std::int32_t>(set.vertices.size());
        set.vertices.push_back(v);
      }
      corners[c] = position[v];
    }
    set.corners.push_back(corners);
  }
  return set;
}

SweepProfile PlaneSweeper::sweepFaces(const Vec3& unitNormal, const OffsetGrid& grid, const FaceSet& faces) const {
  Sums sums(grid);
  std::vector<double> height(faces.vertices.size());
  std::vector<int> index(faces.vertices.size());
  for (std::size_t v = 0; v < height.size(); ++v) {
    height[v] = unitNormal.dot(m_solid.vertices[faces.vertices[v]]);
    index[v] = sums.volume.indexAtOrAbove(height[v]);
  }
  for (std::size_t k = 0; k < faces.faces.size(); ++k) {
    const std::array<std::int32_t, 3>& c = faces.corners[k];
    addFace(sums, unitNormal, static_cast<std::size_t>(faces.faces[k]), height[c[0]], height[c[1]], height[c[2]],
            index[c[0]], index[c[1]], index[c[2]]);
  }
  return sums.profile(0.0);
}

SweepProfile sweepPlanes(const TriangleMesh& solid, const Vec3& unitNormal, const OffsetGrid& grid,
                         const std::vector<double>& riskyShare, double sinAlphaMax) {
  return PlaneSweeper(solid, riskyShare, sinAlphaMax).sweep(unitNormal, grid);
}

}  // namespace multidir::core

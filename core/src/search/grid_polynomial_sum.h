#pragma once
// Sums piecewise polynomials of the offset t (degree <= 3) and samples the sum on a uniform grid.
// Pieces covering many grid points go into difference arrays of coefficients (O(1) each); short pieces are
// evaluated directly at their few points, which keeps the huge coefficients of thin triangles out of the
// prefix sums where they would cancel badly. Pieces are given by grid index ranges [j0, j1): the caller
// computes a height's index once (indexAtOrAbove) and reuses it for every piece that starts or ends there.
#include <array>
#include <cmath>
#include <vector>

#include "multidir/core/search/plane_sweep.h"

namespace multidir::core::detail {

class GridPolynomialSum {
 public:
  using Coefficients = std::array<double, 4>;  // c0 + c1 x + c2 x^2 + c3 x^3 with x = t - ref

  explicit GridPolynomialSum(const OffsetGrid& grid);

  // The first grid index whose offset is at or above t, clamped to [0, count].
  int indexAtOrAbove(double t) const {
    const double position = std::ceil((t - m_grid.firstMm) * m_inverseStep);
    if (!(position > 0)) return 0;  // also for -infinity
    if (position >= m_grid.count) return m_grid.count;
    return static_cast<int>(position);
  }

  // Adds the polynomial at the grid points j0 <= j < j1. Inline: the sweep calls it a few times per face
  // per normal.
  [[gnu::always_inline]] void addPiece(int j0, int j1, double ref, const Coefficients& c) {
    if (j1 <= j0) return;
    if (j1 - j0 <= kDirectEvaluationLimit) {
      for (int j = j0; j < j1; ++j) m_direct[j] += evaluate(c, m_grid.offsetAt(j) - ref);
      return;
    }
    // With p = step (j - center): t - ref = p - r, r = ref - offset(center). Expanded in closed form (a
    // branch-free Taylor shift), then scaled from powers of p to powers of u = j - center.
    const double r = ref - m_centerOffset;
    const double r2 = r * r;
    const double step = m_grid.stepMm;
    const double p0 = c[0] - c[1] * r + c[2] * r2 - c[3] * r2 * r;
    const double p1 = (c[1] - 2.0 * c[2] * r + 3.0 * c[3] * r2) * step;
    const double p2 = (c[2] - 3.0 * c[3] * r) * step * step;
    const double p3 = c[3] * step * step * step;
    Coefficients& begin = m_delta[j0];
    Coefficients& end = m_delta[j1];
    begin[0] += p0, begin[1] += p1, begin[2] += p2, begin[3] += p3;
    end[0] -= p0, end[1] -= p1, end[2] -= p2, end[3] -= p3;
  }
  // Adds c0 + c1 t at every grid point below j1 (a linear piece reaching down to -infinity). Its coefficients
  // stay small, so it always goes into the difference arrays.
  void addLinearBelow(int j1, double c0, double c1) {
    const double p0 = c0 + c1 * m_centerOffset, p1 = c1 * m_grid.stepMm;
    m_delta[0][0] += p0, m_delta[0][1] += p1;
    m_delta[j1][0] -= p0, m_delta[j1][1] -= p1;
  }
  // Adds `value` at every grid point below j1 (a constant piece reaching down to -infinity).
  void addConstantBelow(int j1, double value) {
    m_delta[0][0] += value;
    m_delta[j1][0] -= value;
  }

  std::vector<double> values() const;

  static double evaluate(const Coefficients& c, double x) { return ((c[3] * x + c[2]) * x + c[1]) * x + c[0]; }

 private:
  // Pieces touching at most this many grid points are evaluated point by point.
  static constexpr int kDirectEvaluationLimit = 4;

  OffsetGrid m_grid;
  double m_inverseStep;
  double m_center;  // grid index the expanded polynomials are centred on, to keep their terms small
  double m_centerOffset;  // the offset at m_center
  std::vector<Coefficients> m_delta;  // count + 1 entries
  std::vector<double> m_direct;
};

}  // namespace multidir::core::detail

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

  // Adds the polynomial at the grid points j0 <= j < j1.
  void addPiece(int j0, int j1, double ref, const Coefficients& c);
  // Adds `value` at every grid point below j1 (a constant piece reaching down to -infinity).
  void addConstantBelow(int j1, double value) {
    m_delta[0][0] += value;
    m_delta[j1][0] -= value;
  }

  std::vector<double> values() const;

 private:
  OffsetGrid m_grid;
  double m_inverseStep;
  double m_center;  // grid index the expanded polynomials are centred on, to keep their terms small
  std::vector<Coefficients> m_delta;  // count + 1 entries
  std::vector<double> m_direct;
};

}  // namespace multidir::core::detail

#pragma once
// Sums piecewise polynomials of the offset t (degree <= 3) and samples the sum on a uniform grid.
// Pieces covering many grid points go into difference arrays of coefficients (O(1) each); short pieces are
// evaluated directly at their few points, which keeps the huge coefficients of thin triangles out of the
// prefix sums where they would cancel badly.
#include <array>
#include <vector>

#include "multidir/core/search/plane_sweep.h"

namespace multidir::core::detail {

class GridPolynomialSum {
 public:
  using Coefficients = std::array<double, 4>;  // c0 + c1 x + c2 x^2 + c3 x^3 with x = t - ref

  explicit GridPolynomialSum(const OffsetGrid& grid);

  // Adds the polynomial on lo <= t < hi (lo may be -infinity, hi +infinity).
  void addPiece(double lo, double hi, double ref, const Coefficients& c);

  std::vector<double> values() const;

 private:
  int firstIndexAtOrAbove(double t) const;

  OffsetGrid m_grid;
  double m_center;  // grid index the expanded polynomials are centred on, to keep their terms small
  std::vector<Coefficients> m_delta;  // count + 1 entries
  std::vector<double> m_direct;
};

}  // namespace multidir::core::detail

#include "search/grid_polynomial_sum.h"

#include <algorithm>
#include <cmath>

namespace multidir::core::detail {
GridPolynomialSum::GridPolynomialSum(const OffsetGrid& grid)
    : m_grid(grid),
      m_inverseStep(1.0 / grid.stepMm),
      m_center(0.5 * (grid.count - 1)),
      m_centerOffset(grid.firstMm + grid.stepMm * m_center),
      m_delta(static_cast<std::size_t>(std::max(grid.count, 0)) + 1, Coefficients{0, 0, 0, 0}),
      m_direct(static_cast<std::size_t>(std::max(grid.count, 0)), 0.0) {}

std::vector<double> GridPolynomialSum::values() const {
  std::vector<double> out(m_direct.size());
  Coefficients running{0, 0, 0, 0};
  for (int j = 0; j < m_grid.count; ++j) {
    for (int m = 0; m < 4; ++m) running[m] += m_delta[j][m];
    out[j] = evaluate(running, j - m_center) + m_direct[j];
  }
  return out;
}

}  // namespace multidir::core::detail

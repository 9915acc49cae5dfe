#include "search/grid_polynomial_sum.h"

#include <algorithm>
#include <cmath>

namespace multidir::core::detail {
namespace {

// Pieces touching at most this many grid points are evaluated point by point.
constexpr int kDirectEvaluationLimit = 4;

double evaluate(const GridPolynomialSum::Coefficients& c, double x) { return ((c[3] * x + c[2]) * x + c[1]) * x + c[0]; }

}  // namespace

GridPolynomialSum::GridPolynomialSum(const OffsetGrid& grid)
    : m_grid(grid),
      m_inverseStep(1.0 / grid.stepMm),
      m_center(0.5 * (grid.count - 1)),
      m_delta(static_cast<std::size_t>(std::max(grid.count, 0)) + 1, Coefficients{0, 0, 0, 0}),
      m_direct(static_cast<std::size_t>(std::max(grid.count, 0)), 0.0) {}

void GridPolynomialSum::addPiece(int j0, int j1, double ref, const Coefficients& c) {
  if (j1 <= j0) return;
  if (j1 - j0 <= kDirectEvaluationLimit) {
    for (int j = j0; j < j1; ++j) m_direct[j] += evaluate(c, m_grid.offsetAt(j) - ref);
    return;
  }
  // With u = j - center: t - ref = step (u - s), s = (ref - first) / step - center. Expand binomially.
  const double step = m_grid.stepMm;
  const double s = (ref - m_grid.firstMm) / step - m_center;
  static constexpr double kBinomial[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
  Coefficients inU{0, 0, 0, 0};
  double stepPower = 1.0;
  for (int k = 0; k < 4; ++k, stepPower *= step) {
    if (c[k] == 0.0) continue;
    double minusSPower = 1.0;  // (-s)^(k-m), built from m = k downwards
    for (int m = k; m >= 0; --m, minusSPower *= -s) inU[m] += c[k] * stepPower * kBinomial[k][m] * minusSPower;
  }
  for (int m = 0; m < 4; ++m) {
    m_delta[j0][m] += inU[m];
    m_delta[j1][m] -= inU[m];
  }
}

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

#include "swept_top.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace multidir::slicing::audit {

double sweptTop(const std::vector<core::Vec3>& points, const core::Vec3& axisUnit, double turnRadians) {
  const core::Vec3 n = axisUnit.normalized();
  const double lo = std::min(0.0, turnRadians);
  const double hi = std::max(0.0, turnRadians);
  // Is the peak angle (mod 2 pi) inside [lo, hi]?
  const auto peakInside = [lo, hi](double peak) {
    const double twoPi = 2.0 * M_PI;
    const double first = peak + twoPi * std::ceil((lo - peak) / twoPi);
    return first <= hi;
  };
  double top = -std::numeric_limits<double>::infinity();
  for (const core::Vec3& f : points) {
    const double along = n.dot(f);
    const double c = n.z() * along;
    const double a = f.z() - c;  // (f - n (n.f)).z
    const double b = n.cross(f).z();
    double best = std::max(c + a * std::cos(lo) + b * std::sin(lo), c + a * std::cos(hi) + b * std::sin(hi));
    const double amplitude = std::hypot(a, b);
    if (amplitude > 0.0 && c + amplitude > best && peakInside(std::atan2(b, a))) best = c + amplitude;
    top = std::max(top, best);
  }
  return top;
}

}  // namespace multidir::slicing::audit

#include "multidir/slicing/clearance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace multidir::slicing {

double sweptTopZ(const std::vector<core::Vec3>& points, const core::Vec3& axisUnit, double turnRadians) {
  return sweptMax(points, axisUnit, turnRadians, core::Vec3::UnitZ());
}

double sweptMax(const std::vector<core::Vec3>& points, const core::Vec3& axisUnit, double turnRadians,
                const core::Vec3& direction) {
  const core::Vec3 d = direction.normalized();
  const core::Vec3 a = axisUnit.normalized();
  const double lo = std::min(0.0, turnRadians);
  const double hi = std::max(0.0, turnRadians);
  double top = -std::numeric_limits<double>::infinity();
  for (const core::Vec3& q : points) {
    // Rodrigues: R(t) q = a (a.q) + q_perp cos t + (a x q) sin t.
    const double along = a.dot(q);
    const core::Vec3 perp = q - along * a;
    const double c = d.dot(a) * along;
    const double cosCoeff = d.dot(perp);
    const double sinCoeff = d.dot(a.cross(q));
    const auto zAt = [&](double t) { return c + cosCoeff * std::cos(t) + sinCoeff * std::sin(t); };
    double best = std::max(zAt(lo), zAt(hi));
    // The peak of A cos t + B sin t is at t* = atan2(B, A) (+ 2 pi k).
    const double amplitude = std::hypot(cosCoeff, sinCoeff);
    if (amplitude > 0.0) {
      const double peak = std::atan2(sinCoeff, cosCoeff);
      const double twoPi = 2.0 * M_PI;
      const double first = peak + twoPi * std::ceil((lo - peak) / twoPi);
      if (first <= hi) best = c + amplitude;
    }
    top = std::max(top, best);
  }
  return top;
}

double anyTurnTopZ(const std::vector<core::Vec3>& points) {
  double top = -std::numeric_limits<double>::infinity();
  for (const core::Vec3& q : points) top = std::max(top, q.norm());
  return top;
}

std::vector<core::Vec3> printedPoints(const core::PrintJob& job, std::size_t k) {
  std::vector<core::Vec3> points;
  const Eigen::Isometry3d toK = job.steps[k].modelToFile;
  for (std::size_t i = 0; i <= k; ++i) {
    const Eigen::Isometry3d motion = toK * job.steps[i].modelToFile.inverse();
    for (const core::TriangleMesh* mesh : {&job.steps[i].region, &job.steps[i].supports})
      for (const core::Vec3& v : mesh->vertices) points.push_back(motion * v);
  }
  return points;
}

}  // namespace multidir::slicing

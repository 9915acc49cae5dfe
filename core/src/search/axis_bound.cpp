#include "search/axis_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "multidir/core/common/units.h"

namespace multidir::core::detail {

namespace {

// The largest n . d(theta) over the arc of directions d(theta) = cos(theta) up + sin(theta) (r x up), theta
// in [from, to] (radians): n . d = a cos(theta) + b sin(theta) = R cos(theta - phi), largest at phi when phi
// lies on the arc, else at an end.
double largestDotOnArc(double a, double b, double from, double to) {
  double largest = std::max(a * std::cos(from) + b * std::sin(from), a * std::cos(to) + b * std::sin(to));
  const double phi = std::atan2(b, a);
  for (const double turn : {-2.0 * kPi, 0.0, 2.0 * kPi})
    if (phi + turn >= from && phi + turn <= to) largest = std::max(largest, std::hypot(a, b));
  return largest;
}

}  // namespace

double unavoidableRiskyAreaMm2(const TriangleMesh& model, const MachineSpec& machine, double alphaMaxDegrees,
                               double supportedBandMm) {
  const Vec3 up = machine.up.normalized();
  const Vec3 side = machine.rotationAxis.normalized().cross(up);  // d(90 degrees)
  // The arc of the machine's range, widened to hold up (angle 0), which prints the platform's region.
  const double from = degToRad(std::min(0.0, machine.minAngleDegrees));
  const double to = degToRad(std::max(0.0, machine.maxAngleDegrees));
  const double sinAlpha = std::sin(degToRad(alphaMaxDegrees));
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& v : model.vertices) lowest = std::min(lowest, up.dot(v));
  const double bandTop = lowest + supportedBandMm;
  double area = 0.0;
  for (std::size_t f = 0; f < model.faceCount(); ++f) {
    const Vec3 areaNormal = model.areaNormal(f);
    const double length = areaNormal.norm();
    if (!(length > 0)) continue;
    const Vec3 n = areaNormal / length;
    // Risky for every direction of the arc: even the least downward one faces down beyond alpha_max. The
    // margin keeps a face that is risky by rounding only out of the bound.
    if (!(largestDotOnArc(n.dot(up), n.dot(side), from, to) + sinAlpha < -1e-9)) continue;
    if (std::min({up.dot(model.corner(f, 0)), up.dot(model.corner(f, 1)), up.dot(model.corner(f, 2))}) <= bandTop)
      continue;
    area += 0.5 * length;
  }
  return area;
}

}  // namespace multidir::core::detail

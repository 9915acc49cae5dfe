#include "search/axis_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "multidir/core/common/units.h"
#include "search/floating_pieces.h"

namespace multidir::core::detail {

namespace {

// The margin that keeps a face risky by rounding alone out of the bound, and a face the machine reaches within
// isRealizable's tolerance (1e-6 rad) in: a saved face is never counted. The heights' margin is how far
// clipping may move a point (clipMarginMm: snapping a corner near the plane onto it).
constexpr double kDotMargin = 1e-6;

// Every direction the machine prints along: up (the platform's region) and up turned by each whole stepper
// step of the range, min + i step (isRealizable's angles).
std::vector<Vec3> realizableDirections(const MachineSpec& machine) {
  std::vector<Vec3> directions{machine.up.normalized()};
  const int steps =
      static_cast<int>(std::floor((machine.maxAngleDegrees - machine.minAngleDegrees) / machine.angleStepDegrees + 1e-9));
  for (int i = 0; i <= steps; ++i) {
    const double angle = machine.minAngleDegrees + i * machine.angleStepDegrees;
    if (std::abs(angle) > 1e-9) directions.push_back(rotaryDirection(machine, angle).normalized());
  }
  return directions;
}

// P's highest point along `d` (as planeClearsPlatform measures it).
double platformTopAlong(const Vec3& d, const PlatformRegion& platform, const Vec3& up) {
  return d.dot(platform.center) + platform.radiusMm * (d - d.dot(up) * up).norm();
}

}  // namespace

double unavoidableRiskyAreaMm2(const TriangleMesh& model, const MachineSpec& machine, const PlatformRegion& platform,
                               double alphaMaxDegrees, double supportedBandMm) {
  const Vec3 up = machine.up.normalized();
  const std::vector<Vec3> directions = realizableDirections(machine);
  std::vector<double> tops(directions.size());
  for (std::size_t k = 0; k < directions.size(); ++k) tops[k] = platformTopAlong(directions[k], platform, up);
  const double sinAlpha = std::sin(degToRad(alphaMaxDegrees));
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& v : model.vertices) lowest = std::min(lowest, up.dot(v));
  const double bandTop = lowest + supportedBandMm;
  const double heightMarginMm = clipMarginMm(model);
  double area = 0.0;
  for (std::size_t f = 0; f < model.faceCount(); ++f) {
    const Vec3 areaNormal = model.areaNormal(f);
    const double length = areaNormal.norm();
    if (!(length > 0)) continue;
    const Vec3 n = areaNormal / length;
    const Vec3 a = model.corner(f, 0), b = model.corner(f, 1), c = model.corner(f, 2);
    if (std::min({up.dot(a), up.dot(b), up.dot(c)}) <= bandTop) continue;
    bool saved = false;
    for (std::size_t k = 0; k < directions.size() && !saved; ++k) {
      const Vec3& d = directions[k];
      if (n.dot(d) + sinAlpha < -kDotMargin) continue;  // risky along d
      // Up prints the platform's region, which holds anything; another direction only what lies above P.
      saved = k == 0 || std::max({d.dot(a), d.dot(b), d.dot(c)}) > tops[k] - heightMarginMm;
    }
    if (!saved) area += 0.5 * length;
  }
  return area;
}

}  // namespace multidir::core::detail

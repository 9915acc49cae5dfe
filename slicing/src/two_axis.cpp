#include "multidir/slicing/two_axis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "multidir/core/common/units.h"

namespace multidir::slicing {

namespace {

using core::Error;
using core::ErrorCode;

// Below this sine of the tilt the direction is the platform's normal (or its opposite) for any rotation: the
// rotation then stays where it was rather than spinning the part for a direction's rounding noise. The angle
// left out is at most 1e-9 rad.
constexpr double kFreeRotationSine = 1e-9;
// A coordinate this close beyond a limit is the limit itself (atan2 and acos round by ~1e-14 degrees).
constexpr double kLimitSlackDegrees = 1e-9;

std::string degrees(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", value);
  return text;
}

// The coordinate base + 360 k (a rotary axis reaches the same pose every turn) nearest to `from` within the
// axis' limits, if any k puts it there.
std::optional<double> nearestWithin(double base, double from, const FirmwareRotaryAxis& axis) {
  const double kLow = std::ceil((axis.minDegrees - kLimitSlackDegrees - base) / 360.0);
  const double kHigh = std::floor((axis.maxDegrees + kLimitSlackDegrees - base) / 360.0);
  if (kLow > kHigh) return std::nullopt;
  const double k = std::clamp(std::round((from - base) / 360.0), kLow, kHigh);
  return std::clamp(base + 360.0 * k, axis.minDegrees, axis.maxDegrees);
}

// The turn of a coordinate nearest the middle of the limits: what a refusal names as needed.
double nearestTurnTo(double base, const FirmwareRotaryAxis& axis) {
  const double middle = 0.5 * (axis.minDegrees + axis.maxDegrees);
  return base + 360.0 * std::round((middle - base) / 360.0);
}

// How far that turn stays outside the limits, for naming the nearer miss of two.
double missDegrees(double base, const FirmwareRotaryAxis& axis) {
  const double value = nearestTurnTo(base, axis);
  return std::max({0.0, axis.minDegrees - value, value - axis.maxDegrees});
}

std::string limitsText(const FirmwareRotaryAxis& axis, const char* key) {
  return "the profile allows " + degrees(axis.minDegrees) + " to " + degrees(axis.maxDegrees) + " (multidir." + key +
         "_min, multidir." + key + "_max)";
}

}  // namespace

TwoAxisAngles restAngles(const TwoAxisPlatform& axes) { return {axes.tilt.zeroDegrees, axes.rotation.zeroDegrees}; }

core::Result<TwoAxisAngles> twoAxisAngles(const Eigen::Vector3d& direction, const TwoAxisPlatform& axes,
                                          const TwoAxisAngles& previous, int step) {
  const std::string where = "step " + std::to_string(step);
  if (!direction.allFinite() || direction.norm() < 1e-12)
    return Error{ErrorCode::InvalidParameter, "the printing direction is zero or not finite: re-plan the job", where};
  const Eigen::Vector3d d = direction.normalized();

  // Rot(r) keeps d's height, so the tilt alone brings d.z to 1: t = +-acos(d.z). Tilt(t) takes +Z to
  // cos t Z + sin t (axis x Z), so Rot(r) must turn d's horizontal part (azimuth phi) onto axis x Z (azimuth
  // psi: -90 degrees for a tilt axis along X, 0 for one along Y) for t > 0, onto its opposite for -t.
  const double tilt = core::radToDeg(std::acos(std::clamp(d.z(), -1.0, 1.0)));
  const double horizontal = std::hypot(d.x(), d.y());
  const double psi = axes.tiltAlong == TiltAlong::X ? -90.0 : 0.0;
  const bool free = horizontal < kFreeRotationSine;
  const double rotation = free ? 0.0 : psi - core::radToDeg(std::atan2(d.y(), d.x()));

  struct Candidate {
    double tiltBase;      // firmware coordinate, any turn of it
    double rotationBase;  // likewise
    double tiltAngle;     // the convention's tilt, for messages
  };
  const FirmwareRotaryAxis& T = axes.tilt;
  const FirmwareRotaryAxis& R = axes.rotation;
  // With the rotation free, any rotation coordinate works: the one nearest the previous within the limits.
  const double freeRotation = std::clamp(previous.rotationDegrees, R.minDegrees, R.maxDegrees);
  const std::vector<Candidate> candidates = {
      {T.zeroDegrees + T.direction * tilt, free ? freeRotation : R.zeroDegrees + R.direction * rotation, tilt},
      {T.zeroDegrees - T.direction * tilt, free ? freeRotation : R.zeroDegrees + R.direction * (rotation + 180.0),
       -tilt}};

  std::optional<TwoAxisAngles> best;
  double bestMove = 0.0;
  std::vector<const Candidate*> tiltReachable;
  for (const Candidate& c : candidates) {
    const std::optional<double> t = nearestWithin(c.tiltBase, previous.tiltDegrees, T);
    if (!t) continue;
    tiltReachable.push_back(&c);
    const std::optional<double> r = nearestWithin(c.rotationBase, previous.rotationDegrees, R);
    if (!r) continue;
    const double move = std::abs(*t - previous.tiltDegrees) + std::abs(*r - previous.rotationDegrees);
    // Ties (within rounding) go to the first, the positive tilt.
    if (!best || move < bestMove - 1e-9) {
      best = TwoAxisAngles{*t, *r};
      bestMove = move;
    }
  }
  if (best) return *best;

  if (tiltReachable.empty()) {
    const Candidate& nearer = missDegrees(candidates[0].tiltBase, T) <= missDegrees(candidates[1].tiltBase, T)
                                  ? candidates[0]
                                  : candidates[1];
    return Error{ErrorCode::InvalidParameter,
                 "needs a tilt of " + degrees(nearestTurnTo(nearer.tiltBase, T)) + " deg (axis " + T.letter + "); " +
                     limitsText(T, "tilt") +
                     ": widen the limits if the machine reaches further, or plan with smaller tilts",
                 where};
  }
  // The tilt is reachable, its rotation is not: name the nearer miss among the reachable tilts.
  const Candidate& nearer =
      **std::min_element(tiltReachable.begin(), tiltReachable.end(), [&](const Candidate* a, const Candidate* b) {
        return missDegrees(a->rotationBase, R) < missDegrees(b->rotationBase, R);
      });
  return Error{ErrorCode::InvalidParameter,
               "needs a rotation of " + degrees(nearestTurnTo(nearer.rotationBase, R)) + " deg (axis " + R.letter +
                   ") at a tilt of " + degrees(nearer.tiltAngle) + " deg; " + limitsText(R, "rotation") +
                   ": a rotation range of 360 degrees or more reaches every direction",
               where};
}

}  // namespace multidir::slicing

#include <cmath>

#include "multidir/core/common/units.h"
#include "multidir/core/samples/sample_shapes.h"

namespace multidir::core::samples {
namespace {

constexpr int kSegments = 128;

// Appends `steps` points of the arc around centre from angle `from` to `to` (radians), without the arc's
// first point (the previous piece already ends there).
void appendArc(std::vector<Vec2>& out, const Vec2& centre, double radius, double from, double to, int steps) {
  for (int i = 1; i <= steps; ++i) {
    const double a = from + (to - from) * i / steps;
    out.emplace_back(centre.x() + radius * std::cos(a), centre.y() + radius * std::sin(a));
  }
}

}  // namespace

std::vector<Vec2> mushroomProfile() {
  std::vector<Vec2> p;
  p.emplace_back(0.0, 0.0);
  p.emplace_back(15.0, 0.0);
  // A foot that rounds from the base into the stem.
  appendArc(p, Vec2(15.0, 4.0), 4.0, -kPi / 2.0, -kPi, 6);
  p.back().x() = 11.0;  // the arc ends on r = 11 exactly, where the stem starts
  // The stem tapers from r = 11 to r = 9.
  for (int i = 1; i <= 10; ++i) {
    const double z = 4.0 + 48.0 * i / 10.0;
    p.emplace_back(11.0 - 2.0 * (z - 4.0) / 48.0, z);
  }
  // A fillet from the stem into the cap's underside.
  appendArc(p, Vec2(15.0, 52.0), 6.0, kPi, kPi / 2.0, 8);
  // The underside: nearly flat and dropping towards the rim, the sample's main overhang.
  for (int i = 1; i <= 14; ++i) {
    const double r = 15.0 + 31.0 * i / 14.0;
    const double s = (r - 15.0) / 31.0;
    p.emplace_back(r, 58.0 - 3.0 * s * s);
  }
  // The rim rounds up into the dome.
  appendArc(p, Vec2(46.0, 59.0), 4.0, -kPi / 2.0, 0.0, 8);
  // The dome: a half ellipse from r = 50 at z = 59 up to the top at z = 100.
  constexpr int kDomeSteps = 24;
  for (int i = 1; i < kDomeSteps; ++i) {
    const double a = (kPi / 2.0) * i / kDomeSteps;
    p.emplace_back(50.0 * std::cos(a), 59.0 + 41.0 * std::sin(a));
  }
  p.emplace_back(0.0, 100.0);
  return p;
}

Result<TriangleMesh> makeMushroom() { return revolveProfile(mushroomProfile(), kSegments); }

}  // namespace multidir::core::samples

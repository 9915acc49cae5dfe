#include <cmath>

#include "multidir/core/samples/sample_shapes.h"
#include "multidir/core/samples/sdf.h"
#include "samples/polygonize_coarsen.h"

namespace multidir::core::samples {
namespace {

// Sizes in mm. The spheres overlap so the smooth unions give necks, not pinches; the body's centre sits
// below its radius so the floor cut leaves a flat disc of about 35 mm diameter to stand on.
constexpr double kBodyRadius = 38.0;
constexpr double kBodyCentreZ = 34.0;
constexpr double kBellyRadius = 27.0;
constexpr double kBellyCentreZ = 90.0;
constexpr double kHeadRadius = 19.0;
constexpr double kHeadCentreZ = 128.0;
constexpr double kArmRadius = 4.5;
constexpr double kNoseRadius = 3.0;
// The fine grid's cell (see polygonizeStandingSample).
constexpr double kCellSizeMm = 1.6;

double snowmanDistance(const Vec3& p) {
  double d = sdfSphere(p, Vec3(0, 0, kBodyCentreZ), kBodyRadius);
  d = smoothUnion(d, sdfSphere(p, Vec3(0, 0, kBellyCentreZ), kBellyRadius), 6.0);
  d = smoothUnion(d, sdfSphere(p, Vec3(0, 0, kHeadCentreZ), kHeadRadius), 5.0);
  // Arms go out sideways and slightly up, so their undersides overhang.
  for (double side : {-1.0, 1.0})
    d = smoothUnion(d, sdfCapsule(p, Vec3(side * 18.0, 0, 95.0), Vec3(side * 60.0, 0, 112.0), kArmRadius), 3.0);
  // A carrot nose pointing along -Y.
  d = smoothUnion(d, sdfCapsule(p, Vec3(0, -12.0, 130.0), Vec3(0, -29.0, 129.0), kNoseRadius), 2.0);
  return aboveFloor(d, p);
}

}  // namespace

Result<TriangleMesh> makeSnowman() {
  BoundingBox extent;
  extent.min = Vec3(-60.0 - kArmRadius, -kBodyRadius, 0.0);
  extent.max = Vec3(60.0 + kArmRadius, kBodyRadius, kHeadCentreZ + kHeadRadius);
  return polygonizeStandingSample(snowmanDistance, extent, kCellSizeMm);
}

}  // namespace multidir::core::samples

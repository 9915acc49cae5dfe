#include <cmath>

#include "multidir/core/samples/coarsen.h"
#include "multidir/core/samples/implicit_surface.h"
#include "multidir/core/samples/sample_shapes.h"
#include "multidir/core/samples/sdf.h"

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
// Polygonized on a fine grid (so thin parts keep their shape), then coarsened to edges of about
// kMinEdgeMm..kMaxEdgeMm: marching tetrahedra alone would give several times more triangles.
constexpr double kMinEdgeMm = 1.2;
constexpr double kMaxEdgeMm = 3.0;
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
  // The grid's z levels sit half a cell off z = 0, so the floor's crossings land exactly on z = 0.
  const double margin = 2.0 * kCellSizeMm;
  BoundingBox box;
  box.min = Vec3(-60.0 - kArmRadius - margin, -kBodyRadius - margin, -1.5 * kCellSizeMm);
  box.max = Vec3(60.0 + kArmRadius + margin, kBodyRadius + margin, kHeadCentreZ + kHeadRadius + margin);
  Result<TriangleMesh> fine = polygonize(snowmanDistance, box, kCellSizeMm);
  if (!fine) return fine.error();
  CoarsenOptions coarsen;
  coarsen.minEdgeMm = kMinEdgeMm;
  coarsen.maxEdgeMm = kMaxEdgeMm;
  return collapseShortEdges(*fine, coarsen);
}

}  // namespace multidir::core::samples

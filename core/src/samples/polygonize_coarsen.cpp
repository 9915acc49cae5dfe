#include "samples/polygonize_coarsen.h"

#include "multidir/core/samples/coarsen.h"

namespace multidir::core::samples {
namespace {

constexpr double kMinEdgeMm = 1.2;
constexpr double kMaxEdgeMm = 3.0;

}  // namespace

Result<TriangleMesh> polygonizeStandingSample(const SignedDistance& sdf, const BoundingBox& extent, double cellSizeMm) {
  const double margin = 2.0 * cellSizeMm;
  BoundingBox box;
  box.min = Vec3(extent.min.x() - margin, extent.min.y() - margin, -1.5 * cellSizeMm);
  box.max = Vec3(extent.max.x() + margin, extent.max.y() + margin, extent.max.z() + margin);
  Result<TriangleMesh> fine = polygonize(sdf, box, cellSizeMm);
  if (!fine) return fine.error();
  CoarsenOptions coarsen;
  coarsen.minEdgeMm = kMinEdgeMm;
  coarsen.maxEdgeMm = kMaxEdgeMm;
  return collapseShortEdges(*fine, coarsen);
}

}  // namespace multidir::core::samples

#include "multidir/core/apart/bed_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace multidir::core {
namespace {

bool limited(const BuildVolume& v) { return v.xMm > 0 && v.yMm > 0 && v.zMm > 0; }

// How far the laid box overflows the volume, as the worst ratio of size to room (<= 1: fits).
double overflow(const Vec3& size, const BuildVolume& v) {
  return std::max({size.x() / v.xMm, size.y() / v.yMm, size.z() / v.zMm});
}

}  // namespace

BedPose layOnBed(const TriangleMesh& part, const Vec3& printingDirection, const BuildVolume& volume) {
  const Eigen::Matrix3d toUp =
      Eigen::Quaterniond::FromTwoVectors(printingDirection.normalized(), Vec3::UnitZ()).toRotationMatrix();
  std::vector<Vec3> laid;
  laid.reserve(part.vertices.size());
  for (const Vec3& v : part.vertices) laid.push_back(toUp * v);

  double bestOverflow = std::numeric_limits<double>::infinity();
  Eigen::Matrix3d best = toUp;
  Vec3 bestLow = Vec3::Zero(), bestSize = Vec3::Zero();
  for (int degrees = 0; degrees < 180; ++degrees) {
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(degToRad(degrees), Vec3::UnitZ()).toRotationMatrix();
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
    for (const Vec3& p : laid) {
      const Vec3 q = turn * p;
      low = low.cwiseMin(q);
      high = high.cwiseMax(q);
    }
    const Vec3 size = high - low;
    const double over = limited(volume) ? overflow(size, volume) : 0.0;
    if (over < bestOverflow - 1e-12) {
      bestOverflow = over;
      best = turn * toUp;
      bestLow = low;
      bestSize = size;
    }
    if (!limited(volume) || over <= 1.0) break;  // the first turn that fits
  }
  BedPose pose;
  pose.modelToBed.linear() = best;
  pose.modelToBed.translation() = -bestLow;
  pose.sizeMm = bestSize;
  pose.fits = !limited(volume) || bestOverflow <= 1.0;
  return pose;
}

}  // namespace multidir::core

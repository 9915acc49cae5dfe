#pragma once
// How a part lies on a plain printer's bed: its printing direction turned to +Z (cut face down), then turned
// about Z so that its footprint fits the bed, or, when no turn fits, the turn that overflows least.
#include <Eigen/Geometry>

#include "multidir/core/apart/apart_plan.h"

namespace multidir::core {

struct BedPose {
  // Model frame to bed frame: rotation, then translation that puts the part's box corner at the origin.
  Eigen::Isometry3d modelToBed = Eigen::Isometry3d::Identity();
  Vec3 sizeMm = Vec3::Zero();  // the laid part's box (x, y: footprint; z: height)
  bool fits = true;            // within the volume (all zero volume: always)
};

// Turns about Z are tried every degree over 180 degrees (a box's extents repeat after that); the first that
// fits is taken, so the same part always lies the same way.
BedPose layOnBed(const TriangleMesh& part, const Vec3& printingDirection, const BuildVolume& volume);

}  // namespace multidir::core

#pragma once
// An Open5x-style platform as the printer's firmware moves it, modelled from the machine's side (a cradle that
// tilts about a horizontal line of the printer, a turntable riding on it), not from slicing's angle solver
// (slicing/include/multidir/slicing/two_axis.h): tests compare the two, so this copy must not borrow its answer.
//
// At the firmware's coordinates T (tilt axis) and R (rotation axis), the convention's angles are
// t = (T - tiltZero) / tiltDirection and r = (R - rotationZero) / rotationDirection. A point p of the part, given
// where it is with both angles zero, then stands at Tilt(t) * Rot(r) * p:
//  - Rot(r): the turntable turns by +r degrees about the printer's +Z (counter-clockwise seen from above)
//    through the rotation centre (X, Y);
//  - Tilt(t): the cradle turns by -t degrees about the tilt axis' direction (+X or +Y) through the line at the
//    tilt height over the rotation centre (Z = tiltHeight, and Y (tilt along X) or X (along Y) of the centre),
//    so a positive tilt lifts the platform's top towards +Z x axis.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace multidir::hardware::sim {

struct TwoAxisMachine {
  double tiltZeroDegrees = 0.0;
  double tiltDirection = 1.0;  // +1 or -1
  double rotationZeroDegrees = 0.0;
  double rotationDirection = 1.0;
  bool tiltAlongX = true;  // else along Y
  double tiltHeightMm = 0.0;
  Eigen::Vector2d rotationCenterMm = Eigen::Vector2d::Zero();
};

// Where the platform (and the part on it) stands at the firmware coordinates (degrees): p -> pose * p.
Eigen::Isometry3d twoAxisPlatformPose(const TwoAxisMachine& machine, double tiltCoordinate, double rotationCoordinate);

}  // namespace multidir::hardware::sim

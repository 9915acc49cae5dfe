#pragma once
// Two rotary axes in the printer's firmware (multidir.platform = firmware-2axis), the Open5x arrangement: a
// tilt axis turns a cradle about a horizontal line of the printer (along its X or Y), and the rotation axis
// rides on that cradle, turning the platform about the platform's own normal (the printer's Z when the tilt is
// at zero). The other way round (a tilt axis carried by a turntable) is refused by the profile.
//
// The kinematics, at the convention's angles t (tilt) and r (rotation), both in degrees:
//  - rotation: the platform turns by +r about its normal (counter-clockwise seen from above at rest);
//  - tilt: then the cradle turns the platform, and the part on it, by -t about the tilt axis' direction (+X or
//    +Y): as the one-axis firmware case (core::platformRotation, 4-DOF), a positive tilt lifts the platform's
//    top towards +Z x axis (+Y for a tilt axis along X, -X for one along Y).
// So a point p of the part at rest goes to Tilt(t) * Rot(r) * p (about the axes' lines). The firmware's own
// coordinate of each axis, what `G1 U.. V..` takes and what the limits are given in, is
// zero + direction * angle (multidir.tilt_zero, multidir.tilt_direction, ...).
#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::slicing {

// One rotary axis of the firmware.
struct FirmwareRotaryAxis {
  std::string letter;          // the G-code axis letter (A B C U V W)
  std::string klipperStepper;  // Klipper: the [manual_stepper] that drives it
  double zeroDegrees = 0.0;    // the axis' coordinate at the convention's angle 0 (level, resp. azimuth 0)
  double direction = 1.0;      // +1 or -1: the axis' coordinate per degree of the convention's angle
  double minDegrees = -90.0;   // the axis' limits, in its own coordinate (as the firmware's M208 / position_min)
  double maxDegrees = 90.0;
};

enum class TiltAlong { X, Y };  // the printer axis the tilt axis runs along

// The two axes of a firmware-2axis printer (the profile's multidir.tilt_* and multidir.rotation_* keys).
struct TwoAxisPlatform {
  FirmwareRotaryAxis tilt{"U", "tilt", 0.0, 1.0, -90.0, 90.0};
  FirmwareRotaryAxis rotation{"V", "rotation", 0.0, 1.0, -360.0, 360.0};
  TiltAlong tiltAlong = TiltAlong::X;
  double tiltHeightMm = 0.0;                                 // printer Z of the tilt axis
  Eigen::Vector2d rotationCenter = Eigen::Vector2d::Zero();  // printer XY of the rotation axis at tilt zero
  // The machine's own body, which must stay below the nozzle (two_axis_motion.h): the platform disc about the
  // rotation axis, from the platform plane down by its thickness, and the tilt cradle as a box.
  double platformRadiusMm = 0.0;     // multidir.platform_radius; 0: the plan's platform disc
  double platformThicknessMm = 5.0;  // multidir.platform_thickness
  std::optional<Eigen::AlignedBox3d> cradle;  // multidir.cradle_box: printer coordinates with the tilt at zero
};

// Where the two axes stand: their firmware coordinates, degrees.
struct TwoAxisAngles {
  double tiltDegrees = 0.0;
  double rotationDegrees = 0.0;
};

// The firmware coordinates at which the axes stand when the platform is at rest (both angles zero): where a job
// starts, the `previous` of its first step.
TwoAxisAngles restAngles(const TwoAxisPlatform& axes);

// The axis coordinates that turn `direction` (the step's printing direction in the printer frame at rest, as its
// pose gives it; need not be unit) to the printer's +Z. In general two solutions do, (t, r) and (-t, r + 180),
// and the rotation repeats every 360 degrees; the one chosen is within both axes' limits and moves the least
// from `previous` (|tilt change| + |rotation change|, ties to the positive tilt). A direction within 1e-9 of the
// platform's normal (or of its opposite) leaves the rotation free: it stays at `previous`.
// Errors: InvalidParameter where "step <step>": a direction that is zero or not finite; a direction the limits
// cannot reach, naming the angle it needs and the limits ("needs a tilt of 104.2 deg (axis U); the profile
// allows -90 to 90 (multidir.tilt_min, multidir.tilt_max) ...").
core::Result<TwoAxisAngles> twoAxisAngles(const Eigen::Vector3d& direction, const TwoAxisPlatform& axes,
                                          const TwoAxisAngles& previous, int step);

}  // namespace multidir::slicing

#pragma once
// How a firmware-2axis printer moves the part and its own platform (two_axis.h gives the convention and the
// angles): the pose of every step, the turns between steps with the order of the two axes that keeps the
// nozzle lowest, and the platform's body that must stay below the nozzle (docs/slicing.md "Two firmware axes").
//
// Everything here is in the machine frame of a print job (core::PrintJob, frame Machine): the platform plane at
// rest is z = 0 with the platform centre at the origin; the printer's frame is that moved by
// (platform_center, platform_z). The axes' lines, given in the printer's frame by the profile, are:
//  - the rotation axis: the platform's normal through multidir.rotation_center (vertical at rest);
//  - the tilt axis: along multidir.tilt_along (X or Y) at multidir.tilt_height, crossing the rotation axis (the
//    Open5x cradle: the rotation axis stands on the tilt axis).
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/plan/print_job.h"
#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/two_axis.h"

namespace multidir::slicing {

// One axis moving while the other stands: where a turn goes, in firmware coordinates.
struct AxisMove {
  enum class Axis { Tilt, Rotation };
  Axis axis = Axis::Tilt;
  double fromDegrees = 0.0;
  double toDegrees = 0.0;
};

// A turn of the two axes from one step's angles to the next step's, one axis at a time.
struct TwoAxisTurn {
  TwoAxisAngles from;
  TwoAxisAngles to;
  std::vector<AxisMove> moves;  // in order; empty when the angles do not change
  double sweptTopZ = 0.0;       // machine frame: the highest point the part and the platform's body reach
};

class TwoAxisMachine {
 public:
  // `planPlatformRadiusMm`: the platform's radius when the profile gives none (multidir.platform_radius = 0),
  // the plan's platform disc (core::PlatformRegion::radiusMm).
  TwoAxisMachine(const PrinterProfile& profile, double planPlatformRadiusMm);

  // The rigid motion of the platform (and the part fixed to it) from rest to the axes at `at` (firmware
  // coordinates), machine frame: Tilt(t) * Rot(r) about the axes' lines.
  [[nodiscard]] Eigen::Isometry3d pose(const TwoAxisAngles& at) const;

  // The angles of every step of `job` in printing order, each from the previous one (the first from rest):
  // twoAxisAngles of the step's printing direction in the rest frame. Errors: those of twoAxisAngles, naming
  // the step.
  [[nodiscard]] core::Result<std::vector<TwoAxisAngles>> stepAngles(const core::PrintJob& job) const;

  // `job` with every step posed as this machine holds it (modelToFile = pose(angles k) * step 1's; the region
  // and supports moved with it, lowestHeightMm their new lowest z). The first step stays where it was.
  [[nodiscard]] core::PrintJob posed(const core::PrintJob& job, const std::vector<TwoAxisAngles>& angles) const;

  // The turn from `from` to `to` that keeps the highest point lowest: of rotation-then-tilt, tilt-then-rotation
  // and (when both tilts differ from rest) tilt-to-rest, rotation, tilt, the one whose swept top (exact: every
  // point and body corner turns on a circle about one axis' line per move) is least; ties to fewer moves.
  // `printed`: the part printed so far, in the rest frame (machine frame with the axes at rest).
  [[nodiscard]] TwoAxisTurn planTurn(const std::vector<core::Vec3>& printed, const TwoAxisAngles& from,
                                     const TwoAxisAngles& to) const;

  // The highest point of the platform's body (its disc, exactly, and the tilt cradle) with the axes at `at`.
  [[nodiscard]] double bodyTopZ(const TwoAxisAngles& at) const;

  [[nodiscard]] const TwoAxisPlatform& axes() const { return m_axes; }
  [[nodiscard]] double platformRadiusMm() const { return m_radiusMm; }

 private:
  // The convention's angles, radians, of firmware coordinates.
  [[nodiscard]] double tiltRadians(double tiltDegrees) const;
  [[nodiscard]] double rotationRadians(double rotationDegrees) const;
  [[nodiscard]] Eigen::Isometry3d tiltPose(double tiltDegrees) const;
  // The highest z of `part` (rest frame, moving with both axes) and the cradle's corners (moving with the tilt)
  // over the moves, from `from`.
  [[nodiscard]] double sweptTop(const std::vector<core::Vec3>& part, const TwoAxisAngles& from,
                                const std::vector<AxisMove>& moves) const;

  TwoAxisPlatform m_axes;
  Eigen::Vector3d m_tiltDirection = Eigen::Vector3d::UnitX();
  Eigen::Vector3d m_tiltPoint = Eigen::Vector3d::Zero();      // a point of the tilt axis, machine frame
  Eigen::Vector3d m_rotationPoint = Eigen::Vector3d::Zero();  // where the rotation axis crosses the platform at rest
  double m_radiusMm = 0.0;
  std::vector<core::Vec3> m_disc;    // the platform disc's circumscribed prism corners, rest frame
  std::vector<core::Vec3> m_cradle;  // the cradle box's corners at tilt zero (empty without one)
};

}  // namespace multidir::slicing

#pragma once
// What a printer can do: the platform it builds on and the printing directions it can realize.
//
// The platform plane passes through the model's lowest point along `up`. The platform region P is a disc on
// it (Criterion III keeps every clipping plane above P). The printing directions a machine realizes:
//  - 3-DOF: up only (an ordinary printer; the "fixed direction" baseline);
//  - 4-DOF: the platform turns about one axis r (a line in the platform plane) over an angle range, in
//    whole steps of the stepper; a direction is up turned about r by a realizable angle;
//  - 5-DOF: a robot arm tilts the platform up to a maximal angle from up, at any azimuth, except inside
//    forbidden cones;
//  - apart: an ordinary printer that prints every region as a part of its own, laid on the bed on its cut
//    face (the first on the model's own bottom), the parts glued together afterwards (docs/apart.md). Any
//    direction is realizable (a part can be laid any way up), and the sequence criteria of a
//    multi-directional machine (II: what is left stands on the platform; III: no plane cuts the platform
//    region) do not apply: nothing is printed onto anything else.
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

enum class MachineKind { ThreeAxis, RotaryPlatform, TiltRotate, Apart };

// "3dof", "4dof", "5dof", "apart" (as the command line and profiles spell them).
const char* machineKindName(MachineKind kind);
Result<MachineKind> parseMachineKind(const std::string& text);

struct ForbiddenCone {
  Vec3 axis = Vec3::UnitZ();       // unit
  double halfAngleDegrees = 10.0;  // in (0, 180)
};

struct MachineSpec {
  MachineKind kind = MachineKind::TiltRotate;
  Vec3 up = Vec3::UnitZ();  // unit; the printing direction of the platform at rest

  // Platform region P. A radius <= 0 means "the model's contact footprint plus platformMarginMm".
  double platformRadiusMm = 0.0;
  double platformMarginMm = 5.0;

  // 4-DOF rotary platform.
  Vec3 rotationAxis = Vec3::UnitX();  // unit, perpendicular to up
  double minAngleDegrees = -60.0;
  double maxAngleDegrees = 60.0;
  double angleStepDegrees = 1.0;  // the stepper's resolution: only multiples of it are realizable

  // 5-DOF robot arm.
  double maxTiltDegrees = 90.0;
  std::vector<ForbiddenCone> forbiddenCones;
};

// Names the first field out of range, with its valid range.
Status validate(const MachineSpec& spec);

// The disc P on the platform plane.
struct PlatformRegion {
  Vec3 center = Vec3::Zero();  // on the platform plane
  double radiusMm = 0.0;
  double heightMm = 0.0;  // up . x of the platform plane
};

// P for a model: the given radius, or the footprint (vertices within toleranceMm of the lowest point along
// up) enclosed by a circle around its centroid, plus the margin.
PlatformRegion platformRegionFor(const TriangleMesh& model, const MachineSpec& spec, double toleranceMm = 1e-3);

// Machine angles that print along a direction: 4-DOF the angle about r; 5-DOF tilt from up and azimuth
// (measured in the platform plane from the frame's x axis, see platformFrameX). They are the angles the
// device takes (print-job.json, the drivers' registers); platformRotation is what the device does with them.
struct MachineAngles {
  double rotaryDegrees = 0.0;
  double tiltDegrees = 0.0;
  double azimuthDegrees = 0.0;
};

// A unit vector perpendicular to up that 5-DOF azimuths are measured from (x if possible, else y).
Vec3 platformFrameX(const Vec3& up);

// Whether the machine can print along `direction` (unit), within `toleranceRadians`.
bool isRealizable(const MachineSpec& spec, const Vec3& direction, double toleranceRadians = 1e-6);
MachineAngles machineAnglesFor(const MachineSpec& spec, const Vec3& direction);

// The pose convention, in one place: the rotation the machine applies to the part (model frame, about the
// pivot) when it takes `angles`. docs/hardware.md ("Pose convention") states it for the devices:
//  - 3-DOF: the identity;
//  - 4-DOF: the platform turns by -rotaryDegrees about rotationAxis r (a positive angle tilts the platform's
//    top towards up x r), so rotaryDirection(spec, rotaryDegrees) ends up along up;
//  - 5-DOF and apart (the part laid on the bed along the direction): the platform turns by tiltDegrees about the horizontal axis sin(a) x - cos(a) y of the platform
//    frame (x = platformFrameX(up), y = up x x, a = azimuthDegrees): the direction tilted from up by the tilt
//    towards the azimuth ends up along up, and the platform's top tilts towards the opposite azimuth, a + 180.
// For every realizable direction d, platformRotation(spec, machineAnglesFor(spec, d)) * d == up.
Eigen::Matrix3d platformRotation(const MachineSpec& spec, const MachineAngles& angles);

// The 4-DOF direction for an angle about the axis: up turned by angleDegrees about rotationAxis.
Vec3 rotaryDirection(const MachineSpec& spec, double angleDegrees);

}  // namespace multidir::core

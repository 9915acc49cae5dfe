#pragma once
// The machine profile's limits, checked before any command reaches a device. The drivers call these first
// and send nothing when they fail; a plan or a panel can call them too to check a whole print run up front.
#include "multidir/core/common/result.h"
#include "multidir/core/search/machine.h"

namespace multidir::hardware {

// 4-DOF: the profile must be a rotary platform, the angle finite, inside [minAngleDegrees, maxAngleDegrees]
// and a whole number of angleStepDegrees from minAngleDegrees (within toleranceDegrees): the stepper cannot
// stop anywhere else. InvalidParameter naming the angle, the range or the nearest realizable angles.
core::Status checkRotaryTarget(const core::MachineSpec& machine, double angleDegrees, double toleranceDegrees = 1e-6);

// 5-DOF: the profile must be a tilt-rotate machine, tilt in [0, maxTiltDegrees], azimuth finite, and the
// direction (up tilted by tiltDegrees towards azimuthDegrees, measured from platformFrameX(up)) outside every
// forbidden cone. InvalidParameter naming the limit that is broken.
core::Status checkTiltTarget(const core::MachineSpec& machine, double tiltDegrees, double azimuthDegrees);

// The printing direction of a 5-DOF orientation, the inverse of core::machineAnglesFor for tilt/azimuth.
core::Vec3 tiltAzimuthDirection(const core::MachineSpec& machine, double tiltDegrees, double azimuthDegrees);

}  // namespace multidir::hardware

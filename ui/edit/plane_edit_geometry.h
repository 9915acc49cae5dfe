#pragma once
// Geometry the plan editor needs to offer sensible values: how far a plane can move and still cut what is
// left of the model, the point it turns about, the 5-DOF and 4-DOF directions its controls stand for, and
// where a new plane goes. Pure functions of a plan (no Qt widgets, no VTK), so they can be tested alone.
#include "multidir/core/search/decomposition.h"

namespace multidir::ui {

// Offsets along a normal, in mm; empty when minMm > maxMm.
struct OffsetRange {
  double minMm = 0.0;
  double maxMm = -1.0;
  [[nodiscard]] bool empty() const { return !(minMm <= maxMm); }
};

// What plane `planeIndex` cuts: the regions no earlier plane cut off (those cut off by it or a later plane,
// and the region on the platform). The offsets along `normal` between its lowest and highest vertex: a
// plane outside them cuts nothing. Empty for an index out of range.
[[nodiscard]] OffsetRange offsetRangeBefore(const core::Decomposition& plan, int planeIndex, const core::Vec3& normal);

// The point plane `planeIndex` turns about when its direction changes, so it swings in place instead of
// about the origin: the centre of its cut, or (when it left no cap) the centre of what it cuts, projected
// onto it. The origin for an index out of range.
[[nodiscard]] core::Vec3 planePivot(const core::Decomposition& plan, int planeIndex);

// 5-DOF: the unit direction `tiltDegrees` away from `up`, turned by `azimuthDegrees` in the platform plane
// from core::platformFrameX(up) (as core::machineAnglesFor measures them).
[[nodiscard]] core::Vec3 tiltedDirection(const core::Vec3& up, double tiltDegrees, double azimuthDegrees);

// 4-DOF: the realizable angle nearest `angleDegrees`: a whole number of steps from the minimum, within the
// machine's range.
[[nodiscard]] double snapRotaryDegrees(const core::MachineSpec& machine, double angleDegrees);

// Where Add plane puts a new plane (`index` in clipping order: it is inserted before the plane there).
struct NewPlanePlacement {
  int index = 0;
  core::Plane plane;
};

// With a plane selected: a plane parallel to it, halfway between it and the top of the piece it cuts off,
// inserted before it in clipping order, so that piece is split in two (the new upper part is printed last).
// Without a selection (or without planes): a plane level with `up` at mid-height of what is left on the
// platform, cut last.
[[nodiscard]] NewPlanePlacement suggestNewPlane(const core::Decomposition& plan, int selectedPlane,
                                                const core::Vec3& up);

}  // namespace multidir::ui

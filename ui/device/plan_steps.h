#pragma once
// A plan (core::Decomposition) as the print-run sequencer's steps for one device: the rotary platform turns
// to each region's angle about its axis (4-DOF), the robot arm tilts the platform to each region's tilt and
// azimuth (5-DOF). Every step is checked against the machine profile before a run starts, so a run never
// stops half-way on a target the device would refuse.
#include <cstddef>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/hardware/print_run.h"
#include "ui/device/device_snapshot.h"

namespace multidir::ui {

// "region-01.stl" for index 0: the file savePlan writes for the region (core/plan/plan_file.h).
std::string regionFileName(std::size_t index);

// What the panel keeps of a plan's region: its machine angles and its printing direction.
struct RegionTarget {
  core::MachineAngles angles;
  core::Vec3 direction = core::Vec3::UnitZ();  // unit
};

// The targets of each region of `plan`, in printing order (all the panel keeps of a plan).
std::vector<RegionTarget> regionTargets(const core::Decomposition& plan);

// One step per region in printing order. Rotary angles within `snapToleranceDegrees` of a stepper step are
// moved onto it (the plan's angles come from directions and carry rounding noise). InvalidParameter for an
// empty plan or one the device cannot run. For the rotary platform the plan's real mismatch is named first:
// every region whose direction tilts beyond the platform's range, then a direction off the plane it turns in
// (a 5-DOF plan's), and only then a region's angle against the range and the stepper's grid (its number
// from 1).
core::Result<std::vector<hardware::PrintStep>> printSteps(const std::vector<RegionTarget>& regions,
                                                          DeviceKind kind, const core::MachineSpec& machine,
                                                          double snapToleranceDegrees = 1e-4);

}  // namespace multidir::ui

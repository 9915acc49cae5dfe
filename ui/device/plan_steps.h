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

// The machine angles of each region of `plan`, in printing order (all the panel keeps of a plan).
std::vector<core::MachineAngles> regionAngles(const core::Decomposition& plan);

// One step per region in printing order. Rotary angles within `snapToleranceDegrees` of a stepper step are
// moved onto it (the plan's angles come from directions and carry rounding noise). InvalidParameter naming
// the first region the profile cannot reach (its number from 1), or an empty plan.
core::Result<std::vector<hardware::PrintStep>> printSteps(const std::vector<core::MachineAngles>& regions,
                                                          DeviceKind kind, const core::MachineSpec& machine,
                                                          double snapToleranceDegrees = 1e-4);

}  // namespace multidir::ui

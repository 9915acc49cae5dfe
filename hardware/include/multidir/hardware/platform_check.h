#pragma once
// Is the device at a Modbus address the one a job needs? A job for the rotary platform (4-DOF) run against a
// robot arm, or one for the robot arm (5-DOF) against a rotary controller, otherwise fails deep in the
// driver's connect with a Modbus exception ("illegal data address", "gateway target"), which does not say
// that the wrong device is connected. The check only reads registers: nothing is written to either device.
#include "multidir/core/common/result.h"
#include "multidir/core/search/machine.h"
#include "multidir/hardware/connection.h"

namespace multidir::hardware {

// Reads the status block of the device `kind` needs at `connection` (the rotary controller's registers 0-13
// at `rotaryUnitId`, or the robot program's 128-150 at `robotUnitId`). Done when it reads, and whenever the
// check cannot tell (nothing answers, a timeout, another failure: the driver's connect() then says why in its
// own words). When the device refuses the block with a Modbus exception and the other device's block reads,
// InvalidParameter saying what the job needs, what answers there and what to do.
core::Status checkPlatformFor(core::MachineKind kind, ConnectionSettings connection, int rotaryUnitId, int robotUnitId);

}  // namespace multidir::hardware

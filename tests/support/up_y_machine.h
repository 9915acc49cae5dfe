#pragma once
// The machine most search tests use: MachineSpec's defaults (5-DOF) standing the model on +Y, the shared
// models' up axis (../shared/models/README.md).
#include "multidir/core/search/machine.h"

namespace multidir::test {

inline core::MachineSpec upY() {
  core::MachineSpec machine;
  machine.up = core::Vec3::UnitY();
  return machine;
}

}  // namespace multidir::test

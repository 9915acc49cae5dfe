#pragma once
// A machine kind as the studio names it to a person, translated (core::machineKindName's "5dof" is the file
// format's id, never shown).
#include <QString>

#include "multidir/core/search/machine.h"

namespace multidir::ui {

[[nodiscard]] QString machineKindText(core::MachineKind kind);

}  // namespace multidir::ui

#include "ui/common/machine_kind_text.h"

#include <QCoreApplication>

namespace multidir::ui {

QString machineKindText(core::MachineKind kind) {
  switch (kind) {
    case core::MachineKind::ThreeAxis: return QCoreApplication::translate("multidir::ui::MachineKind", "3-DOF");
    case core::MachineKind::RotaryPlatform:
      return QCoreApplication::translate("multidir::ui::MachineKind", "rotary platform (4-DOF)");
    case core::MachineKind::TiltRotate:
      return QCoreApplication::translate("multidir::ui::MachineKind", "tilting (5-DOF)");
    case core::MachineKind::Apart:
      return QCoreApplication::translate("multidir::ui::MachineKind", "printed apart");
  }
  return QString::fromLatin1(core::machineKindName(kind));
}

}  // namespace multidir::ui

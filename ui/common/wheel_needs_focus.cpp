#include "ui/common/wheel_needs_focus.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QEvent>
#include <QWidget>

namespace multidir::ui {
namespace {

bool isField(const QObject* object) {
  return qobject_cast<const QAbstractSpinBox*>(object) != nullptr || qobject_cast<const QComboBox*>(object) != nullptr;
}

}  // namespace

bool WheelNeedsFocus::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() == QEvent::Polish && isField(watched)) {
    auto* field = static_cast<QWidget*>(watched);
    if (field->focusPolicy() == Qt::WheelFocus) field->setFocusPolicy(Qt::StrongFocus);
  } else if (event->type() == QEvent::Wheel && isField(watched) && !static_cast<QWidget*>(watched)->hasFocus()) {
    // Ignored and filtered: QApplication hands the wheel on to the parent, which scrolls.
    event->ignore();
    return true;
  }
  return QObject::eventFilter(watched, event);
}

}  // namespace multidir::ui

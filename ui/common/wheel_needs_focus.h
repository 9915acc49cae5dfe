#pragma once
// The mouse wheel changes a field (spin box, combo box) only when the field has the keyboard focus: a wheel
// turned to scroll a dock must scroll the dock, not change the number under the cursor on the way
// (min region height 2 -> 6 was seen). Installed once on the application (MainWindow does it): it gives
// every spin box and combo box the focus policy StrongFocus when it is polished, so that the wheel no longer
// gives it the focus, and passes a wheel over an unfocused one on to its parent (the dock's scroll area).
#include <QObject>

namespace multidir::ui {

class WheelNeedsFocus : public QObject {
 public:
  explicit WheelNeedsFocus(QObject* parent = nullptr) : QObject(parent) {}

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;
};

}  // namespace multidir::ui

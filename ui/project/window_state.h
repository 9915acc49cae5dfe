#pragma once
// The main window's geometry and the layout of its docks and toolbars, kept in QSettings ("window/geometry",
// "window/state") between runs. Docks and toolbars are matched by objectName, so each needs one.
class QMainWindow;

namespace multidir::ui {

// Call when the window closes.
void saveWindowState(const QMainWindow& window);
// Call once the docks and toolbars exist; false when nothing was saved or what was saved does not fit.
bool restoreWindowState(QMainWindow& window);

}  // namespace multidir::ui

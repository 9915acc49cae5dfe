#pragma once
// The main window's geometry and the layout of its docks and toolbars, kept in QSettings ("window/geometry",
// "window/state") between runs. Docks and toolbars are matched by objectName, so each needs one.
#include <QSize>

class QMainWindow;

namespace multidir::ui {

// The studio's preferred size for a new window, where the screen has room for it.
inline constexpr QSize kPreferredWindowSize{1480, 900};
// The size a new window opens at (nothing restored): kPreferredWindowSize, shrunk to fit inside `available` (the
// screen's available geometry) with room left for the window manager's frame and title bar, so the whole
// window, title bar included, is on screen (a 1280x720 projector, a 1366x768 laptop).
[[nodiscard]] QSize initialWindowSize(const QSize& available);

// Call when the window closes.
void saveWindowState(const QMainWindow& window);
// Call once the docks and toolbars exist; false when nothing was saved or what was saved does not fit.
bool restoreWindowState(QMainWindow& window);

}  // namespace multidir::ui

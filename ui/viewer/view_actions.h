#pragma once
// The 3D view's own actions, for the View menu and the View toolbar: the standard views (front, back, left,
// right, top, bottom, isometric), the orthographic toggle and the measuring tool, each with its shortcut.
// Shortcuts follow the numeric keypad's custom in 3D programs (both the keypad and the main row work): 1
// front, Ctrl+1 back, 3 right, Ctrl+3 left, 7 top, Ctrl+7 bottom, 0 isometric, 5 orthographic; M measures.
// A field being typed in keeps its digits: Qt gives text input precedence over plain-key shortcuts.
#include <QList>

class QAction;
class QMenu;
class QToolBar;

namespace multidir::ui {

class MeshViewerWidget;

struct ViewActions {
  QList<QAction*> standardViews;  // front, back, left, right, top, bottom, isometric
  QAction* orthographic = nullptr;  // checkable; follows the view
  QAction* measure = nullptr;       // checkable; follows the view (Esc ends measuring)
};

// Creates the actions (parented to `viewer`'s window, object names "view<Name>", "orthographicView",
// "measureDistance"), adds them to `menu` (a "Standard views" submenu, then the two toggles) and `toolBar`.
ViewActions addViewActions(MeshViewerWidget* viewer, QMenu* menu, QToolBar* toolBar);

}  // namespace multidir::ui

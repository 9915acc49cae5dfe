#include "ui/viewer/view_actions.h"

#include <QAction>
#include <QKeySequence>
#include <QMenu>
#include <QToolBar>

#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

// A key of the main row and the same digit on the keypad, each with `modifiers`.
QList<QKeySequence> digitKeys(Qt::Key digit, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
  return {QKeySequence(modifiers | digit), QKeySequence(modifiers | Qt::KeypadModifier | digit)};
}

}  // namespace

ViewActions addViewActions(MeshViewerWidget* viewer, QMenu* menu, QToolBar* toolBar) {
  QWidget* window = viewer->window();
  const struct {
    StandardView view;
    const char* name;
    QString text;
    QString toolTip;
    QList<QKeySequence> keys;
  } views[] = {
      {StandardView::Front, "viewFront", MeshViewerWidget::tr("&Front"), MeshViewerWidget::tr("Look at the model's front"),
       digitKeys(Qt::Key_1)},
      {StandardView::Back, "viewBack", MeshViewerWidget::tr("&Back"), MeshViewerWidget::tr("Look at the model's back"),
       digitKeys(Qt::Key_1, Qt::ControlModifier)},
      {StandardView::Left, "viewLeft", MeshViewerWidget::tr("&Left"), MeshViewerWidget::tr("Look at the model's left side"),
       digitKeys(Qt::Key_3, Qt::ControlModifier)},
      {StandardView::Right, "viewRight", MeshViewerWidget::tr("&Right"),
       MeshViewerWidget::tr("Look at the model's right side"), digitKeys(Qt::Key_3)},
      {StandardView::Top, "viewTop", MeshViewerWidget::tr("&Top"),
       MeshViewerWidget::tr("Look down the printing direction (Up)"), digitKeys(Qt::Key_7)},
      {StandardView::Bottom, "viewBottom", MeshViewerWidget::tr("Botto&m"),
       MeshViewerWidget::tr("Look up at the model from below the platform"), digitKeys(Qt::Key_7, Qt::ControlModifier)},
      {StandardView::Iso, "viewIso", MeshViewerWidget::tr("&Isometric"),
       MeshViewerWidget::tr("Look at the front, the right and the top equally"), digitKeys(Qt::Key_0)},
  };
  ViewActions actions;
  QMenu* standard = menu->addMenu(MeshViewerWidget::tr("&Standard views"));
  for (const auto& entry : views) {
    auto* action = new QAction(entry.text, window);
    action->setObjectName(QString::fromLatin1(entry.name));
    action->setShortcuts(entry.keys);
    action->setToolTip(QStringLiteral("%1 (%2)").arg(entry.toolTip, entry.keys.front().toString(QKeySequence::NativeText)));
    const StandardView view = entry.view;
    QObject::connect(action, &QAction::triggered, viewer, [viewer, view] { viewer->setStandardView(view); });
    standard->addAction(action);
    toolBar->addAction(action);
    actions.standardViews.push_back(action);
  }
  toolBar->addSeparator();

  actions.orthographic = menu->addAction(MeshViewerWidget::tr("&Orthographic"));
  actions.orthographic->setObjectName(QStringLiteral("orthographicView"));
  actions.orthographic->setCheckable(true);
  actions.orthographic->setShortcuts(digitKeys(Qt::Key_5));
  actions.orthographic->setToolTip(
      MeshViewerWidget::tr("Parallel projection: equal lengths look equal wherever they are (5)"));
  QObject::connect(actions.orthographic, &QAction::toggled, viewer, &MeshViewerWidget::setOrthographic);
  toolBar->addAction(actions.orthographic);

  actions.measure = menu->addAction(MeshViewerWidget::tr("M&easure distance"));
  actions.measure->setObjectName(QStringLiteral("measureDistance"));
  actions.measure->setCheckable(true);
  actions.measure->setShortcut(QKeySequence(Qt::Key_M));
  actions.measure->setToolTip(
      MeshViewerWidget::tr("Click two points on the model: their coordinates and the distance between them (M; Esc "
                           "ends)"));
  QObject::connect(actions.measure, &QAction::toggled, viewer, &MeshViewerWidget::setMeasuring);
  QObject::connect(viewer, &MeshViewerWidget::measuringChanged, actions.measure, &QAction::setChecked);
  toolBar->addAction(actions.measure);
  return actions;
}

}  // namespace multidir::ui

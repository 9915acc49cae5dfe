// MainWindow's part in plan editing: the Edit plan dock, the undo stack with its Edit menu, and the wiring
// between the editor, the viewer and the status bar. Kept apart from main_window.cpp so that editing is
// one place to read.
#include <QAction>
#include <QDockWidget>
#include <QKeySequence>
#include <QMenuBar>
#include <QStatusBar>
#include <QUndoStack>

#include "ui/edit/plan_editor.h"
#include "ui/main_window.h"
#include "ui/panels/plane_edit_panel.h"
#include "ui/panels/search_panel.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {

void MainWindow::buildPlanEditing() {
  m_planEditor = new PlanEditor(m_document->editHistory(), this);
  m_planeEditPanel = new PlaneEditPanel(m_planEditor, this);
  auto* dock = new QDockWidget(tr("Edit plan"), this);
  dock->setObjectName(QStringLiteral("editPlanDock"));
  dock->setWidget(m_planeEditPanel);
  dock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
  addDockWidget(Qt::RightDockWidgetArea, dock);
  tabifyDockWidget(m_planDock, dock);

  // An edited plan is shown like a searched one, and the Search panel's J_G and verdict follow it (unless a
  // new search is running, whose read-out that is).
  connect(m_planEditor, &PlanEditor::planEvaluated, this, [this](const SearchRun& run) {
    showPlan(run, PlanChange::Edit);
    if (!isSearching()) m_searchPanel->searchFinished(*run.plan);
  });
  connect(m_planEditor, &PlanEditor::selectionChanged, m_viewer, &MeshViewerWidget::setSelectedPlane);
  // A click on a plane's disc in the view selects it; a disc of a plane the editor does not have (the view
  // still shows the plan before a deletion) changes nothing.
  connect(m_viewer, &MeshViewerWidget::clippingPlaneClicked, m_planEditor, [this](int plane) {
    if (plane >= 0 && static_cast<std::size_t>(plane) < m_planEditor->state().planes.size()) {
      m_planEditor->selectPlane(plane);
    }
  });
  // A refusal is also said in the status bar, and taken back from there once an edit is accepted.
  connect(m_planEditor, &PlanEditor::refusalChanged, this,
          [this, said = QString()](const QString& message, const QString& detail) mutable {
            if (message.isEmpty()) {
              if (!said.isEmpty() && statusBar()->currentMessage() == said) {
                statusBar()->clearMessage();
                statusBar()->setToolTip(QString());
              }
            } else {
              statusBar()->showMessage(message);
              statusBar()->setToolTip(detail);
            }
            said = message;
          });
}

void MainWindow::buildEditMenu() {
  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  // Their texts follow the stack: "Undo Move plane 2".
  QAction* undo = undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setObjectName(QStringLiteral("undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setObjectName(QStringLiteral("redo"));
  redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
  edit->addAction(undo);
  edit->addAction(redo);
}

}  // namespace multidir::ui

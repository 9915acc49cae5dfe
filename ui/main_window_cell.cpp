// The robot cell in the studio (docs/robot-cell.md, "Studio"): the cell's section in the Machine tab, shown while
// the machine is "robot arm under a fixed extruder" (the paper's cell loaded when there is none yet), and the
// Cell view dock that poses the sliced job on the cell in the viewer and draws the cell section's reach map.
#include <QDockWidget>

#include "ui/main_window.h"
#include "ui/panels/cell_panel.h"
#include "ui/panels/cell_view_panel.h"
#include "ui/panels/machine_panel.h"

namespace multidir::ui {

void MainWindow::buildRobotCell(QDockWidget* besideDock) {
  m_cellPanel = new CellPanel(m_document, m_machinePanel);
  m_machinePanel->setCellSection(m_cellPanel);
  connect(m_machinePanel, &MachinePanel::robotCellChosen, m_cellPanel, [this](bool chosen) {
    if (chosen) m_cellPanel->ensureCell();
  });
  m_cellViewPanel = new CellViewPanel(m_document, m_viewer, this);
  // The reach map the cell section made is drawn in the cell view; a stale one goes from both.
  connect(m_cellPanel, &CellPanel::reachMapChanged, m_cellViewPanel,
          [this] { m_cellViewPanel->setReachMap(m_cellPanel->reachMap(), m_cellPanel->reachMapGoneText()); });
  auto* dock = new QDockWidget(tr("Cell view"), this);
  dock->setObjectName(QStringLiteral("cellViewDock"));
  dock->setWidget(m_cellViewPanel);
  dock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
  addDockWidget(Qt::RightDockWidgetArea, dock);
  tabifyDockWidget(besideDock, dock);
  besideDock->raise();
}

}  // namespace multidir::ui

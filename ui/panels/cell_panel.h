#pragma once
// The robot cell in the Machine tab (machine "robot arm under a fixed extruder"; docs/robot-cell.md, "Studio"):
// the arm model, the fixed nozzle's tip and axis in the robot base frame, the flange-to-platform transform (the
// calibration), the table height; Load/Save of the cell file; the `cell check` result; and "Find extruder
// position", the reach map of the plan shown (robot/reach_map.h) run off the GUI thread with progress and
// Cancel, its best position offered for the nozzle.
//
// The cell lives in the studio document: the fields show document->cell() and every edit replaces it there.
// The reach map is this panel's result for the cell and the plan it was made for (the Cell view draws it): a new
// or edited plan, supports grown for it, or a cell changed in anything but its nozzle tip (ui/viewer/
// cell_reach_map.h: the map places the tip) drops it, and reachMapGoneText() says why.
#include <QWidget>
#include <array>
#include <memory>
#include <optional>

#include "multidir/robot/reach_map.h"
#include "ui/viewer/cell_reach_map.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace multidir::ui {

class CellJob;
class StudioDocument;

class CellPanel : public QWidget {
  Q_OBJECT

 public:
  CellPanel(StudioDocument* document, QWidget* parent = nullptr);

  // Reads the cell file into the document (parse errors shown in plain words naming the key; a cell with
  // problems is taken and its problems shown by the check). False and the document unchanged on a read error.
  bool loadCellFile(const QString& path);
  // Writes the document's cell; false with the reason shown when it cannot.
  bool saveCellFile(const QString& path);
  // The document has no cell yet: the shipped paper cell (resources/cells/ur5-fixed-extruder.json).
  void ensureCell();

  // "Find extruder position" for the plan shown; false (the reason shown) with no plan or no cell, or while
  // one runs.
  bool findExtruderPosition();
  void cancelReach();
  [[nodiscard]] bool isFindingPosition() const;
  // The last reach map's best position (nullopt: none yet, or the map was for another cell or plan).
  [[nodiscard]] const std::optional<robot::ReachPoint>& bestPosition() const { return m_best; }
  // The last reach map with the cell it was scored for (null: none yet, or dropped as stale).
  [[nodiscard]] const std::shared_ptr<const CellReachMap>& reachMap() const { return m_map; }
  // Why the last map was dropped ("" while one is kept, or before the first).
  [[nodiscard]] QString reachMapGoneText() const { return m_mapGone; }
  // Puts the nozzle tip at the best position ("Use this position").
  void useBestPosition();

  // What the panel says under the fields: the check, a load/save message, the reach result.
  [[nodiscard]] QString checkText() const;
  [[nodiscard]] QString messageText() const;
  [[nodiscard]] QString reachText() const;

 signals:
  // A reach map was made, or the one kept was dropped (reachMap(), reachMapGoneText()).
  void reachMapChanged();

 private:
  void showCell();
  void dropReachMap(const QString& why);
  void takeFields();
  void showMessage(const QString& text, bool error);

  StudioDocument* m_document;
  QComboBox* m_model = nullptr;
  std::array<QDoubleSpinBox*, 3> m_tip{};
  std::array<QDoubleSpinBox*, 3> m_axis{};
  std::array<QDoubleSpinBox*, 3> m_flangeMm{};
  std::array<QDoubleSpinBox*, 3> m_flangeDegrees{};
  QDoubleSpinBox* m_table = nullptr;
  QLabel* m_check = nullptr;
  QLabel* m_message = nullptr;
  QPushButton* m_find = nullptr;
  QPushButton* m_cancel = nullptr;
  QProgressBar* m_progress = nullptr;
  QLabel* m_reach = nullptr;
  QPushButton* m_use = nullptr;
  CellJob* m_job = nullptr;
  std::optional<robot::ReachPoint> m_best;
  std::shared_ptr<const CellReachMap> m_map;
  QString m_mapGone;
  bool m_showing = false;  // fields being set from the document: their signals are not edits
};

}  // namespace multidir::ui

#pragma once
// The sliced job on the robot cell, in the viewer (docs/robot-cell.md, "Studio"): "Show on the cell" converts
// the document's sliced job for the document's cell off the GUI thread (robot::robotJobMotion: the poses the
// robot programs command, with progress and Cancel) and hands it to the viewer's cell view; a slider runs over
// every move of every step, Play/Pause steps through them, and the steps the conversion refuses are listed
// with their line and reason (the viewer draws their red markers).
//
// The reach map "Find extruder position" made (CellPanel::reachMap) is drawn in the same view, over the job when
// one is shown, else over the cell alone with the arm at home; "Show the reach map" hides and shows it, and the
// panel says what it shows or why the map went (a changed plan or cell: no stale map is drawn).
#include <QWidget>
#include <memory>

#include "ui/viewer/cell_motion.h"
#include "ui/viewer/cell_reach_map.h"

class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSlider;
class QTimer;

namespace multidir::ui {

class CellJob;
class MeshViewerWidget;
class StudioDocument;

class CellViewPanel : public QWidget {
  Q_OBJECT

 public:
  CellViewPanel(StudioDocument* document, MeshViewerWidget* viewer, QWidget* parent = nullptr);

  // Starts converting the sliced job for the cell; false (the reason shown) without a sliced job or a cell, or
  // while one runs.
  bool showOnCell();
  void cancel();
  [[nodiscard]] bool isConverting() const;
  // Ends the cell view.
  void hideCellView();
  [[nodiscard]] const CellMotion* motion() const { return m_motion.get(); }
  [[nodiscard]] QString statusText() const;
  [[nodiscard]] QString warningsText() const;

  // The reach map to draw (null: none; `goneText` then says why, "" when there simply is none). A new map is
  // shown at once.
  void setReachMap(std::shared_ptr<const CellReachMap> map, const QString& goneText);
  [[nodiscard]] const CellReachMap* reachMap() const { return m_reachMap.get(); }
  // "Show the reach map": draws the map in the cell view (entering it with the cell alone when no job is shown)
  // or hides it.
  void setReachMapShown(bool shown);
  [[nodiscard]] bool isReachMapShown() const;
  [[nodiscard]] QString reachStatusText() const;

 private:
  void setMotion(std::shared_ptr<const CellMotion> motion);
  // What the viewer draws: the job's motion, or the cell alone under a reach map shown, and the map.
  void showInViewer();
  void showPosition(int index);
  void updateEnabled();

  StudioDocument* m_document;
  MeshViewerWidget* m_viewer;
  QPushButton* m_show = nullptr;
  QPushButton* m_cancel = nullptr;
  QPushButton* m_hide = nullptr;
  QProgressBar* m_progress = nullptr;
  QSlider* m_slider = nullptr;
  QPushButton* m_play = nullptr;
  QLabel* m_position = nullptr;
  QLabel* m_status = nullptr;
  QLabel* m_warnings = nullptr;
  QTimer* m_timer = nullptr;
  QCheckBox* m_reachShown = nullptr;
  QLabel* m_reachStatus = nullptr;
  CellJob* m_job = nullptr;
  std::shared_ptr<const CellMotion> m_motion;
  std::shared_ptr<const CellReachMap> m_reachMap;
};

}  // namespace multidir::ui

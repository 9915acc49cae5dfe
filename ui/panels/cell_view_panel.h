#pragma once
// The sliced job on the robot cell, in the viewer (docs/robot-cell.md, "Studio"): "Show on the cell" converts
// the document's sliced job for the document's cell off the GUI thread (robot::robotJobMotion: the poses the
// robot programs command, with progress and Cancel) and hands it to the viewer's cell view; a slider runs over
// every move of every step, Play/Pause steps through them, and the steps the conversion refuses are listed
// with their line and reason (the viewer draws their red markers).
#include <QWidget>
#include <memory>

#include "ui/viewer/cell_motion.h"

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

 private:
  void setMotion(std::shared_ptr<const CellMotion> motion);
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
  CellJob* m_job = nullptr;
  std::shared_ptr<const CellMotion> m_motion;
};

}  // namespace multidir::ui

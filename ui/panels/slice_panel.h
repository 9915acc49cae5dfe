#pragma once
// The G-code part of the Plan dock: the Slice button, the running job's progress ("Slicing step 2 of 3") and
// its Cancel button, what went wrong, the estimates table (per step: print time and filament; the total; the
// whole model printed along up with the slicer's supports, when sliced for comparison) and the audit's
// unsupported extrusion under it, Export G-code, and
// the preview's controls (Preview G-code, the layer slider, travel moves).
//
// The panel only shows and collects; SliceSession (ui/slicing) runs the job and drives the viewer.
#include <QString>
#include <QWidget>
#include <optional>

#include "multidir/slicing/slice_job.h"

class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSlider;
class QTableWidget;

namespace multidir::ui {

struct GcodePreview;

class SlicePanel : public QWidget {
  Q_OBJECT

 public:
  explicit SlicePanel(QWidget* parent = nullptr);

  // Estimates table rows carry their kind in Qt::UserRole of column 0.
  enum class RowKind { Step = 1, Total = 2, FixedDirection = 3 };
  // Column 1 carries the print time in seconds in Qt::UserRole.
  static constexpr int kTimeColumn = 1;

  // Whether Slice can start (a plan is shown whose supports are not being grown) and, when not, why.
  void setSliceable(bool sliceable, const QString& reason = QString());
  void showRunning(bool running);
  void showProgress(double fraction, const QString& stage);
  // A finished job: its estimates, Export and Preview enabled; `layers` the preview's layer count.
  void showResult(const slicing::SlicedJob& job, int layers);
  // The audit's unsupported extrusion under the estimates ("Unsupported extrusion: 12.3 mm (0.4 %) in
  // magenta", the preview's warning colour); hidden when the audit did not run.
  void showUnsupported(bool audited, double unsupportedMm, double percent);
  // Drops the shown result (the plan changed, or a new job starts): table emptied, Export and Preview off.
  void clearResult();
  // A message under the buttons: an error (`detail` kept in full, selectable) or a plain note.
  void showMessage(const QString& headline, const QString& detail = QString(), bool error = true);
  // The preview's state as the viewer shows it (the button is checked while it shows).
  void setPreviewShown(bool shown);
  // The layer slider's position (1..layers) and what that layer is.
  void setLayerText(const QString& text);
  // The height of the slider's layer (the nozzle's printer Z in its step's pose, mm; docs/slicing.md,
  // "Preview"), shown beside the slider; nullopt shows nothing.
  void setLayerZ(std::optional<double> zMm);

  [[nodiscard]] QTableWidget* estimatesTable() const { return m_table; }
  [[nodiscard]] QPushButton* sliceButton() const { return m_slice; }
  [[nodiscard]] QPushButton* cancelButton() const { return m_cancel; }
  [[nodiscard]] QPushButton* exportButton() const { return m_export; }
  [[nodiscard]] QPushButton* previewButton() const { return m_preview; }
  [[nodiscard]] QSlider* layerSlider() const { return m_layers; }
  [[nodiscard]] QLabel* layerZLabel() const { return m_layerZ; }
  [[nodiscard]] QCheckBox* travelBox() const { return m_travel; }
  [[nodiscard]] QLabel* messageLabel() const { return m_message; }
  [[nodiscard]] QLabel* stageLabel() const { return m_stage; }
  [[nodiscard]] QLabel* unsupportedLabel() const { return m_unsupported; }

 signals:
  void sliceClicked();
  void cancelClicked();
  void exportClicked();
  void previewToggled(bool shown);
  void layerLimitChanged(int layers);
  void travelVisibleChanged(bool visible);

 private:
  void updatePreviewControls();

  QPushButton* m_slice = nullptr;
  QPushButton* m_cancel = nullptr;
  QProgressBar* m_progress = nullptr;
  QLabel* m_stage = nullptr;
  QLabel* m_message = nullptr;
  QTableWidget* m_table = nullptr;
  QLabel* m_unsupported = nullptr;
  QLabel* m_slowerNote = nullptr;  // why the multi-directional job takes longer than the fixed direction
  QPushButton* m_export = nullptr;
  QPushButton* m_preview = nullptr;
  QSlider* m_layers = nullptr;
  QLabel* m_layerText = nullptr;
  QLabel* m_layerZ = nullptr;
  QCheckBox* m_travel = nullptr;
  bool m_sliceable = false;
  bool m_running = false;
  bool m_hasResult = false;
};

}  // namespace multidir::ui

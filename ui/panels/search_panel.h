#pragma once
// The Search panel: the search's parameters (scheme, beam width, w, region scales, normals, offset step,
// alpha_max, min. region height, min. gain per plane, and for 4-DOF machines how many rotation axes to try), Run and Cancel, a progress bar, a live read-out (level,
// beams alive, best J_G, candidates scored), a chart of the best J_G per level, and what the result means
// (support-free or not, improved or not, cancelled).
//
// The panel only shows and collects; MainWindow runs the search (SearchJob) and feeds the panel.
#include <QElapsedTimer>
#include <QWidget>
#include <optional>

#include "multidir/core/search/decomposition.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTimer;

namespace multidir::ui {

class JgChart;

class SearchPanel : public QWidget {
  Q_OBJECT

 public:
  explicit SearchPanel(QWidget* parent = nullptr);

  [[nodiscard]] core::SearchOptions searchOptions() const;
  void setSearchOptions(const core::SearchOptions& options);
  // 4-DOF rotation axes to try (0: only the machine's own axis).
  [[nodiscard]] int axisSearchCount() const;
  void setAxisSearchCount(int count);
  // The axis-search count is offered for 4-DOF machines only.
  void setRotaryMachine(bool rotary);
  // The price of a part (SearchOptions::partCostMm2 and cutFaceCost, docs/apart.md) is offered for the apart
  // machine only.
  void setApartMachine(bool apart);
  // alpha_max, the same value as the Overhangs panel's (MainWindow links the two).
  [[nodiscard]] double alphaMaxDegrees() const;
  void setAlphaMaxDegrees(double degrees);
  // Run is offered only when a model is shown and the machine is valid; `reason` says why not.
  void setRunnable(bool runnable, const QString& reason);

  // A search started: clears the read-out and the chart, swaps Run for Cancel. `maxLevels` is
  // core::maxSearchLevels of its options. While it runs the progress bar says where it is: "Level k of n",
  // beams alive, best J_G, candidates scored and the time it has taken, updated every second.
  void searchStarted(double jgBeforeMm2, int maxLevels = 0);
  void showFraction(double fraction, const QString& phase);
  void showProgress(const core::SearchProgress& progress);
  void cancelRequested();
  // The search ended with `plan` (complete or cancelled), or failed.
  void searchFinished(const core::Decomposition& plan);
  void searchFailed(const QString& headline, const QString& detail);
  // After searchFinished: its plan was not shown, the plan shown was kept; the notice says `text` (why).
  void noteKeptPlan(const QString& text);
  // The search was stopped and its result dropped (another model is being opened): nothing of it stays.
  void searchDropped();
  // A new model is shown: the read-out, chart and notice of the previous model's search are cleared.
  void clearResult();

  // What the notice line says (for tests and the status bar).
  [[nodiscard]] QString noticeText() const;
  [[nodiscard]] QString readoutText() const;
  // The progress bar's text, whole (the bar shows it elided to its width, and whole in its tooltip).
  [[nodiscard]] QString progressText() const;
  // Points on the best-J_G chart.
  [[nodiscard]] int chartPointCount() const;

 signals:
  void runClicked();
  void cancelClicked();
  void alphaMaxChanged(double degrees);
  // A setting was edited (by the user or setSearchOptions / setAxisSearchCount).
  void settingsChanged();

 private:
  void setRunning(bool running);
  // Beam width and scales mean something to the beam scheme only: editable when it is chosen and no search runs.
  void updateBeamOnlyControls();
  // "Also the finalists" means something only while polishing is on: editable then, when no search runs.
  void updatePolishFinalists();
  void showNotice(const QString& text, bool warning);
  void updateProgressText();
  // The progress bar says `text` ("%p" stands for the percentage), elided to its width when it does not fit,
  // whole in its tooltip.
  void setProgressText(const QString& text);
  void showProgressText();
  bool eventFilter(QObject* watched, QEvent* event) override;
  void resetReadout();

  QComboBox* m_scheme = nullptr;
  QSpinBox* m_beamWidth = nullptr;
  QDoubleSpinBox* m_minVolumeDivisor = nullptr;
  QSpinBox* m_volumeScales = nullptr;
  QLabel* m_beamWidthLabel = nullptr;
  QLabel* m_volumeScalesLabel = nullptr;
  QSpinBox* m_normals = nullptr;
  QDoubleSpinBox* m_partCost = nullptr;
  QDoubleSpinBox* m_cutFaceCost = nullptr;
  QLabel* m_partCostLabel = nullptr;
  QLabel* m_cutFaceCostLabel = nullptr;
  QDoubleSpinBox* m_offsetStep = nullptr;
  QDoubleSpinBox* m_alpha = nullptr;
  QDoubleSpinBox* m_minRegionHeight = nullptr;
  QDoubleSpinBox* m_minPlaneGain = nullptr;
  QSpinBox* m_polishEffort = nullptr;  // 0: off, else SearchOptions::polishEffort
  QCheckBox* m_polishFinalists = nullptr;  // SearchOptions::polishFinalists, with polishing on
  QCheckBox* m_searchTails = nullptr;      // SearchOptions::searchTails
  QSpinBox* m_axisCount = nullptr;
  QLabel* m_axisCountLabel = nullptr;
  QPushButton* m_run = nullptr;
  QPushButton* m_cancel = nullptr;
  QProgressBar* m_progress = nullptr;
  QString m_progressText;  // whole, "%p" not yet replaced
  QLabel* m_level = nullptr;
  QLabel* m_beams = nullptr;
  QLabel* m_bestJg = nullptr;
  QLabel* m_candidates = nullptr;
  QLabel* m_notice = nullptr;
  JgChart* m_chart = nullptr;
  core::SearchOptions m_hidden;  // options the panel does not edit keep their values
  double m_jgBefore = 0.0;
  bool m_runnable = false;
  bool m_running = false;
  bool m_cancelling = false;
  int m_maxLevels = 0;
  QString m_phase;                               // core's phase when it is not the search itself
  std::optional<core::SearchProgress> m_latest;  // of the running search
  QElapsedTimer m_clock;                         // since the search started
  QTimer* m_tick = nullptr;                      // refreshes the elapsed time
};

}  // namespace multidir::ui

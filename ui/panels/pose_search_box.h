#pragma once
// The Machine panel's "Best pose" group: how many poses to try and to search fully, "Find best pose" and
// Cancel, the progress (cheap scores first, then full searches) and a table of the poses tried, one row per
// core::PoseTrial in the order core returns them, the chosen one marked (bold, "chosen" in its row header).
// Clicking a row asks to preview that pose (poseClicked); "Use this pose" asks to make it the model's up
// (useClicked); "Show current up" ends a preview. The box only shows and asks: MainWindow runs the search and
// applies the pose.
#include <QGroupBox>
#include <QString>

#include "multidir/core/search/pose_search.h"
#include "ui/jobs/pose_search_job.h"

class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace multidir::ui {

class PoseSearchBox : public QGroupBox {
  Q_OBJECT

 public:
  // Table columns.
  enum Column {
    SourceColumn,
    UpColumn,
    ContactColumn,
    MarginColumn,
    RiskyColumn,
    JgColumn,
    RegionsColumn,
    SearchColumn,
    ColumnCount
  };

  explicit PoseSearchBox(QWidget* parent = nullptr);

  // The pose counts as entered (cheap scheme: core's default, greedy).
  [[nodiscard]] core::PoseOptions poseOptions() const;
  void setPoseOptions(int poses, int fullSearches);

  // Whether "Find best pose" may start now; `reason` (tooltip) says why not.
  void setRunnable(bool runnable, const QString& reason);
  void searchStarted();
  void showProgress(double fraction, PoseSearchJob::Phase phase);
  void cancelRequested();
  // The poses tried (a cancelled search lists the ones that finished as scored, the others as not scored).
  void showResult(const core::PoseSearchResult& result, bool cancelled);
  // The search could not run or ended without a result; the table keeps nothing of it.
  void showFailure(const QString& headline, const QString& detail);
  // A new model or a dropped search: empties the table and the status.
  void clear();
  // Says which trial is the model's up now (-1: none of them): its Search column tells "in use".
  void setTrialInUse(int trial);

  // Trials listed (rows), the chosen one (-1 when none) and the one selected (-1 when none).
  [[nodiscard]] int trialCount() const;
  [[nodiscard]] int chosenTrial() const { return m_chosen; }
  [[nodiscard]] int selectedTrial() const;
  [[nodiscard]] QTableWidget* table() const { return m_table; }
  [[nodiscard]] QString statusText() const;

 signals:
  void findClicked();
  void cancelClicked();
  // A row was clicked: preview that trial's pose.
  void poseClicked(int trial);
  // "Use this pose" with `trial` selected.
  void useClicked(int trial);
  void showCurrentClicked();

 private:
  void updateButtons();

  QSpinBox* m_poses = nullptr;
  QSpinBox* m_fullSearches = nullptr;
  QPushButton* m_find = nullptr;
  QPushButton* m_cancel = nullptr;
  QProgressBar* m_progress = nullptr;
  QLabel* m_status = nullptr;
  QTableWidget* m_table = nullptr;
  QPushButton* m_use = nullptr;
  QPushButton* m_showCurrent = nullptr;
  bool m_runnable = false;
  bool m_running = false;
  int m_chosen = -1;
  std::vector<bool> m_scored;  // per trial: it finished at least its cheap plan
};

}  // namespace multidir::ui

#pragma once
// The job timeline of the Hardware panel: one row per step of the print run (its region) with what the step
// is doing (waiting, moving, settling, printing, done, paused with the reason, failed, aborted) and when it
// started and ended, following the sequencer's log as it happens.
//
// Rows follow the log entries (hardware::PrintRunLogEntry: the step and state after each event, wall-clock
// time): a step the run went past is done; the step an entry names takes the entry's state.
//
// Thread: GUI thread.
#include <QDateTime>
#include <QString>
#include <QWidget>
#include <optional>
#include <vector>

#include "multidir/hardware/print_run.h"

class QTableWidget;

namespace multidir::ui {

enum class StepPhase { Waiting, Moving, Settling, Printing, Done, Paused, Failed, Aborted };

struct TimelineRow {
  QString region;  // the step's region file
  StepPhase phase = StepPhase::Waiting;
  std::optional<QDateTime> started;  // the first time the run turned the platform for the step
  std::optional<QDateTime> ended;    // done, failed or aborted
  QString reason;                    // why paused, failed or aborted ("" otherwise)
};

// Applies one log entry to `rows` (one per step). `reason`: why the run paused, failed or stopped.
void applyRunEvent(std::vector<TimelineRow>& rows, const hardware::PrintRunLogEntry& entry, const QString& reason);

class JobTimeline : public QWidget {
  Q_OBJECT

 public:
  explicit JobTimeline(QWidget* parent = nullptr);

  // A new run of `steps`: every row waiting.
  void reset(const std::vector<hardware::PrintStep>& steps);
  void apply(const hardware::PrintRunLogEntry& entry, const QString& reason);

  [[nodiscard]] const std::vector<TimelineRow>& rows() const { return m_rows; }
  // "waiting", "moving", ..., translated.
  static QString phaseText(StepPhase phase);

 private:
  void refresh();

  QTableWidget* m_table = nullptr;
  std::vector<TimelineRow> m_rows;
};

}  // namespace multidir::ui

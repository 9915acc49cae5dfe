#include "ui/device/job_timeline.h"

#include <QBrush>
#include <QColor>
#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>
#include <chrono>

#include "ui/device/device_reading.h"

namespace multidir::ui {
namespace {

enum Column { kStep, kRegion, kState, kStarted, kEnded, kColumns };

QString timeText(const std::optional<QDateTime>& time) {
  return time ? DeviceReading::clockTime(*time) : QStringLiteral("—");
}

QDateTime wallTime(const hardware::PrintRunLogEntry& entry) {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(entry.wallTime.time_since_epoch());
  return QDateTime::fromMSecsSinceEpoch(ms.count());
}

bool finished(StepPhase phase) {
  return phase == StepPhase::Done || phase == StepPhase::Failed || phase == StepPhase::Aborted;
}

QColor phaseColour(StepPhase phase) {
  switch (phase) {
    case StepPhase::Done:
      return QColor(0x2e, 0x7d, 0x32);
    case StepPhase::Paused:
      return QColor(0xb2, 0x6a, 0x00);
    case StepPhase::Failed:
    case StepPhase::Aborted:
      return QColor(0xc6, 0x28, 0x28);
    default:
      return {};
  }
}

}  // namespace

void applyRunEvent(std::vector<TimelineRow>& rows, const hardware::PrintRunLogEntry& entry, const QString& reason) {
  if (entry.step >= rows.size()) return;
  const QDateTime at = wallTime(entry);
  // The run went past these steps: they were printed (by the printer or, after Region done, by hand).
  for (std::size_t k = 0; k < entry.step; ++k) {
    TimelineRow& row = rows[k];
    if (finished(row.phase)) continue;
    row.phase = StepPhase::Done;
    row.reason.clear();
    if (!row.ended) row.ended = at;
  }
  TimelineRow& row = rows[entry.step];
  const auto under = [&](StepPhase phase) {
    row.phase = phase;
    row.reason.clear();
    row.ended.reset();
    if (!row.started) row.started = at;
  };
  switch (entry.state) {
    case hardware::PrintRunState::Idle:
      break;
    case hardware::PrintRunState::Moving:
      under(StepPhase::Moving);
      break;
    case hardware::PrintRunState::Settling:
      under(StepPhase::Settling);
      break;
    case hardware::PrintRunState::Printing:
      under(StepPhase::Printing);
      break;
    case hardware::PrintRunState::Paused:
      // Later entries while paused (a stop confirmed) keep the reason it paused for.
      if (row.phase != StepPhase::Paused || row.reason.isEmpty()) row.reason = reason;
      row.phase = StepPhase::Paused;
      break;
    case hardware::PrintRunState::Faulted:
      if (row.phase == StepPhase::Failed) break;  // a later entry of the same fault
      row.phase = StepPhase::Failed;
      row.reason = reason;
      row.ended = at;
      break;
    case hardware::PrintRunState::Completed:
      if (row.phase != StepPhase::Done) row.ended = at;
      row.phase = StepPhase::Done;
      row.reason.clear();
      break;
    case hardware::PrintRunState::Aborted:
      // Later entries of an aborted run (a stop confirmed) keep the time it ended.
      if (finished(row.phase)) break;
      row.phase = StepPhase::Aborted;
      row.reason = reason;
      row.ended = at;
      break;
  }
}

JobTimeline::JobTimeline(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("jobTimeline"));
  m_table = new QTableWidget(0, kColumns, this);
  m_table->setObjectName(QStringLiteral("jobTimelineTable"));
  m_table->setHorizontalHeaderLabels({tr("Step"), tr("Region"), tr("State"), tr("Started"), tr("Ended")});
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_table->setSelectionMode(QAbstractItemView::NoSelection);
  m_table->verticalHeader()->hide();
  m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_table->horizontalHeader()->setSectionResizeMode(kState, QHeaderView::Stretch);
  m_table->setWordWrap(true);
  m_table->setMinimumHeight(90);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(m_table);
}

void JobTimeline::reset(const std::vector<hardware::PrintStep>& steps) {
  m_rows.assign(steps.size(), TimelineRow{});
  for (std::size_t k = 0; k < steps.size(); ++k) m_rows[k].region = QString::fromStdString(steps[k].regionFile);
  refresh();
}

void JobTimeline::apply(const hardware::PrintRunLogEntry& entry, const QString& reason) {
  applyRunEvent(m_rows, entry, reason);
  refresh();
}

QString JobTimeline::phaseText(StepPhase phase) {
  switch (phase) {
    case StepPhase::Waiting:
      return tr("waiting");
    case StepPhase::Moving:
      return tr("moving");
    case StepPhase::Settling:
      return tr("settling");
    case StepPhase::Printing:
      return tr("printing");
    case StepPhase::Done:
      return tr("done");
    case StepPhase::Paused:
      return tr("paused");
    case StepPhase::Failed:
      return tr("failed");
    case StepPhase::Aborted:
      return tr("aborted");
  }
  return {};
}

void JobTimeline::refresh() {
  m_table->setRowCount(static_cast<int>(m_rows.size()));
  for (int r = 0; r < static_cast<int>(m_rows.size()); ++r) {
    const TimelineRow& row = m_rows[static_cast<std::size_t>(r)];
    QString state = phaseText(row.phase);
    if (!row.reason.isEmpty()) state = tr("%1: %2").arg(state, row.reason);
    const QString cells[kColumns] = {QString::number(r + 1), row.region, state, timeText(row.started),
                                     timeText(row.ended)};
    for (int c = 0; c < kColumns; ++c) {
      auto* item = m_table->item(r, c);
      if (!item) {
        item = new QTableWidgetItem;
        m_table->setItem(r, c, item);
      }
      item->setText(cells[c]);
      if (c == kState) {
        item->setToolTip(state);
        const QColor colour = phaseColour(row.phase);
        item->setForeground(colour.isValid() ? QBrush(colour) : QBrush());
      }
    }
  }
  m_table->resizeRowsToContents();
}

}  // namespace multidir::ui

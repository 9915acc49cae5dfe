#include "ui/panels/cell_view_panel.h"

#include <QCheckBox>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>

#include "ui/document/studio_document.h"
#include "ui/jobs/cell_job.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

// Play: the slider runs through the job in about this many ticks of kPlayTickMs, whatever its length.
constexpr int kPlayTicks = 600;
constexpr int kPlayTickMs = 40;

}  // namespace

CellViewPanel::CellViewPanel(StudioDocument* document, MeshViewerWidget* viewer, QWidget* parent)
    : QWidget(parent), m_document(document), m_viewer(viewer) {
  setObjectName(QStringLiteral("cellViewPanel"));
  m_show = new QPushButton(tr("Show on the cell"), this);
  m_show->setObjectName(QStringLiteral("cellViewShow"));
  m_show->setToolTip(tr("The sliced job on the robot cell: the arm, the platform and the part at the poses the "
                        "robot programs command (multidir robot-program)"));
  m_cancel = new QPushButton(tr("Cancel"), this);
  m_cancel->setObjectName(QStringLiteral("cellViewCancel"));
  m_cancel->hide();
  m_hide = new QPushButton(tr("Back to the plan"), this);
  m_hide->setObjectName(QStringLiteral("cellViewHide"));
  m_progress = new QProgressBar(this);
  m_progress->setObjectName(QStringLiteral("cellViewProgress"));
  m_progress->setRange(0, 1000);
  m_progress->hide();
  m_slider = new QSlider(Qt::Horizontal, this);
  m_slider->setObjectName(QStringLiteral("cellViewSlider"));
  m_slider->setRange(0, 0);
  m_play = new QPushButton(tr("Play"), this);
  m_play->setObjectName(QStringLiteral("cellViewPlay"));
  m_play->setCheckable(true);
  m_position = new QLabel(this);
  m_position->setObjectName(QStringLiteral("cellViewPosition"));
  m_status = new QLabel(this);
  m_status->setObjectName(QStringLiteral("cellViewStatus"));
  m_status->setWordWrap(true);
  m_warnings = new QLabel(this);
  m_warnings->setObjectName(QStringLiteral("cellViewWarnings"));
  m_warnings->setWordWrap(true);
  m_warnings->setStyleSheet(QStringLiteral("color: #d03030;"));
  m_timer = new QTimer(this);
  m_timer->setInterval(kPlayTickMs);
  m_reachShown = new QCheckBox(tr("Show the reach map"), this);
  m_reachShown->setObjectName(QStringLiteral("cellViewReachMap"));
  m_reachShown->setToolTip(tr("The nozzle positions \"Find extruder position\" scored (Machine tab), coloured from "
                              "red (none of the plan's poses reachable with margin) to blue (all of them); the best "
                              "one ringed in white"));
  m_reachShown->setEnabled(false);
  m_reachStatus = new QLabel(this);
  m_reachStatus->setObjectName(QStringLiteral("cellViewReachStatus"));
  m_reachStatus->setWordWrap(true);
  m_job = new CellJob(this);

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_show);
  buttons->addWidget(m_cancel);
  buttons->addWidget(m_hide);
  auto* run = new QHBoxLayout;
  run->addWidget(m_play);
  run->addWidget(m_slider, 1);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(buttons);
  layout->addWidget(m_progress);
  layout->addLayout(run);
  layout->addWidget(m_position);
  layout->addWidget(m_status);
  layout->addWidget(m_warnings);
  layout->addWidget(m_reachShown);
  layout->addWidget(m_reachStatus);
  layout->addStretch(1);

  connect(m_show, &QPushButton::clicked, this, &CellViewPanel::showOnCell);
  connect(m_cancel, &QPushButton::clicked, this, &CellViewPanel::cancel);
  connect(m_hide, &QPushButton::clicked, this, &CellViewPanel::hideCellView);
  connect(m_slider, &QSlider::valueChanged, this, &CellViewPanel::showPosition);
  connect(m_reachShown, &QCheckBox::toggled, this, [this] { showInViewer(); });
  connect(m_play, &QPushButton::toggled, this, [this](bool on) {
    m_play->setText(on ? tr("Pause") : tr("Play"));
    if (on && m_slider->value() >= m_slider->maximum()) m_slider->setValue(0);
    if (on) {
      m_timer->start();
    } else {
      m_timer->stop();
    }
  });
  connect(m_timer, &QTimer::timeout, this, [this] {
    const int step = std::max(1, (m_slider->maximum() + 1) / kPlayTicks);
    if (m_slider->value() >= m_slider->maximum()) {
      m_play->setChecked(false);
      return;
    }
    m_slider->setValue(std::min(m_slider->maximum(), m_slider->value() + step));
  });
  connect(m_job, &CellJob::progressed, this, [this](double f) { m_progress->setValue(static_cast<int>(f * 1000)); });
  connect(m_job, &CellJob::cancelled, this, [this] {
    m_status->setText(tr("Cancelled."));
    updateEnabled();
  });
  // The motion belongs to the sliced job and the cell it was made for: either changing ends it.
  connect(m_document, &StudioDocument::slicedJobChanged, this, [this] {
    setMotion(nullptr);
    updateEnabled();
  });
  connect(m_document, &StudioDocument::cellChanged, this, [this] {
    if (m_motion) m_status->setText(tr("The cell changed: show the job on it again."));
    setMotion(nullptr);
    updateEnabled();
  });
  updateEnabled();
}

bool CellViewPanel::showOnCell() {
  if (m_job->isRunning()) return false;
  const auto& job = m_document->slicedJob();
  if (!m_document->cell()) {
    m_status->setText(tr("There is no robot cell: choose the machine \"robot arm under a fixed extruder\"."));
    return false;
  }
  if (!job || job->steps.empty()) {
    m_status->setText(tr("The plan is not sliced: slice it with the cell's profile (ur5-cell-0.8) first."));
    return false;
  }
  const std::filesystem::path folder =
      std::filesystem::path(job->steps.front().path).parent_path();
  auto result = std::make_shared<std::shared_ptr<CellMotion>>();
  auto motion = std::make_shared<CellMotion>();
  motion->cell = *m_document->cell();
  std::shared_ptr<const void> files = job->files;  // the job's folder stays while the work reads it
  const bool started = m_job->start([motion, result, folder, files](core::JobContext context) {
    auto steps = robot::robotJobMotion(folder, motion->cell, robot::RobotProgramOptions{}, context);
    if (!steps) return QString::fromStdString(steps.error().describe());
    motion->steps = std::move(*steps);
    *result = motion;
    return QString();
  });
  if (!started) return false;
  // One pair of connections per run: the result handler and the cancel handler each drop both.
  auto connection = std::make_shared<QMetaObject::Connection>();
  auto onCancel = std::make_shared<QMetaObject::Connection>();
  *connection = connect(m_job, &CellJob::finished, this, [this, result, connection, onCancel](const QString& error) {
    disconnect(*connection);
    disconnect(*onCancel);
    if (!error.isEmpty()) {
      m_status->setText(tr("The job cannot be posed on the cell: %1").arg(error));
      updateEnabled();
      return;
    }
    setMotion(*result);
    updateEnabled();
  });
  *onCancel = connect(m_job, &CellJob::cancelled, this, [connection, onCancel] {
    disconnect(*connection);
    disconnect(*onCancel);
  });
  m_progress->setValue(0);
  m_status->setText(tr("Converting the job for the cell..."));
  updateEnabled();
  return true;
}

void CellViewPanel::cancel() { m_job->cancel(); }

bool CellViewPanel::isConverting() const { return m_job->isRunning(); }

void CellViewPanel::hideCellView() {
  {
    const QSignalBlocker blocker(m_reachShown);  // back to the plan: the map is kept, not drawn
    m_reachShown->setChecked(false);
  }
  setMotion(nullptr);
}

void CellViewPanel::setReachMap(std::shared_ptr<const CellReachMap> map, const QString& goneText) {
  m_reachMap = std::move(map);
  m_reachShown->setEnabled(m_reachMap != nullptr);
  if (m_reachMap) {
    const robot::ReachPoint& best = m_reachMap->map.best;
    m_reachStatus->setText(tr("Reach map: %1 nozzle positions every %2 mm; the best, ringed, at %3, %4, %5 mm with "
                              "%6 % of the plan's poses reachable with margin.")
                               .arg(m_reachMap->map.points.size())
                               .arg(m_reachMap->gridMm, 0, 'f', 0)
                               .arg(best.nozzleTipMm.x(), 0, 'f', 0)
                               .arg(best.nozzleTipMm.y(), 0, 'f', 0)
                               .arg(best.nozzleTipMm.z(), 0, 'f', 0)
                               .arg(100.0 * best.score, 0, 'f', 1));
  } else {
    m_reachStatus->setText(goneText.isEmpty() ? QString() : tr("Reach map not shown: %1").arg(goneText));
  }
  const QSignalBlocker blocker(m_reachShown);
  m_reachShown->setChecked(m_reachMap != nullptr);
  showInViewer();
}

void CellViewPanel::setReachMapShown(bool shown) { m_reachShown->setChecked(shown && m_reachMap); }

bool CellViewPanel::isReachMapShown() const { return m_reachMap && m_reachShown->isChecked(); }

QString CellViewPanel::reachStatusText() const { return m_reachStatus->text(); }

void CellViewPanel::showInViewer() {
  const bool map = isReachMapShown() && m_document->cell();
  std::shared_ptr<const CellMotion> shown = m_motion;
  if (!shown && map) {
    auto alone = std::make_shared<CellMotion>();
    alone->cell = *m_document->cell();
    shown = alone;
  }
  m_viewer->setCellMotion(shown);
  if (shown) {
    m_viewer->setCellPosition(cellPositionAt(*shown, m_slider->value()));
    m_viewer->setCellReachMap(map ? m_reachMap : nullptr, tr("Plan's poses reachable with margin (%)"));
  }
}

void CellViewPanel::setMotion(std::shared_ptr<const CellMotion> motion) {
  m_play->setChecked(false);
  m_motion = std::move(motion);
  showInViewer();
  QString warnings;
  if (m_motion) {
    int moves = 0;
    for (const auto& step : m_motion->steps) {
      moves += static_cast<int>(step.samples.size());
      if (step.warning) warnings += (warnings.isEmpty() ? QString() : QStringLiteral("\n")) + QString::fromStdString(step.warning->text);
    }
    m_status->setText(tr("%n step(s) on the %1, %2 moves.", nullptr, static_cast<int>(m_motion->steps.size()))
                          .arg(QString::fromStdString(m_motion->cell.arm.name).toUpper())
                          .arg(moves));
  }
  m_warnings->setText(warnings);
  m_warnings->setVisible(!warnings.isEmpty());
  {
    const QSignalBlocker blocker(m_slider);
    m_slider->setRange(0, m_motion ? std::max(0, cellPositionCount(*m_motion) - 1) : 0);
    m_slider->setValue(0);
  }
  showPosition(0);
  updateEnabled();
}

void CellViewPanel::showPosition(int index) {
  if (!m_motion || m_motion->steps.empty()) {
    m_position->clear();
    return;
  }
  const CellPosition position = cellPositionAt(*m_motion, index);
  m_viewer->setCellPosition(position);
  const robot::StepMotion& step = m_motion->steps[static_cast<std::size_t>(position.step)];
  if (step.samples.empty()) {
    m_position->setText(tr("Step %1 of %2: no move converted (the arm at home).").arg(step.step).arg(m_motion->steps.size()));
    return;
  }
  const robot::MotionSample& sample = step.samples[static_cast<std::size_t>(position.sample)];
  m_position->setText(tr("Step %1 of %2, move %3 of %4 (%5, line %6)")
                          .arg(step.step)
                          .arg(m_motion->steps.size())
                          .arg(position.sample + 1)
                          .arg(step.samples.size())
                          .arg(QString::fromStdString(step.gcodeFile))
                          .arg(sample.line));
}

void CellViewPanel::updateEnabled() {
  const bool running = m_job->isRunning();
  m_show->setEnabled(!running);
  m_cancel->setVisible(running);
  m_progress->setVisible(running);
  m_hide->setEnabled(m_motion != nullptr);
  m_slider->setEnabled(m_motion != nullptr);
  m_play->setEnabled(m_motion != nullptr);
}

QString CellViewPanel::statusText() const { return m_status->text(); }
QString CellViewPanel::warningsText() const { return m_warnings->text(); }

}  // namespace multidir::ui

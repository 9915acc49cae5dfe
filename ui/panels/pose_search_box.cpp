#include "ui/panels/pose_search_box.h"

#include <QFont>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "ui/common/table_columns.h"

namespace multidir::ui {
namespace {

QString area(double mm2) { return QLocale().toString(mm2, 'f', 1); }

QString upText(const core::Vec3& up) {
  auto number = [](double x) { return QLocale().toString(std::abs(x) < 5e-4 ? 0.0 : x, 'f', 2); };
  return QStringLiteral("%1, %2, %3").arg(number(up.x()), number(up.y()), number(up.z()));
}

QString sourceText(core::PoseSource source) {
  switch (source) {
    case core::PoseSource::Given: return PoseSearchBox::tr("given up");
    case core::PoseSource::Resting: return PoseSearchBox::tr("resting");
  }
  return {};
}

}  // namespace

PoseSearchBox::PoseSearchBox(QWidget* parent) : QGroupBox(tr("Best pose"), parent) {
  setObjectName(QStringLiteral("poseSearchBox"));
  const core::PoseOptions defaults;
  m_poses = new QSpinBox(this);
  m_poses->setObjectName(QStringLiteral("posesToTry"));
  m_poses->setRange(1, 200);
  m_poses->setValue(defaults.poses);
  m_poses->setToolTip(tr("Poses tried: the current up and the poses the model stands in on its own"));
  m_fullSearches = new QSpinBox(this);
  m_fullSearches->setObjectName(QStringLiteral("poseFullSearches"));
  m_fullSearches->setRange(1, defaults.poses);
  m_fullSearches->setValue(defaults.fullSearches);
  m_fullSearches->setToolTip(tr("Poses given the full search with the Search tab's settings: the current up first, "
                                "then the best-scored others. The others are scored with a quick greedy plan, "
                                "except those ruled out: poses no plan of which could beat the current up's"));
  connect(m_poses, QOverload<int>::of(&QSpinBox::valueChanged), this,
          [this](int poses) { m_fullSearches->setMaximum(poses); });

  m_find = new QPushButton(tr("Find best pose"), this);
  m_find->setObjectName(QStringLiteral("findBestPose"));
  m_find->setToolTip(tr("Try how the model could stand on the platform, each pose with its own decomposition, "
                        "and keep the one with the least risky area left"));
  m_cancel = new QPushButton(tr("Cancel"), this);
  m_cancel->setObjectName(QStringLiteral("cancelPoseSearch"));
  m_progress = new QProgressBar(this);
  m_progress->setObjectName(QStringLiteral("poseProgress"));
  m_progress->setRange(0, 1000);
  m_progress->setTextVisible(false);
  m_progress->hide();
  m_status = new QLabel(this);
  m_status->setObjectName(QStringLiteral("poseStatus"));
  m_status->setWordWrap(true);

  m_table = new QTableWidget(0, ColumnCount, this);
  m_table->setObjectName(QStringLiteral("poseTable"));
  m_table->setHorizontalHeaderLabels({tr("Source"), tr("Up"), tr("Contact (mm²)"), tr("Margin (mm)"),
                                      tr("Risky area (mm²)"), tr("J_G (mm²)"), tr("Regions"), tr("Search")});
  m_table->horizontalHeaderItem(ContactColumn)
      ->setToolTip(tr("Area of the patch of the model's convex hull that stands on the platform in this pose"));
  m_table->horizontalHeaderItem(MarginColumn)
      ->setToolTip(tr("How far inside that patch the centre of mass falls: the model stands only when it is "
                      "positive"));
  m_table->horizontalHeaderItem(RiskyColumn)
      ->setToolTip(tr("Risky area of the whole model printed along this up alone (J_G before)"));
  m_table->horizontalHeaderItem(JgColumn)->setToolTip(tr("J_G of the plan found for this pose"));
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_table->setSelectionMode(QAbstractItemView::SingleSelection);
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  fitColumnsToWidth(m_table, UpColumn);  // the up's three numbers, elided where the dock is narrow
  m_table->setMinimumHeight(140);

  m_use = new QPushButton(tr("Use this pose"), this);
  m_use->setObjectName(QStringLiteral("usePose"));
  m_use->setToolTip(tr("Make the selected pose the model's up; the chosen pose's plan is shown, another pose is "
                       "searched"));
  m_showCurrent = new QPushButton(tr("Show current up"), this);
  m_showCurrent->setObjectName(QStringLiteral("showCurrentUp"));
  m_showCurrent->setToolTip(tr("End the preview of a pose: show the model with its up again"));

  auto* counts = new QFormLayout;
  counts->addRow(tr("Poses to try:"), m_poses);
  counts->addRow(tr("Full searches:"), m_fullSearches);
  auto* run = new QHBoxLayout;
  run->addWidget(m_find);
  run->addWidget(m_cancel);
  auto* use = new QHBoxLayout;
  use->addWidget(m_use);
  use->addWidget(m_showCurrent);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(counts);
  layout->addLayout(run);
  layout->addWidget(m_progress);
  layout->addWidget(m_status);
  layout->addWidget(m_table);
  layout->addLayout(use);

  connect(m_find, &QPushButton::clicked, this, &PoseSearchBox::findClicked);
  connect(m_cancel, &QPushButton::clicked, this, &PoseSearchBox::cancelClicked);
  connect(m_table, &QTableWidget::cellClicked, this, [this](int row, int) { emit poseClicked(row); });
  connect(m_table, &QTableWidget::itemSelectionChanged, this, &PoseSearchBox::updateButtons);
  connect(m_use, &QPushButton::clicked, this, [this] {
    if (selectedTrial() >= 0) emit useClicked(selectedTrial());
  });
  connect(m_showCurrent, &QPushButton::clicked, this, &PoseSearchBox::showCurrentClicked);
  updateButtons();
}

core::PoseOptions PoseSearchBox::poseOptions() const {
  core::PoseOptions options;
  options.poses = m_poses->value();
  options.fullSearches = std::min(m_fullSearches->value(), options.poses);
  return options;
}

void PoseSearchBox::setPoseOptions(int poses, int fullSearches) {
  m_poses->setValue(poses);
  m_fullSearches->setValue(fullSearches);
}

void PoseSearchBox::setRunnable(bool runnable, const QString& reason) {
  m_runnable = runnable;
  m_find->setToolTip(runnable ? tr("Try how the model could stand on the platform, each pose with its own "
                                   "decomposition, and keep the one with the least risky area left")
                              : reason);
  updateButtons();
}

void PoseSearchBox::searchStarted() {
  clear();
  m_running = true;
  m_progress->setValue(0);
  m_progress->show();
  m_status->setText(tr("Full search of the given up..."));
  updateButtons();
}

void PoseSearchBox::showProgress(double fraction, PoseSearchJob::Phase phase) {
  m_progress->setValue(static_cast<int>(std::lround(1000.0 * std::clamp(fraction, 0.0, 1.0))));
  if (!m_running || !m_cancel->isEnabled()) return;  // "Cancelling..." stays
  switch (phase) {
    case PoseSearchJob::Phase::GivenUpSearch: m_status->setText(tr("Full search of the given up...")); break;
    case PoseSearchJob::Phase::CheapScores:
      m_status->setText(tr("Scoring the poses that could beat it with quick plans..."));
      break;
    case PoseSearchJob::Phase::FullSearches: m_status->setText(tr("Full searches of the best poses...")); break;
    case PoseSearchJob::Phase::Done: m_status->setText(tr("Choosing the best pose...")); break;
  }
}

void PoseSearchBox::cancelRequested() {
  m_status->setText(tr("Cancelling the pose search..."));
  m_cancel->setEnabled(false);
}

void PoseSearchBox::showResult(const core::PoseSearchResult& result, bool cancelled) {
  m_running = false;
  m_progress->hide();
  m_table->clearContents();
  const int count = static_cast<int>(result.trials.size());
  m_table->setRowCount(count);
  m_chosen = result.chosenTrial;
  m_scored.assign(count, false);
  QStringList rowNames;
  for (int row = 0; row < count; ++row) {
    const core::PoseTrial& trial = result.trials[row];
    // A finished plan has at least one region: a trial with none was never scored (the search was cancelled).
    const bool scored = trial.regions > 0;
    m_scored[row] = scored;
    // A pose ruled out has no plan, only a bound every plan of it is above: its J_G cell says so.
    const QString search = trial.searched    ? tr("full search")
                           : scored          ? tr("quick plan")
                           : trial.ruledOut  ? tr("ruled out")
                                             : tr("not scored");
    const QString jg = scored           ? area(trial.jgAfterMm2)
                       : trial.ruledOut ? tr("≥ %1").arg(area(trial.unavoidableMm2))
                                        : tr("-");
    const QString cells[ColumnCount] = {sourceText(trial.pose.source),
                                        upText(trial.pose.up),
                                        area(trial.pose.contactAreaMm2),
                                        QLocale().toString(trial.pose.stabilityMarginMm, 'f', 2),
                                        area(trial.pose.riskyAreaMm2),
                                        jg,
                                        scored ? QString::number(trial.regions) : tr("-"),
                                        search};
    for (int column = 0; column < ColumnCount; ++column) {
      auto* item = new QTableWidgetItem(cells[column]);
      if (column != SourceColumn && column != UpColumn && column != SearchColumn)
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      if (row == m_chosen) {
        QFont font = item->font();
        font.setBold(true);
        item->setFont(font);
      }
      if (trial.ruledOut && (column == JgColumn || column == SearchColumn))
        item->setToolTip(tr("Not searched: at least %1 mm² of this pose's overhang cannot be saved by any direction "
                            "the machine prints along, more than the J_G of the given up's plan, so it could not "
                            "win").arg(area(trial.unavoidableMm2)));
      m_table->setItem(row, column, item);
    }
    rowNames << (row == m_chosen ? tr("chosen") : QString::number(row + 1));
  }
  m_table->setVerticalHeaderLabels(rowNames);
  setTextTooltips(m_table, UpColumn);
  const core::PoseTrial& chosen = result.trials[m_chosen];
  const QString best = tr("Best pose: up %1 (%2), J_G %3 mm², %n region(s).", nullptr, chosen.regions)
                           .arg(upText(chosen.pose.up), sourceText(chosen.pose.source), area(chosen.jgAfterMm2));
  m_status->setText(cancelled ? tr("Cancelled: the poses that finished are listed. %1").arg(best) : best);
  updateButtons();
}

void PoseSearchBox::showFailure(const QString& headline, const QString& detail) {
  m_running = false;
  clear();
  m_status->setText(headline);
  m_status->setToolTip(detail);
}

void PoseSearchBox::clear() {
  m_running = false;
  m_progress->hide();
  m_table->setRowCount(0);
  m_chosen = -1;
  m_scored.clear();
  m_status->clear();
  m_status->setToolTip(QString());
  updateButtons();
}

void PoseSearchBox::setTrialInUse(int trial) {
  for (int row = 0; row < m_table->rowCount(); ++row) {
    QTableWidgetItem* item = m_table->item(row, SearchColumn);
    if (!item) continue;
    QString text = item->text();
    const QString mark = tr(", in use");
    if (text.endsWith(mark)) text.chop(mark.size());
    item->setText(row == trial ? text + mark : text);
  }
}

int PoseSearchBox::trialCount() const { return m_table->rowCount(); }

int PoseSearchBox::selectedTrial() const {
  const QList<QTableWidgetItem*> selected = m_table->selectedItems();
  return selected.isEmpty() ? -1 : selected.front()->row();
}

QString PoseSearchBox::statusText() const { return m_status->text(); }

void PoseSearchBox::updateButtons() {
  m_find->setEnabled(m_runnable && !m_running);
  m_cancel->setEnabled(m_running);
  m_poses->setEnabled(!m_running);
  m_fullSearches->setEnabled(!m_running);
  m_use->setEnabled(!m_running && selectedTrial() >= 0);
  m_showCurrent->setEnabled(m_table->rowCount() > 0);
}

}  // namespace multidir::ui

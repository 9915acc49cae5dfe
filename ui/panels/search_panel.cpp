#include "ui/panels/search_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "ui/panels/jg_chart.h"

namespace multidir::ui {
namespace {

QString area(double mm2) { return QLocale().toString(mm2, 'f', 1); }

// "0:07", "12:34": minutes and seconds.
QString elapsedText(qint64 ms) {
  const qint64 seconds = ms / 1000;
  return QStringLiteral("%1:%2").arg(seconds / 60).arg(seconds % 60, 2, 10, QLatin1Char('0'));
}

// J_G below this counts as zero: a plan is support-free when what is left is numerical dust.
constexpr double kSupportFreeMm2 = 1e-6;

}  // namespace

SearchPanel::SearchPanel(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("searchPanel"));
  const core::SearchOptions defaults;
  m_hidden = defaults;

  m_scheme = new QComboBox(this);
  m_scheme->setObjectName(QStringLiteral("scheme"));
  m_scheme->addItem(tr("Beam search (Algorithm 1)"), static_cast<int>(core::SearchScheme::Beam));
  m_scheme->addItem(tr("Constrained greedy"), static_cast<int>(core::SearchScheme::ConstrainedGreedy));
  m_scheme->addItem(tr("Greedy"), static_cast<int>(core::SearchScheme::Greedy));
  m_beamWidth = new QSpinBox(this);
  m_beamWidth->setObjectName(QStringLiteral("beamWidth"));
  m_beamWidth->setRange(1, 200);
  m_beamWidth->setValue(defaults.beamWidth);
  m_beamWidth->setToolTip(tr("How many partial plans each level keeps (b)"));
  m_minVolumeDivisor = new QDoubleSpinBox(this);
  m_minVolumeDivisor->setObjectName(QStringLiteral("minVolumeDivisor"));
  m_minVolumeDivisor->setRange(1.0, 1000.0);
  m_minVolumeDivisor->setDecimals(1);
  m_minVolumeDivisor->setValue(defaults.minVolumeDivisor);
  m_minVolumeDivisor->setToolTip(tr("w: every region cut off keeps at least the model's volume divided by w"));
  m_volumeScales = new QSpinBox(this);
  m_volumeScales->setObjectName(QStringLiteral("volumeScales"));
  m_volumeScales->setRange(1, 4);
  m_volumeScales->setValue(defaults.volumeScales);
  m_volumeScales->setToolTip(tr("Beam search only: runs at this many region scales side by side, the smallest region "
                                "V/w, V/2w, V/4w, ..., the beam width shared among them, and keeps the best plan. "
                                "No single w suits every model. 1: one beam search at w"));
  m_normals = new QSpinBox(this);
  m_normals->setObjectName(QStringLiteral("normals"));
  m_normals->setRange(1, 5000);
  m_normals->setValue(defaults.candidates.normalSamples);
  m_normals->setToolTip(tr("Candidate normals sampled on the whole sphere (5-DOF)"));
  m_offsetStep = new QDoubleSpinBox(this);
  m_offsetStep->setObjectName(QStringLiteral("offsetStep"));
  m_offsetStep->setRange(0.05, 100.0);
  m_offsetStep->setDecimals(2);
  m_offsetStep->setSuffix(tr(" mm"));
  m_offsetStep->setValue(defaults.candidates.offsetStepMm);
  m_offsetStep->setToolTip(tr("Distance between candidate planes along each normal"));
  m_alpha = new QDoubleSpinBox(this);
  m_alpha->setObjectName(QStringLiteral("searchAlpha"));
  m_alpha->setRange(0.0, 89.0);
  m_alpha->setDecimals(1);
  m_alpha->setSuffix(tr("°"));
  m_alpha->setValue(defaults.alphaMaxDegrees);
  m_alpha->setToolTip(tr("Maximal self-supporting angle the search plans for"));
  m_minRegionHeight = new QDoubleSpinBox(this);
  m_minRegionHeight->setObjectName(QStringLiteral("minRegionHeight"));
  m_minRegionHeight->setRange(0.0, 1000.0);
  m_minRegionHeight->setDecimals(1);
  m_minRegionHeight->setSuffix(tr(" mm"));
  m_minRegionHeight->setValue(defaults.minRegionHeightMm);
  m_minRegionHeight->setToolTip(tr("No region, the one on the platform included, is thinner than this along its "
                                   "printing direction"));
  m_minPlaneGain = new QDoubleSpinBox(this);
  m_minPlaneGain->setObjectName(QStringLiteral("minPlaneGain"));
  m_minPlaneGain->setRange(0.0, 100.0);
  m_minPlaneGain->setDecimals(1);
  m_minPlaneGain->setSuffix(tr(" % of J_G"));
  m_minPlaneGain->setValue(defaults.minPlaneGainPercent);
  m_minPlaneGain->setToolTip(tr("A plane stays only if removing it would raise J_G by at least this share of J_G "
                                "before (and by at least 1 mm²): each region costs a platform move and a seam"));
  m_partCost = new QDoubleSpinBox(this);
  m_partCost->setObjectName(QStringLiteral("partCost"));
  m_partCost->setRange(0.0, 1e6);
  m_partCost->setDecimals(1);
  m_partCost->setSuffix(tr(" mm²"));
  m_partCost->setValue(defaults.partCostMm2);
  m_partCost->setToolTip(tr("Apart: the risky area one more part must save, for its dowels and handling (the "
                            "support whose print time equals its dowels')"));
  m_cutFaceCost = new QDoubleSpinBox(this);
  m_cutFaceCost->setObjectName(QStringLiteral("cutFaceCost"));
  m_cutFaceCost->setRange(0.0, 1000.0);
  m_cutFaceCost->setDecimals(2);
  m_cutFaceCost->setSuffix(tr(" mm² per mm² of cut face"));
  m_cutFaceCost->setValue(defaults.cutFaceCost);
  m_cutFaceCost->setToolTip(tr("Apart: the risky area one more part must save for every mm² of its cut face, "
                               "whose two sides are printed solid"));
  m_axisCount = new QSpinBox(this);
  m_polishEffort = new QSpinBox(this);
  m_polishEffort->setObjectName(QStringLiteral("polishEffort"));
  m_polishEffort->setRange(0, 6);
  m_polishEffort->setValue(defaults.polish ? defaults.polishEffort : 0);
  m_polishEffort->setSpecialValueText(tr("off"));
  m_polishEffort->setToolTip(tr("After the search, move every plane continuously (normal and offset) to lower J_G "
                                "further, every constraint kept; higher values refine more finely and take longer"));
  m_polishFinalists = new QCheckBox(tr("also the finalists"), this);
  m_polishFinalists->setObjectName(QStringLiteral("polishFinalists"));
  m_polishFinalists->setChecked(defaults.polishFinalists);
  m_polishFinalists->setToolTip(tr("Also polish the search's best plan for every other number of cuts that may beat "
                                   "its own plan, and keep the least J_G: the plan changes less with the settings"));
  m_searchTails = new QCheckBox(tr("the tails of the polished plan"), this);
  m_searchTails->setObjectName(QStringLiteral("searchTails"));
  m_searchTails->setChecked(defaults.searchTails);
  m_searchTails->setToolTip(tr("After polishing, search the plan's later planes again from each of its polished "
                               "states and keep a lower plan found there: lower J_G on some models, about twice "
                               "the time"));
  m_axisCount->setObjectName(QStringLiteral("axisCount"));
  m_axisCount->setRange(0, 180);
  m_axisCount->setValue(0);
  m_axisCount->setSpecialValueText(tr("machine's axis only"));
  m_axisCount->setToolTip(tr("4-DOF: also try this many rotation axes spread over 180° and keep the best"));

  auto* form = new QFormLayout;
  form->addRow(tr("Scheme:"), m_scheme);
  m_beamWidthLabel = new QLabel(tr("Beam width:"), this);
  form->addRow(m_beamWidthLabel, m_beamWidth);
  form->addRow(tr("Volume divisor w:"), m_minVolumeDivisor);
  m_volumeScalesLabel = new QLabel(tr("Scales:"), this);
  form->addRow(m_volumeScalesLabel, m_volumeScales);
  form->addRow(tr("Normals:"), m_normals);
  form->addRow(tr("Offset step:"), m_offsetStep);
  form->addRow(tr("Max. overhang angle α:"), m_alpha);
  form->addRow(tr("Min. region height:"), m_minRegionHeight);
  form->addRow(tr("Min. gain per plane:"), m_minPlaneGain);
  // One row: the panel must fit a 1280x720 screen (StudioSmallScreen).
  auto* polishRow = new QHBoxLayout;
  polishRow->addWidget(m_polishEffort, 1);
  polishRow->addWidget(m_polishFinalists);
  form->addRow(tr("Polish the planes:"), polishRow);
  form->addRow(tr("Search again:"), m_searchTails);
  m_axisCountLabel = new QLabel(tr("Axes to try:"), this);
  form->addRow(m_axisCountLabel, m_axisCount);
  m_partCostLabel = new QLabel(tr("Price of a part:"), this);
  form->addRow(m_partCostLabel, m_partCost);
  m_cutFaceCostLabel = new QLabel(tr("... and of its cut face:"), this);
  form->addRow(m_cutFaceCostLabel, m_cutFaceCost);

  m_run = new QPushButton(tr("&Run search"), this);
  m_run->setObjectName(QStringLiteral("runSearch"));
  m_run->setDefault(true);
  m_cancel = new QPushButton(tr("&Cancel"), this);
  m_cancel->setObjectName(QStringLiteral("cancelSearch"));
  m_cancel->setEnabled(false);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_run, 1);
  buttons->addWidget(m_cancel);
  connect(m_run, &QPushButton::clicked, this, &SearchPanel::runClicked);
  connect(m_cancel, &QPushButton::clicked, this, &SearchPanel::cancelClicked);
  connect(m_scheme, &QComboBox::currentIndexChanged, this, &SearchPanel::updateBeamOnlyControls);
  connect(m_scheme, &QComboBox::currentIndexChanged, this, &SearchPanel::settingsChanged);
  for (QSpinBox* box : {m_beamWidth, m_volumeScales, m_normals, m_axisCount, m_polishEffort})
    connect(box, &QSpinBox::valueChanged, this, &SearchPanel::settingsChanged);
  for (QCheckBox* box : {m_polishFinalists, m_searchTails})
    connect(box, &QCheckBox::toggled, this, &SearchPanel::settingsChanged);
  connect(m_polishEffort, &QSpinBox::valueChanged, this, &SearchPanel::updatePolishFinalists);
  for (QDoubleSpinBox* box :
       {m_minVolumeDivisor, m_offsetStep, m_alpha, m_minRegionHeight, m_minPlaneGain, m_partCost, m_cutFaceCost})
    connect(box, &QDoubleSpinBox::valueChanged, this, &SearchPanel::settingsChanged);
  connect(m_alpha, &QDoubleSpinBox::valueChanged, this, &SearchPanel::alphaMaxChanged);
  m_tick = new QTimer(this);
  m_tick->setInterval(1000);
  connect(m_tick, &QTimer::timeout, this, &SearchPanel::updateProgressText);

  m_progress = new QProgressBar(this);
  m_progress->setObjectName(QStringLiteral("searchProgress"));
  m_progress->setRange(0, 1000);
  m_progress->setValue(0);
  setProgressText(QStringLiteral("%p%"));
  m_progress->installEventFilter(this);
  connect(m_progress, &QProgressBar::valueChanged, this, &SearchPanel::showProgressText);

  auto* readout = new QGroupBox(tr("Progress"), this);
  auto* grid = new QGridLayout(readout);
  m_level = new QLabel(QStringLiteral("-"), readout);
  m_beams = new QLabel(QStringLiteral("-"), readout);
  m_bestJg = new QLabel(QStringLiteral("-"), readout);
  m_candidates = new QLabel(QStringLiteral("-"), readout);
  m_bestJg->setObjectName(QStringLiteral("bestJg"));
  int row = 0;
  for (const auto& [label, value] : {std::pair<QString, QLabel*>{tr("Level:"), m_level},
                                     {tr("Beams alive:"), m_beams},
                                     {tr("Best J_G:"), m_bestJg},
                                     {tr("Candidates scored:"), m_candidates}}) {
    grid->addWidget(new QLabel(label, readout), row, 0);
    grid->addWidget(value, row, 1);
    value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    ++row;
  }
  m_chart = new JgChart(readout);
  grid->addWidget(m_chart, row, 0, 1, 2);

  m_notice = new QLabel(this);
  m_notice->setObjectName(QStringLiteral("searchNotice"));
  m_notice->setWordWrap(true);
  m_notice->hide();

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addLayout(buttons);
  layout->addWidget(m_progress);
  layout->addWidget(m_notice);
  layout->addWidget(readout, 1);
  setRotaryMachine(false);
  setApartMachine(false);
  setRunnable(false, tr("Open a model first."));
}

core::SearchOptions SearchPanel::searchOptions() const {
  core::SearchOptions options = m_hidden;
  options.scheme = static_cast<core::SearchScheme>(m_scheme->currentData().toInt());
  options.beamWidth = m_beamWidth->value();
  options.minVolumeDivisor = m_minVolumeDivisor->value();
  options.volumeScales = m_volumeScales->value();
  options.candidates.normalSamples = m_normals->value();
  options.candidates.offsetStepMm = m_offsetStep->value();
  options.alphaMaxDegrees = m_alpha->value();
  options.minRegionHeightMm = m_minRegionHeight->value();
  options.minPlaneGainPercent = m_minPlaneGain->value();
  options.partCostMm2 = m_partCost->value();
  options.cutFaceCost = m_cutFaceCost->value();
  options.polish = m_polishEffort->value() > 0;
  if (options.polish) options.polishEffort = m_polishEffort->value();
  options.polishFinalists = options.polish && m_polishFinalists->isChecked();
  options.searchTails = m_searchTails->isChecked();
  return options;
}

void SearchPanel::setSearchOptions(const core::SearchOptions& options) {
  m_hidden = options;
  for (int i = 0; i < m_scheme->count(); ++i) {
    if (m_scheme->itemData(i).toInt() == static_cast<int>(options.scheme)) m_scheme->setCurrentIndex(i);
  }
  m_beamWidth->setValue(options.beamWidth);
  m_minVolumeDivisor->setValue(options.minVolumeDivisor);
  m_volumeScales->setValue(options.volumeScales);
  m_normals->setValue(options.candidates.normalSamples);
  m_offsetStep->setValue(options.candidates.offsetStepMm);
  m_alpha->setValue(options.alphaMaxDegrees);
  m_minRegionHeight->setValue(options.minRegionHeightMm);
  m_minPlaneGain->setValue(options.minPlaneGainPercent);
  m_partCost->setValue(options.partCostMm2);
  m_cutFaceCost->setValue(options.cutFaceCost);
  m_polishEffort->setValue(options.polish ? options.polishEffort : 0);
  m_polishFinalists->setChecked(options.polishFinalists);
  m_searchTails->setChecked(options.searchTails);
  emit settingsChanged();  // also when only options the panel does not show changed
}

double SearchPanel::alphaMaxDegrees() const { return m_alpha->value(); }

void SearchPanel::setAlphaMaxDegrees(double degrees) { m_alpha->setValue(degrees); }

int SearchPanel::axisSearchCount() const { return m_axisCount->isEnabled() ? m_axisCount->value() : 0; }

void SearchPanel::setAxisSearchCount(int count) { m_axisCount->setValue(count); }

void SearchPanel::setRotaryMachine(bool rotary) {
  m_axisCount->setEnabled(rotary);
  m_axisCountLabel->setEnabled(rotary);
}

void SearchPanel::setApartMachine(bool apart) {
  for (QWidget* widget : {static_cast<QWidget*>(m_partCost), static_cast<QWidget*>(m_cutFaceCost),
                          static_cast<QWidget*>(m_partCostLabel), static_cast<QWidget*>(m_cutFaceCostLabel)})
    widget->setEnabled(apart);
}

void SearchPanel::setRunnable(bool runnable, const QString& reason) {
  m_runnable = runnable;
  m_run->setEnabled(runnable && !m_running);
  m_run->setToolTip(runnable ? tr("Search for clipping planes that make the model printable with less support")
                             : reason);
}

void SearchPanel::setRunning(bool running) {
  m_running = running;
  m_run->setEnabled(m_runnable && !running);
  m_cancel->setEnabled(running);
  for (QWidget* w : std::initializer_list<QWidget*>{m_scheme, m_minVolumeDivisor, m_normals, m_offsetStep, m_alpha,
                                                    m_minRegionHeight, m_minPlaneGain, m_polishEffort,
                                                    m_searchTails}) {
    w->setEnabled(!running);
  }
  updateBeamOnlyControls();
  updatePolishFinalists();
}

void SearchPanel::updatePolishFinalists() {
  // Its value stays in the box while polishing is off, for when it is turned on again.
  m_polishFinalists->setEnabled(m_polishEffort->value() > 0 && !m_running);
}

void SearchPanel::updateBeamOnlyControls() {
  const bool beam = static_cast<core::SearchScheme>(m_scheme->currentData().toInt()) == core::SearchScheme::Beam;
  // Their values stay in searchOptions() (and in plans and projects) whatever the scheme.
  for (QWidget* box : std::initializer_list<QWidget*>{m_beamWidth, m_volumeScales}) box->setEnabled(beam && !m_running);
  for (QLabel* label : {m_beamWidthLabel, m_volumeScalesLabel}) label->setEnabled(beam);
}

void SearchPanel::searchStarted(double jgBeforeMm2, int maxLevels) {
  m_jgBefore = jgBeforeMm2;
  m_maxLevels = maxLevels;
  m_cancelling = false;
  m_latest.reset();
  m_phase.clear();
  m_clock.start();
  m_tick->start();
  setRunning(true);
  resetReadout();
  m_bestJg->setText(tr("%1 mm²").arg(area(jgBeforeMm2)));
  m_candidates->setText(QStringLiteral("0"));
  m_chart->setBest(0, jgBeforeMm2);
  updateProgressText();
}

void SearchPanel::resetReadout() {
  m_progress->setValue(0);
  setProgressText(QStringLiteral("%p%"));
  for (QLabel* value : {m_level, m_beams, m_bestJg, m_candidates}) value->setText(QStringLiteral("-"));
  m_chart->clear();
  m_notice->hide();
  m_notice->clear();
}

void SearchPanel::showFraction(double fraction, const QString& phase) {
  m_progress->setValue(static_cast<int>(std::lround(1000.0 * fraction)));
  m_phase = phase;  // SearchJob names only the phases after the search itself (supports)
  updateProgressText();
}

void SearchPanel::showProgress(const core::SearchProgress& progress) {
  m_latest = progress;
  m_level->setText(QString::number(progress.level));
  if (progress.axisCount > 0) {
    m_level->setText(tr("%1 (axis %2 of %3)").arg(progress.level).arg(progress.axisIndex + 1).arg(progress.axisCount));
  }
  if (progress.polishing) m_level->setText(tr("%1 (polishing)").arg(progress.level));
  m_beams->setText(QString::number(progress.beamsAlive));
  m_bestJg->setText(tr("%1 mm²").arg(area(progress.bestJgMm2)));
  m_candidates->setText(QLocale().toString(progress.candidatesScored));
  // The apart machine's second search (the 5-DOF plan for its bound) has J_G of another machine: the chart
  // keeps the apart search's.
  if (progress.stage == 1) m_chart->setBest(progress.level, progress.bestJgMm2);
  updateProgressText();
}

void SearchPanel::updateProgressText() {
  if (!m_running) return;
  const QString elapsed = elapsedText(m_clock.elapsed());
  QString text;
  if (m_cancelling) {
    text = tr("Cancelling: keeping the best plan so far... %1").arg(elapsed);
  } else if (!m_phase.isEmpty()) {
    text = tr("%1 %2 - %3").arg(m_phase, QStringLiteral("%p%"), elapsed);
  } else if (!m_latest) {
    text = m_maxLevels > 0 ? tr("Level 1 of %1: scoring candidates... %2").arg(m_maxLevels).arg(elapsed)
                           : tr("Scoring candidates... %1").arg(elapsed);
  } else {
    const core::SearchProgress& p = *m_latest;
    if (p.polishing) {
      setProgressText(tr("Polishing the planes: %1 % · best J_G %2 mm² · %3")
                                .arg(qRound(100 * p.polishFraction))
                                .arg(area(p.bestJgMm2), elapsed));
      return;
    }
    QString level = m_maxLevels > 0 ? tr("Level %1 of %2").arg(p.level).arg(m_maxLevels) : tr("Level %1").arg(p.level);
    if (p.axisCount > 0) level = tr("Axis %1 of %2, %3").arg(p.axisIndex + 1).arg(p.axisCount).arg(level);
    if (p.stageCount > 1)
      level = (p.stage == 1 ? tr("Apart search (1 of 2), %1") : tr("5-DOF search for the bound (2 of 2), %1")).arg(level);
    text = tr("%1 · beams alive: %2 · best J_G %3 mm² · %4 candidates · %5")
               .arg(level, QLocale().toString(p.beamsAlive), area(p.bestJgMm2),
                    QLocale().toString(p.candidatesScored), elapsed);
  }
  setProgressText(text);
}

void SearchPanel::cancelRequested() {
  m_cancel->setEnabled(false);
  m_cancelling = true;
  updateProgressText();
}

void SearchPanel::searchFinished(const core::Decomposition& plan) {
  setRunning(false);
  m_tick->stop();
  m_progress->setValue(m_progress->maximum());
  setProgressText(plan.cancelled ? tr("Cancelled") : tr("Done"));
  m_bestJg->setText(tr("%1 mm²").arg(area(plan.jgAfterMm2)));
  const int regions = static_cast<int>(plan.regions.size());
  QStringList lines;
  bool warning = false;
  if (plan.cancelled) {
    lines << tr("Cancelled: showing the best plan found so far.");
    warning = true;
  }
  if (plan.jgAfterMm2 >= plan.jgBeforeMm2 - kSupportFreeMm2 && plan.jgBeforeMm2 > kSupportFreeMm2) {
    lines << tr("Nothing improved: no clipping plane lowers the risky area (J_G stays %1 mm²). Try more "
                "normals, a smaller offset step, a larger w or another machine.")
                 .arg(area(plan.jgAfterMm2));
    warning = true;
  } else if (plan.jgAfterMm2 > kSupportFreeMm2) {
    lines << tr("Not support-free: %1 mm² still needs support (was %2 mm²), in %n region(s).", nullptr, regions)
                 .arg(area(plan.jgAfterMm2), area(plan.jgBeforeMm2));
    warning = true;
  } else {
    lines << tr("Support-free in %n region(s) (J_G was %1 mm²).", nullptr, regions).arg(area(plan.jgBeforeMm2));
  }
  if (plan.statistics.proxyFaces > 0) {
    lines << tr("The search ran on a simplified copy of %1 faces; its planes then cut the full model, and every "
                "number shown is the full model's.")
                 .arg(QLocale().toString(plan.statistics.proxyFaces));
    // What changed between the copy and the full model (a plane moved or dropped), in the search's words.
    for (std::size_t i = 1; i < plan.statistics.notes.size(); ++i) lines << QString::fromStdString(plan.statistics.notes[i]);
  }
  showNotice(lines.join(QLatin1Char('\n')), warning);
}

void SearchPanel::noteKeptPlan(const QString& text) { showNotice(text, true); }

void SearchPanel::searchFailed(const QString& headline, const QString& detail) {
  setRunning(false);
  m_tick->stop();
  m_progress->setValue(0);
  setProgressText(tr("Failed"));
  showNotice(detail.isEmpty() ? headline : tr("%1\n%2").arg(headline, detail), true);
}

void SearchPanel::searchDropped() {
  setRunning(false);
  m_tick->stop();
  resetReadout();
  setProgressText(tr("Stopped"));
}

void SearchPanel::clearResult() {
  if (m_running) return;
  resetReadout();
}

void SearchPanel::showNotice(const QString& text, bool warning) {
  m_notice->setText(text);
  m_notice->setStyleSheet(warning ? QStringLiteral("QLabel { background: #fff1d6; color: #6b4200; border: 1px solid "
                                                   "#e0a040; padding: 4px; }")
                                  : QStringLiteral("QLabel { background: #ddf5dd; color: #1d5a1d; border: 1px solid "
                                                   "#60b060; padding: 4px; }"));
  m_notice->show();
}

QString SearchPanel::noticeText() const { return m_notice->text(); }

QString SearchPanel::readoutText() const {
  return QStringList{m_level->text(), m_beams->text(), m_bestJg->text(), m_candidates->text()}.join(QLatin1Char('|'));
}

QString SearchPanel::progressText() const { return m_progress->toolTip(); }

void SearchPanel::setProgressText(const QString& text) {
  m_progressText = text;
  showProgressText();
}

void SearchPanel::showProgressText() {
  const int span = m_progress->maximum() - m_progress->minimum();
  const int percent = span > 0 ? qRound(100.0 * (m_progress->value() - m_progress->minimum()) / span) : 0;
  QString whole = m_progressText;
  whole.replace(QStringLiteral("%p"), QString::number(percent));
  m_progress->setToolTip(whole);
  // A bar's text never wraps: what does not fit is cut off at both ends. Elided, it says where it was cut.
  constexpr int kTextMarginPixels = 12;
  const int room = std::max(0, m_progress->contentsRect().width() - kTextMarginPixels);
  m_progress->setFormat(m_progress->fontMetrics().elidedText(whole, Qt::ElideRight, room));
}

bool SearchPanel::eventFilter(QObject* watched, QEvent* event) {
  if (watched == m_progress && event->type() == QEvent::Resize) showProgressText();
  return QWidget::eventFilter(watched, event);
}

int SearchPanel::chartPointCount() const { return m_chart->pointCount(); }

}  // namespace multidir::ui

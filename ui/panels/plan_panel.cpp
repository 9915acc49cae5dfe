#include "ui/panels/plan_panel.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPixmap>
#include <QSlider>
#include <QSpinBox>
#include <QStringList>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "ui/common/region_palette.h"

namespace multidir::ui {
namespace {

QString number(double value, int decimals) { return QLocale().toString(value, 'f', decimals); }

QString directionText(const core::Vec3& d) {
  return QStringLiteral("(%1, %2, %3)").arg(number(d.x(), 2), number(d.y(), 2), number(d.z(), 2));
}

QIcon swatch(const QColor& colour) {
  QPixmap pixmap(14, 14);
  pixmap.fill(colour);
  return QIcon(pixmap);
}

QTableWidgetItem* cell(const QString& text, bool numeric) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
  if (numeric) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  return item;
}

// What a region's supports hold up (docs/supports.md): J_G counts risky faces only, so a region with 0.0 mm²
// risky area may still carry supports for lowest points, downward edges or later regions' struts.
QString causeText(const core::SupportSet& set) {
  if (set.empty()) return QString();
  const core::SupportCause& cause = set.cause;
  QStringList parts;
  if (cause.faceContacts > 0)
    parts << (cause.faceContacts == 1 ? PlanPanel::tr("1 contact on risky faces")
                                      : PlanPanel::tr("%1 contacts on risky faces").arg(cause.faceContacts));
  if (cause.pointContacts > 0)
    parts << (cause.pointContacts == 1 ? PlanPanel::tr("1 lowest point")
                                       : PlanPanel::tr("%1 lowest points").arg(cause.pointContacts));
  if (cause.edgeContacts > 0)
    parts << PlanPanel::tr("%1 mm of downward edges").arg(number(cause.edgeLengthMm, 1));
  if (cause.carriedVolumeMm3 > 0)
    parts << PlanPanel::tr("struts of later regions (%1 mm³)").arg(number(cause.carriedVolumeMm3, 1));
  return parts.join(QStringLiteral(", "));
}

}  // namespace

PlanPanel::PlanPanel(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("planPanel"));
  m_summary = new QLabel(tr("No plan yet: run a search or open a plan."), this);
  m_summary->setObjectName(QStringLiteral("planSummary"));
  m_summary->setWordWrap(true);

  m_table = new QTableWidget(0, kSupportCauseColumn + 1, this);
  m_table->setObjectName(QStringLiteral("regionTable"));
  m_table->setHorizontalHeaderLabels({tr("Region"), tr("Volume (mm³)"), tr("Risky (mm²)"), tr("Direction"),
                                      tr("Machine angles"), tr("Supports (mm³)"), tr("Supports hold up")});
  m_table->horizontalHeaderItem(kSupportCauseColumn)
      ->setToolTip(tr("Risky faces are the area J_G counts. Lowest points and downward edges have no area but "
                      "still print in air; struts of regions printed later go on through this region's space."));
  m_table->verticalHeader()->hide();
  m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_table->horizontalHeader()->setStretchLastSection(true);
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_table->setAlternatingRowColors(true);

  m_directions = new QCheckBox(tr("Printing directions"), this);
  m_directions->setObjectName(QStringLiteral("showDirections"));
  m_directions->setChecked(true);
  m_planes = new QCheckBox(tr("Clipping planes"), this);
  m_planes->setObjectName(QStringLiteral("showPlanes"));
  m_supports = new QCheckBox(tr("Supports"), this);
  m_supports->setObjectName(QStringLiteral("showSupports"));
  m_supports->setChecked(true);
  m_supports->setToolTip(tr("The tree supports grown for the risky area the plan leaves, in one colour"));
  m_turn = new QCheckBox(tr("Turn the view as the machine turns the part"), this);
  m_turn->setObjectName(QStringLiteral("turnWithMachine"));
  m_explode = new QSlider(Qt::Horizontal, this);
  m_explode->setObjectName(QStringLiteral("explodeSlider"));
  m_explode->setRange(0, 100);
  m_explode->setToolTip(tr("Moves the regions apart along their printing directions"));

  m_step = new QSpinBox(this);
  m_step->setObjectName(QStringLiteral("sequenceStep"));
  m_step->setRange(0, 0);
  m_previous = new QToolButton(this);
  m_previous->setArrowType(Qt::LeftArrow);
  m_previous->setToolTip(tr("Previous region"));
  m_next = new QToolButton(this);
  m_next->setArrowType(Qt::RightArrow);
  m_next->setToolTip(tr("Next region"));
  m_stepLabel = new QLabel(this);
  auto* stepper = new QHBoxLayout;
  stepper->addWidget(m_previous);
  stepper->addWidget(m_step);
  stepper->addWidget(m_next);
  stepper->addWidget(m_stepLabel, 1);

  auto* form = new QFormLayout;
  form->addRow(tr("Show:"), m_directions);
  form->addRow(QString(), m_planes);
  form->addRow(QString(), m_supports);
  form->addRow(tr("Exploded view:"), m_explode);
  form->addRow(tr("Printed up to:"), stepper);
  form->addRow(QString(), m_turn);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_summary);
  layout->addWidget(m_table, 1);
  layout->addLayout(form);

  connect(m_directions, &QCheckBox::toggled, this, &PlanPanel::directionsVisibleChanged);
  connect(m_planes, &QCheckBox::toggled, this, &PlanPanel::clippingPlanesVisibleChanged);
  connect(m_supports, &QCheckBox::toggled, this, &PlanPanel::supportsVisibleChanged);
  connect(m_turn, &QCheckBox::toggled, this, &PlanPanel::turnWithMachineChanged);
  connect(m_explode, &QSlider::valueChanged, this, [this] { emit explodeDistanceChanged(explodeDistanceMm()); });
  connect(m_step, QOverload<int>::of(&QSpinBox::valueChanged), this, [this](int count) {
    updateStepLabel();
    emit shownRegionsChanged(count);
  });
  connect(m_previous, &QToolButton::clicked, m_step, &QSpinBox::stepDown);
  connect(m_next, &QToolButton::clicked, m_step, &QSpinBox::stepUp);
  clearPlan();
}

void PlanPanel::setPlan(const core::Decomposition& plan, core::MachineKind kind) { setPlan(plan, kind, {}); }

void PlanPanel::setPlan(const core::Decomposition& plan, core::MachineKind kind,
                        const std::vector<core::SupportSet>& supports) {
  m_regions = static_cast<int>(plan.regions.size());
  m_table->setRowCount(m_regions);
  for (int i = 0; i < m_regions; ++i) {
    const core::Region& region = plan.regions[static_cast<std::size_t>(i)];
    auto* index = cell(QString::number(i + 1), false);
    index->setIcon(swatch(regionColor(i)));
    m_table->setItem(i, 0, index);
    m_table->setItem(i, 1, cell(number(region.volumeMm3, 1), true));
    m_table->setItem(i, 2, cell(number(region.riskyAreaMm2, 1), true));
    m_table->setItem(i, 3, cell(directionText(region.printingDirection), false));
    QString angles;
    switch (kind) {
      case core::MachineKind::ThreeAxis: angles = tr("none (fixed)"); break;
      case core::MachineKind::RotaryPlatform:
        angles = tr("rotary %1°").arg(number(region.angles.rotaryDegrees, 1));
        break;
      case core::MachineKind::TiltRotate:
      case core::MachineKind::Apart:
        angles = tr("tilt %1°, azimuth %2°").arg(number(region.angles.tiltDegrees, 1),
                                                  number(region.angles.azimuthDegrees, 1));
        break;
    }
    m_table->setItem(i, 4, cell(angles, false));
    // A dash when no supports were grown for the plan (none needed, or none computed), so it is not read
    // as "needs none".
    const bool known = supports.size() == plan.regions.size();
    auto* volume = cell(known ? number(supports[static_cast<std::size_t>(i)].volumeMm3, 1) : tr("–"), true);
    if (!known) volume->setToolTip(tr("No supports were grown for this plan"));
    m_table->setItem(i, kSupportVolumeColumn, volume);
    m_table->setItem(i, kSupportCauseColumn, cell(known ? causeText(supports[static_cast<std::size_t>(i)]) : tr("–"), false));
  }
  m_summary->setText(tr("%n region(s); J_G %1 mm² before, %2 mm² after.", nullptr, m_regions)
                         .arg(number(plan.jgBeforeMm2, 1), number(plan.jgAfterMm2, 1)));
  {
    const QSignalBlocker block(m_step);
    m_step->setRange(1, std::max(1, m_regions));
    m_step->setValue(m_regions);
  }
  {
    const QSignalBlocker block(m_explode);
    m_explode->setValue(0);
  }
  for (QWidget* w : std::initializer_list<QWidget*>{m_directions, m_planes, m_turn, m_explode, m_step, m_previous, m_next})
    w->setEnabled(m_regions > 0);
  const bool hasSupports = supports.size() == plan.regions.size() &&
                           std::any_of(supports.begin(), supports.end(), [](const core::SupportSet& set) { return !set.empty(); });
  m_supports->setEnabled(hasSupports);
  updateStepLabel();
}

void PlanPanel::clearPlan() {
  m_regions = 0;
  m_table->setRowCount(0);
  m_summary->setText(tr("No plan yet: run a search or open a plan."));
  {
    const QSignalBlocker block(m_step);
    m_step->setRange(0, 0);
  }
  for (QWidget* w : std::initializer_list<QWidget*>{m_directions, m_planes, m_turn, m_explode, m_step, m_previous, m_next})
    w->setEnabled(false);
  m_supports->setEnabled(false);
  updateStepLabel();
}

int PlanPanel::shownRegions() const { return m_step->value(); }

void PlanPanel::setShownRegions(int count) { m_step->setValue(count); }

double PlanPanel::explodeDistanceMm() const {
  // At the slider's end regions move a quarter of the model's size per level.
  return 0.25 * m_modelSizeMm * m_explode->value() / m_explode->maximum();
}

void PlanPanel::setExplodeFraction(double fraction) {
  m_explode->setValue(static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * m_explode->maximum())));
}

void PlanPanel::setClippingPlanesShown(bool shown) { m_planes->setChecked(shown); }

void PlanPanel::setSupportsShown(bool shown) { m_supports->setChecked(shown); }

void PlanPanel::setModelSize(double sizeMm) {
  if (std::isfinite(sizeMm) && sizeMm > 0.0) m_modelSizeMm = sizeMm;
}

void PlanPanel::updateStepLabel() {
  m_stepLabel->setText(m_regions > 0 ? tr("of %1").arg(m_regions) : QString());
}

}  // namespace multidir::ui

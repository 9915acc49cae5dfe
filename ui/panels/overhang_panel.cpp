#include "ui/panels/overhang_panel.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSlider>
#include <QDoubleSpinBox>
#include <QSignalBlocker>
#include <cmath>
#include <QVBoxLayout>

#include "multidir/core/common/units.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {

OverhangPanel::OverhangPanel(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("overhangPanel"));
  m_slider = new QSlider(Qt::Horizontal, this);
  m_slider->setObjectName(QStringLiteral("alphaSlider"));
  m_spin = new QDoubleSpinBox(this);
  m_spin->setObjectName(QStringLiteral("alphaSpin"));
  // alpha_max = 90 degrees would call no face risky at all, which the analysis rejects. The spin box has
  // the Search panel's precision (one value, shown in both); the slider moves in whole degrees.
  m_slider->setRange(0, 89);
  m_spin->setRange(0.0, 89.0);
  m_spin->setDecimals(1);
  m_spin->setSuffix(tr("°"));
  m_slider->setValue(static_cast<int>(std::lround(core::kDefaultAlphaMaxDegrees)));
  m_spin->setValue(core::kDefaultAlphaMaxDegrees);
  const QString tip = tr("Maximal self-supporting angle: faces that lean over by more than this from the "
                         "printing direction need support");
  m_slider->setToolTip(tip);
  m_spin->setToolTip(tip);
  connect(m_slider, &QSlider::valueChanged, this, [this](int value) {
    // A slider that only follows the spin box's rounding must not round the spin box's value.
    if (static_cast<int>(std::lround(m_spin->value())) != value) m_spin->setValue(value);
  });
  connect(m_spin, &QDoubleSpinBox::valueChanged, this, [this](double value) {
    const QSignalBlocker blocker(m_slider);
    m_slider->setValue(static_cast<int>(std::lround(value)));
    emit alphaMaxChanged(value);
  });

  auto* angleRow = new QHBoxLayout;
  angleRow->addWidget(m_slider, 1);
  angleRow->addWidget(m_spin);

  m_area = new QLabel(this);
  m_area->setObjectName(QStringLiteral("riskyAreaLabel"));
  QFont big = m_area->font();
  big.setBold(true);
  m_area->setFont(big);
  m_area->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_faces = new QLabel(this);
  m_faces->setObjectName(QStringLiteral("riskyFacesLabel"));

  auto* swatch = new QLabel(this);
  swatch->setFixedSize(14, 14);
  swatch->setStyleSheet(QStringLiteral("background-color: %1; border: 1px solid #444;")
                            .arg(MeshViewerWidget::riskyColor().name()));
  auto* legend = new QHBoxLayout;
  legend->addWidget(swatch);
  legend->addWidget(new QLabel(tr("Risky faces (need support when printed along the up direction)"), this), 1);

  auto* form = new QFormLayout;
  form->addRow(tr("Max. overhang angle α:"), angleRow);
  form->addRow(tr("Risky area:"), m_area);
  form->addRow(tr("Risky faces:"), m_faces);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addLayout(legend);
  layout->addStretch(1);
  showUnavailable(tr("No model"));
}

double OverhangPanel::alphaMaxDegrees() const { return m_spin->value(); }

void OverhangPanel::setAlphaMaxDegrees(double degrees) { m_spin->setValue(degrees); }

void OverhangPanel::showResult(double riskyAreaMm2, std::size_t riskyFaces, std::size_t faces) {
  m_area->setText(tr("%1 mm²").arg(QLocale().toString(riskyAreaMm2, 'f', 1)));
  m_area->setToolTip(QString());
  m_faces->setText(tr("%1 of %2").arg(QLocale().toString(static_cast<qulonglong>(riskyFaces)),
                                      QLocale().toString(static_cast<qulonglong>(faces))));
}

void OverhangPanel::showUnavailable(const QString& reason) {
  m_area->setText(tr("unavailable"));
  m_area->setToolTip(reason);
  m_faces->setText(reason);
}

QString OverhangPanel::riskyAreaText() const { return m_area->text(); }

}  // namespace multidir::ui

#include "ui/panels/machine_panel.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>

#include "multidir/core/analysis/overhang.h"
#include "ui/common/error_text.h"
#include "ui/document/studio_document.h"
#include "ui/panels/pose_search_box.h"

namespace multidir::ui {
namespace {

// The kind box's data for the robot cell: not a core::MachineKind (the search sees a 5-DOF machine).
constexpr int kRobotCellItem = -1;

QDoubleSpinBox* angleBox(QWidget* parent, double low, double high, double value, const QString& name) {
  auto* box = new QDoubleSpinBox(parent);
  box->setObjectName(name);
  box->setRange(low, high);
  box->setDecimals(2);
  box->setValue(value);
  box->setSuffix(QCoreApplication::translate("multidir::ui::MachinePanel", "°"));
  return box;
}

QString axisText(const core::Vec3& v) {
  auto number = [](double x) { return QString::number(std::abs(x) < 1e-12 ? 0.0 : x, 'g', 6); };
  return QStringLiteral("%1,%2,%3").arg(number(v.x()), number(v.y()), number(v.z()));
}

}  // namespace

MachinePanel::MachinePanel(StudioDocument* document, QWidget* parent) : QWidget(parent), m_document(document) {
  setObjectName(QStringLiteral("machinePanel"));
  const core::MachineSpec defaults;
  m_kind = new QComboBox(this);
  m_kind->setObjectName(QStringLiteral("machineKind"));
  m_kind->addItem(tr("3-DOF: fixed printing direction"), static_cast<int>(core::MachineKind::ThreeAxis));
  m_kind->addItem(tr("4-DOF: rotary platform"), static_cast<int>(core::MachineKind::RotaryPlatform));
  m_kind->addItem(tr("5-DOF: tilting robot arm"), static_cast<int>(core::MachineKind::TiltRotate));
  m_kind->addItem(tr("5-DOF: robot arm under a fixed extruder"), kRobotCellItem);
  // Every region printed on its own on an ordinary printer and glued (docs/apart.md): its prices of a part
  // are the Search panel's, with the search's other options.
  m_kind->addItem(tr("Apart (plain printer, parts joined by dowels)"), static_cast<int>(core::MachineKind::Apart));
  m_kind->setCurrentIndex(2);

  m_rotaryGroup = new QGroupBox(tr("Rotary platform (4-DOF)"), this);
  m_axis = new QLineEdit(axisText(defaults.rotationAxis), m_rotaryGroup);
  m_axis->setObjectName(QStringLiteral("rotationAxis"));
  m_axis->setToolTip(tr("The axis the platform turns about, as x,y,z or x, -y, +z; it must lie in the platform "
                        "plane (perpendicular to up)"));
  m_pickAxis = new QPushButton(tr("Pick on platform"), m_rotaryGroup);
  m_pickAxis->setObjectName(QStringLiteral("pickAxisOnPlatform"));
  m_pickAxis->setCheckable(true);
  m_pickAxis->setToolTip(tr("Click two points on the platform in the 3D view: the axis runs from the first to the "
                            "second. Esc or this button again cancels."));
  m_minAngle = angleBox(m_rotaryGroup, -180, 180, defaults.minAngleDegrees, QStringLiteral("minAngle"));
  m_maxAngle = angleBox(m_rotaryGroup, -180, 180, defaults.maxAngleDegrees, QStringLiteral("maxAngle"));
  m_step = angleBox(m_rotaryGroup, 0, 90, defaults.angleStepDegrees, QStringLiteral("angleStep"));
  m_step->setToolTip(tr("The stepper's resolution: only multiples of this angle can be reached"));
  auto* rotary = new QFormLayout(m_rotaryGroup);
  rotary->addRow(tr("Rotation axis:"), m_axis);
  rotary->addRow(QString(), m_pickAxis);
  rotary->addRow(tr("Minimal angle:"), m_minAngle);
  rotary->addRow(tr("Maximal angle:"), m_maxAngle);
  rotary->addRow(tr("Angle step:"), m_step);

  m_tiltGroup = new QGroupBox(tr("Tilting arm (5-DOF)"), this);
  m_maxTilt = angleBox(m_tiltGroup, 0, 180, defaults.maxTiltDegrees, QStringLiteral("maxTilt"));
  m_maxTilt->setToolTip(tr("How far the arm can tilt the platform away from up"));
  auto* tilt = new QFormLayout(m_tiltGroup);
  tilt->addRow(tr("Tilt limit:"), m_maxTilt);

  m_radius = new QDoubleSpinBox(this);
  m_radius->setObjectName(QStringLiteral("platformRadius"));
  m_radius->setRange(0, 5000);
  m_radius->setDecimals(1);
  m_radius->setSuffix(tr(" mm"));
  m_radius->setSpecialValueText(tr("model footprint"));
  m_radius->setValue(defaults.platformRadiusMm);
  m_radius->setToolTip(tr("Radius of the platform disc that no clipping plane may cut; 0 uses the model's "
                          "footprint plus a margin"));

  m_error = new QLabel(this);
  m_error->setObjectName(QStringLiteral("machineError"));
  m_error->setWordWrap(true);
  m_error->setStyleSheet(QStringLiteral("color: #d03030;"));
  m_error->hide();

  auto* form = new QFormLayout;
  form->addRow(tr("Machine:"), m_kind);
  form->addRow(tr("Platform radius:"), m_radius);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(m_rotaryGroup);
  layout->addWidget(m_tiltGroup);
  layout->addWidget(m_error);
  m_cellIndex = layout->count();
  m_poseBox = new PoseSearchBox(this);
  layout->addWidget(m_poseBox);
  layout->addStretch(1);

  connect(m_kind, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    updateEnabled();
    emit robotCellChosen(isRobotCell());
    emit machineChanged();
  });
  connect(m_axis, &QLineEdit::textChanged, this, &MachinePanel::machineChanged);
  connect(m_pickAxis, &QPushButton::toggled, this, &MachinePanel::pickAxisToggled);
  for (QDoubleSpinBox* box : {m_minAngle, m_maxAngle, m_step, m_maxTilt, m_radius}) {
    connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &MachinePanel::machineChanged);
  }
  updateEnabled();
  connect(this, &MachinePanel::machineChanged, this, &MachinePanel::sendToDocument);
  connect(m_document, &StudioDocument::machineChanged, this, &MachinePanel::showDocumentMachine);
  // The document's machine is checked for the document's up whenever either changes (first, before those who
  // read errorText() on the same signals: they were connected after the panel was made).
  connect(m_document, &StudioDocument::machineChanged, this, [this] { validateFor(m_document->up()); });
  connect(m_document, &StudioDocument::upChanged, this, [this] { validateFor(m_document->up()); });
  showDocumentMachine();
  validateFor(m_document->up());
}

void MachinePanel::sendToDocument() {
  if (m_showing) return;
  m_sending = true;
  m_document->setMachineIsRobotCell(isRobotCell());  // the Hardware dock's device follows it
  m_document->setMachine(machineSpec(m_document->up()));
  m_sending = false;
}

void MachinePanel::showDocumentMachine() {
  // The panel's own edit coming back is not shown again: it would rewrite an axis being typed ("1,0" reads as
  // no axis) under the cursor.
  if (m_sending) return;
  m_showing = true;
  setMachineSpec(m_document->machine());
  m_showing = false;
}

core::MachineKind MachinePanel::kind() const {
  if (isRobotCell()) return core::MachineKind::TiltRotate;
  return static_cast<core::MachineKind>(m_kind->currentData().toInt());
}

bool MachinePanel::isRobotCell() const { return m_kind->currentData().toInt() == kRobotCellItem; }

void MachinePanel::setCellSection(QWidget* section) {
  m_cellSection = section;
  section->setParent(this);
  static_cast<QVBoxLayout*>(layout())->insertWidget(m_cellIndex, section);
  updateEnabled();
}

std::optional<core::Vec3> MachinePanel::rotationAxis() const {
  const core::Result<core::Vec3> axis = core::parseDirection(m_axis->text().toStdString());
  if (!axis) return std::nullopt;
  return axis->normalized();
}

core::MachineSpec MachinePanel::machineSpec(const core::Vec3& up) const {
  core::MachineSpec spec;
  spec.kind = kind();
  spec.up = up.normalized();
  spec.platformRadiusMm = m_radius->value();
  spec.platformMarginMm = m_marginMm;
  spec.rotationAxis = rotationAxis().value_or(core::Vec3::Zero());
  spec.minAngleDegrees = m_minAngle->value();
  spec.maxAngleDegrees = m_maxAngle->value();
  spec.angleStepDegrees = m_step->value();
  spec.maxTiltDegrees = m_maxTilt->value();
  spec.forbiddenCones = m_cones;
  return spec;
}

void MachinePanel::setMachineSpec(const core::MachineSpec& spec) {
  QSignalBlocker blocker(this);  // one machineChanged at the end, not one per field
  // A 5-DOF machine keeps the robot cell when it is chosen: the cell is a 5-DOF machine for the search.
  if (!(isRobotCell() && spec.kind == core::MachineKind::TiltRotate)) {
    for (int i = 0; i < m_kind->count(); ++i) {
      if (m_kind->itemData(i).toInt() == static_cast<int>(spec.kind)) m_kind->setCurrentIndex(i);
    }
  }
  m_axis->setText(axisText(spec.rotationAxis));
  m_minAngle->setValue(spec.minAngleDegrees);
  m_maxAngle->setValue(spec.maxAngleDegrees);
  m_step->setValue(spec.angleStepDegrees);
  m_maxTilt->setValue(spec.maxTiltDegrees);
  m_radius->setValue(std::max(0.0, spec.platformRadiusMm));
  m_cones = spec.forbiddenCones;
  m_marginMm = spec.platformMarginMm;
  updateEnabled();
  blocker.unblock();
  emit machineChanged();
}

bool MachinePanel::validateFor(const core::Vec3& up) {
  QString problem;
  bool axisProblem = false;
  if (kind() == core::MachineKind::RotaryPlatform && !rotationAxis()) {
    axisProblem = true;
    problem = tr("The rotation axis \"%1\" cannot be read: type three numbers x,y,z or an axis such as x or -y.")
                  .arg(m_axis->text());
  } else {
    const core::Status status = core::validate(machineSpec(up));
    if (!status) {
      problem = tr("%1 (%2)").arg(errorHeadline(status.error().code),
                                  QString::fromStdString(status.error().describe()));
      axisProblem = status.error().where == "rotation axis";
    }
  }
  m_error->setText(problem);
  m_error->setVisible(!problem.isEmpty());
  m_axis->setStyleSheet(axisProblem ? QStringLiteral("border: 1px solid #d03030;") : QString());
  return problem.isEmpty();
}

QString MachinePanel::errorText() const { return m_error->text(); }

void MachinePanel::setRotationAxis(const core::Vec3& axis, const core::Vec3& up) {
  // C-locale numbers (parseDirection reads '.'), without a "-0.0000" for a component that rounds to zero.
  auto text = [&axis](int decimals) {
    auto number = [decimals](double x) {
      const double scale = std::pow(10.0, decimals);
      const double rounded = std::round(x * scale) / scale;
      return QString::number(rounded == 0.0 ? 0.0 : rounded, 'f', decimals);
    };
    return QStringLiteral("%1,%2,%3").arg(number(axis.x()), number(axis.y()), number(axis.z()));
  };
  // Four decimals read well and keep an axis exact for an up along x, y or z; a tilted up needs more for
  // the rounded axis to stay in the platform plane (validate() allows 1e-6).
  const core::Vec3 unitUp = up.normalized();
  int decimals = 4;
  for (; decimals < 9; ++decimals) {
    const core::Result<core::Vec3> readBack = core::parseDirection(text(decimals).toStdString());
    if (readBack && std::abs(readBack->normalized().dot(unitUp)) < 1e-7) break;
  }
  m_axis->setText(text(decimals));
}

void MachinePanel::setPickAvailable(bool available) {
  m_pickAvailable = available;
  updateEnabled();
}

void MachinePanel::setPicking(bool picking) {
  const QSignalBlocker blocker(m_pickAxis);
  m_pickAxis->setChecked(picking);
}

bool MachinePanel::isPicking() const { return m_pickAxis->isChecked(); }

void MachinePanel::updateEnabled() {
  m_rotaryGroup->setVisible(kind() == core::MachineKind::RotaryPlatform);
  m_tiltGroup->setVisible(kind() == core::MachineKind::TiltRotate);
  if (m_cellSection) m_cellSection->setVisible(isRobotCell());
  const bool pickable = m_pickAvailable && kind() == core::MachineKind::RotaryPlatform;
  if (!pickable) m_pickAxis->setChecked(false);  // emits pickAxisToggled(false) when it was on
  m_pickAxis->setEnabled(pickable);
}

}  // namespace multidir::ui

#include "ui/panels/plane_edit_panel.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QShortcut>
#include <QSignalBlocker>
#include <QSlider>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "ui/edit/plan_editor.h"
#include "ui/edit/plane_edit_geometry.h"
#include "ui/edit/plane_numbering.h"

namespace multidir::ui {
namespace {

// Positions of the offset slider across its range: fine enough that a drag looks continuous.
constexpr int kOffsetSteps = 1000;
// Tilt and azimuth sliders move in tenths of a degree.
constexpr int kAngleScale = 10;

QString number(double value, int decimals) { return QLocale().toString(value, 'f', decimals); }

QTableWidgetItem* cell(const QString& text, bool numeric) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
  if (numeric) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  return item;
}

QDoubleSpinBox* angleBox(QWidget* parent, const QString& name) {
  auto* box = new QDoubleSpinBox(parent);
  box->setObjectName(name);
  box->setDecimals(1);
  box->setSuffix(QStringLiteral("°"));
  // Typed values apply on Enter or when focus leaves, not at every keystroke.
  box->setKeyboardTracking(false);
  return box;
}

QSlider* slider(QWidget* parent, const QString& name) {
  auto* s = new QSlider(Qt::Horizontal, parent);
  s->setObjectName(name);
  return s;
}

QWidget* pair(QWidget* parent, QWidget* box, QWidget* slide) {
  auto* row = new QWidget(parent);
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(box);
  layout->addWidget(slide, 1);
  return row;
}

// Azimuths in (-180, 180], the convention of core's machine angles and so of the Plan and Hardware panels.
double wrapDegrees(double degrees) {
  double wrapped = std::fmod(degrees, 360.0);
  if (wrapped <= -180.0) wrapped += 360.0;
  if (wrapped > 180.0) wrapped -= 360.0;
  return wrapped;
}

bool validPlane(const std::vector<core::Plane>& planes, int plane) {
  return plane >= 0 && static_cast<std::size_t>(plane) < planes.size();
}

}  // namespace

PlaneEditPanel::PlaneEditPanel(PlanEditor* editor, QWidget* parent) : QWidget(parent), m_editor(editor) {
  setObjectName(QStringLiteral("planeEditPanel"));
  m_hint = new QLabel(this);
  m_hint->setObjectName(QStringLiteral("editHint"));
  m_hint->setWordWrap(true);
  m_jg = new QLabel(this);
  m_jg->setObjectName(QStringLiteral("editJg"));
  m_jg->setWordWrap(true);

  m_table = new QTableWidget(0, 3, this);
  m_table->setObjectName(QStringLiteral("planeTable"));
  m_table->setHorizontalHeaderLabels({tr("Plane"), tr("Normal"), tr("Offset (mm)")});
  m_table->horizontalHeaderItem(0)->setToolTip(
      tr("Planes are numbered in printing order, like the regions: plane k is the base of region k + 1"));
  m_table->verticalHeader()->hide();
  m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_table->horizontalHeader()->setStretchLastSection(true);
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_table->setSelectionMode(QAbstractItemView::SingleSelection);
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);

  m_controls = new QWidget(this);
  m_offset = new QDoubleSpinBox(m_controls);
  m_offset->setObjectName(QStringLiteral("planeOffset"));
  m_offset->setRange(-1e6, 1e6);
  m_offset->setDecimals(2);
  m_offset->setSingleStep(0.5);
  m_offset->setSuffix(tr(" mm"));
  m_offset->setKeyboardTracking(false);
  m_offset->setToolTip(tr("Distance of the plane from the origin along its normal"));
  m_offsetSlider = slider(m_controls, QStringLiteral("planeOffsetSlider"));
  m_offsetSlider->setRange(0, kOffsetSteps);
  m_offsetSlider->setToolTip(tr("Moves the plane along its normal across what is left of the model"));
  auto* form = new QFormLayout(m_controls);
  form->setContentsMargins(0, 0, 0, 0);
  form->addRow(tr("Offset:"), pair(m_controls, m_offset, m_offsetSlider));

  m_fiveDof = new QWidget(m_controls);
  m_tilt = angleBox(m_fiveDof, QStringLiteral("planeTilt"));
  m_tiltSlider = slider(m_fiveDof, QStringLiteral("planeTiltSlider"));
  m_azimuth = angleBox(m_fiveDof, QStringLiteral("planeAzimuth"));
  m_azimuth->setRange(-180.0, 180.0);
  m_azimuth->setWrapping(true);
  m_azimuthSlider = slider(m_fiveDof, QStringLiteral("planeAzimuthSlider"));
  m_azimuthSlider->setRange(-180 * kAngleScale, 180 * kAngleScale);
  auto* fiveForm = new QFormLayout(m_fiveDof);
  fiveForm->setContentsMargins(0, 0, 0, 0);
  fiveForm->addRow(tr("Tilt:"), pair(m_fiveDof, m_tilt, m_tiltSlider));
  fiveForm->addRow(tr("Azimuth:"), pair(m_fiveDof, m_azimuth, m_azimuthSlider));
  form->addRow(m_fiveDof);

  m_fourDof = new QWidget(m_controls);
  m_rotary = angleBox(m_fourDof, QStringLiteral("planeRotary"));
  m_rotary->setDecimals(2);
  m_rotarySlider = slider(m_fourDof, QStringLiteral("planeRotarySlider"));
  auto* fourForm = new QFormLayout(m_fourDof);
  fourForm->setContentsMargins(0, 0, 0, 0);
  fourForm->addRow(tr("Rotary angle:"), pair(m_fourDof, m_rotary, m_rotarySlider));
  form->addRow(m_fourDof);

  m_add = new QPushButton(tr("&Add plane"), this);
  m_add->setObjectName(QStringLiteral("addPlane"));
  m_add->setToolTip(
      tr("Splits the piece above the selected plane in two (or, with no plane selected, cuts what "
         "is left on the platform at mid-height)"));
  m_delete = new QPushButton(tr("&Delete plane"), this);
  m_delete->setObjectName(QStringLiteral("deletePlane"));
  m_busy = new QLabel(tr("Updating the plan..."), this);
  m_busy->setObjectName(QStringLiteral("editBusy"));
  m_busy->setVisible(false);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_add);
  buttons->addWidget(m_delete);
  buttons->addWidget(m_busy, 1);

  m_offsetNote = new QLabel(this);
  m_offsetNote->setObjectName(QStringLiteral("offsetFollowsTilt"));
  m_offsetNote->setWordWrap(true);
  m_offsetNote->setVisible(false);

  m_refusal = new QLabel(this);
  m_refusal->setObjectName(QStringLiteral("editRefusal"));
  m_refusal->setWordWrap(true);
  m_refusal->setStyleSheet(QStringLiteral("color: #d32f2f;"));
  m_refusal->setVisible(false);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_hint);
  layout->addWidget(m_jg);
  layout->addWidget(m_table, 1);
  layout->addWidget(m_controls);
  layout->addWidget(m_offsetNote);
  layout->addLayout(buttons);
  layout->addWidget(m_refusal);

  connect(m_table, &QTableWidget::itemSelectionChanged, this, [this] {
    const QList<QTableWidgetItem*> selected = m_table->selectedItems();
    m_editor->selectPlane(selected.isEmpty() ? -1 : planeOfRow(selected.front()->row()));
  });
  connect(m_offset, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &PlaneEditPanel::offsetTyped);
  connectSlider(m_offsetSlider, [this](int session) { offsetSlid(m_offsetSlider->value(), session); });

  auto angleFromBox = [this](QDoubleSpinBox* box, QSlider* slide) {
    connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this, slide](double degrees) {
      {
        const QSignalBlocker block(slide);
        slide->setValue(static_cast<int>(std::lround(degrees * kAngleScale)));
      }
      directionChanged(0);
    });
  };
  auto angleFromSlider = [this](QDoubleSpinBox* box, QSlider* slide) {
    connectSlider(slide, [this, box, slide](int session) {
      {
        const QSignalBlocker block(box);
        box->setValue(slide->value() / static_cast<double>(kAngleScale));
      }
      directionChanged(session);
    });
  };
  angleFromBox(m_tilt, m_tiltSlider);
  angleFromBox(m_azimuth, m_azimuthSlider);
  angleFromSlider(m_tilt, m_tiltSlider);
  angleFromSlider(m_azimuth, m_azimuthSlider);
  connect(m_rotary, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this] { directionChanged(0); });
  connectSlider(m_rotarySlider, [this](int session) {
    const core::MachineSpec& machine = m_editor->machine();
    {
      const QSignalBlocker block(m_rotary);
      m_rotary->setValue(machine.minAngleDegrees + m_rotarySlider->value() * machine.angleStepDegrees);
    }
    directionChanged(session);
  });

  // Delete in the table deletes the selected plane; a double-click edits the cell's value: the offset, or
  // the direction (the tilt on 5-DOF machines, the rotary angle on 4-DOF ones).
  auto* deleteKey = new QShortcut(QKeySequence(QKeySequence::Delete), m_table);
  deleteKey->setContext(Qt::WidgetWithChildrenShortcut);
  connect(deleteKey, &QShortcut::activated, this, [this] {
    if (m_delete->isEnabled()) m_delete->click();
  });
  connect(m_table, &QTableWidget::cellDoubleClicked, this, [this](int row, int column) {
    m_editor->selectPlane(planeOfRow(row));
    if (!m_controls->isEnabled()) return;
    QDoubleSpinBox* box = m_offset;
    if (column == 1 && m_fiveDof->isVisibleTo(this)) box = m_tilt;
    if (column == 1 && m_fourDof->isVisibleTo(this)) box = m_rotary;
    box->setFocus(Qt::OtherFocusReason);
    box->selectAll();
  });
  connect(m_add, &QPushButton::clicked, m_editor, &PlanEditor::addPlane);
  connect(m_delete, &QPushButton::clicked, this, [this] { m_editor->deletePlane(m_editor->selectedPlane()); });
  connect(m_editor, &PlanEditor::stateChanged, this, &PlaneEditPanel::refresh);
  connect(m_editor, &PlanEditor::planEvaluated, this, &PlaneEditPanel::refresh);
  connect(m_editor, &PlanEditor::refusalChanged, this, &PlaneEditPanel::showRefusal);
  connect(m_editor, &PlanEditor::evaluatingChanged, m_busy, &QLabel::setVisible);
  refresh();
}

QString PlaneEditPanel::refusalText() const { return m_refusal->text(); }

QString PlaneEditPanel::jgText() const { return m_jg->text(); }

void PlaneEditPanel::connectSlider(QSlider* slide, const std::function<void(int dragSession)>& edit) {
  connect(slide, &QSlider::sliderPressed, this, [this, slide] {
    m_dragged = slide;
    m_dragSession = m_editor->beginDrag();
  });
  connect(slide, &QSlider::sliderReleased, this, [this] {
    m_dragged = nullptr;
    m_dragSession = 0;
    m_editor->endDrag();
  });
  connect(slide, &QSlider::valueChanged, this, [this, slide, edit] { edit(dragSessionOf(slide)); });
}

int PlaneEditPanel::dragSessionOf(const QSlider* slide) const {
  return slide == m_dragged && slide->isSliderDown() ? m_dragSession : 0;
}

void PlaneEditPanel::refresh() {
  const bool hasPlan = m_editor->hasPlan();
  if (!hasPlan) {
    m_hint->setText(tr("No plan to edit: run a search or open a plan."));
  } else if (!m_editor->canEdit()) {
    m_hint->setText(tr("This plan is shown without its model: open the model it was made from to edit it."));
  } else {
    m_hint->setText(tr("Select a plane to move, tilt or delete it. Every change can be undone (Ctrl+Z)."));
  }
  refreshJg();
  refreshTable();
  refreshControls();
}

void PlaneEditPanel::refreshJg() {
  const std::shared_ptr<const core::Decomposition> plan = m_editor->plan();
  if (!plan) {
    m_jg->clear();
    return;
  }
  m_jg->setText(tr("J_G before: %1 mm² (the whole model printed along up)\nJ_G after: %2 mm² (%3 mm² before "
                   "editing)")
                    .arg(number(plan->jgBeforeMm2, 1), number(plan->jgAfterMm2, 1), number(m_editor->startJgMm2(), 1)));
}

int PlaneEditPanel::planeOfRow(int row) const {
  const int count = static_cast<int>(m_editor->state().planes.size());
  return row >= 0 && row < count ? planeIndexOfNumber(row + 1, count) : -1;
}

int PlaneEditPanel::rowOfPlane(int plane) const {
  const int count = static_cast<int>(m_editor->state().planes.size());
  return plane >= 0 && plane < count ? planeNumber(plane, count) - 1 : -1;
}

void PlaneEditPanel::refreshTable() {
  // One row per plane in printing order (plane_numbering.h): row k shows plane k + 1, the base of region k + 2.
  const std::vector<core::Plane>& planes = m_editor->state().planes;
  const QSignalBlocker block(m_table);
  m_table->setRowCount(static_cast<int>(planes.size()));
  for (int row = 0; row < static_cast<int>(planes.size()); ++row) {
    const core::Plane& plane = planes[static_cast<std::size_t>(planeOfRow(row))];
    m_table->setItem(row, 0, cell(QString::number(row + 1), false));
    m_table->setItem(
        row, 1,
        cell(QStringLiteral("(%1, %2, %3)")
                 .arg(number(plane.normal.x(), 3), number(plane.normal.y(), 3), number(plane.normal.z(), 3)),
             false));
    m_table->setItem(row, 2, cell(number(plane.offset, 2), true));
  }
  const int selected = m_editor->selectedPlane();
  if (validPlane(planes, selected)) {
    m_table->selectRow(rowOfPlane(selected));
  } else {
    m_table->clearSelection();
  }
}

void PlaneEditPanel::refreshControls() {
  const bool editable = m_editor->canEdit();
  const PlanEditState& state = m_editor->state();
  const int selected = state.selectedPlane;
  const bool hasSelection = editable && validPlane(state.planes, selected);
  const core::MachineSpec& machine = m_editor->machine();
  m_add->setEnabled(editable);
  m_delete->setEnabled(hasSelection);
  m_controls->setEnabled(hasSelection);
  refreshOffsetNote();
  m_fiveDof->setVisible(machine.kind == core::MachineKind::TiltRotate);
  m_fourDof->setVisible(machine.kind == core::MachineKind::RotaryPlatform);
  if (!hasSelection) {
    // Greyed fields show nothing rather than a plane that is no longer selected (or another model's).
    for (QDoubleSpinBox* field : {m_offset, m_tilt, m_azimuth, m_rotary}) {
      const QSignalBlocker block(field);
      field->clear();
    }
    for (QSlider* slide : {m_offsetSlider, m_tiltSlider, m_azimuthSlider, m_rotarySlider}) {
      const QSignalBlocker block(slide);
      slide->setValue(slide->minimum());
    }
    return;
  }

  const core::Plane& plane = state.planes[static_cast<std::size_t>(selected)];
  const std::shared_ptr<const core::Decomposition> shown = m_editor->plan();
  if (m_dragged != m_offsetSlider && shown) {
    const OffsetRange range = offsetRangeBefore(*shown, selected, plane.normal);
    if (!range.empty() && range.maxMm > range.minMm) {
      m_rangeMin = range.minMm;
      m_rangeMax = range.maxMm;
    } else {
      m_rangeMin = plane.offset - 1.0;
      m_rangeMax = plane.offset + 1.0;
    }
  }
  const core::MachineAngles angles = core::machineAnglesFor(machine, plane.normal);
  const QSignalBlocker blockOffset(m_offset);
  const QSignalBlocker blockOffsetSlider(m_offsetSlider);
  const QSignalBlocker blockTilt(m_tilt);
  const QSignalBlocker blockTiltSlider(m_tiltSlider);
  const QSignalBlocker blockAzimuth(m_azimuth);
  const QSignalBlocker blockAzimuthSlider(m_azimuthSlider);
  const QSignalBlocker blockRotary(m_rotary);
  const QSignalBlocker blockRotarySlider(m_rotarySlider);
  m_offset->setValue(plane.offset);
  if (m_dragged != m_offsetSlider) {
    const double fraction = (plane.offset - m_rangeMin) / (m_rangeMax - m_rangeMin);
    m_offsetSlider->setValue(static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * kOffsetSteps)));
  }
  switch (machine.kind) {
    case core::MachineKind::ThreeAxis:
      break;
    case core::MachineKind::TiltRotate:
    case core::MachineKind::Apart:
      m_tilt->setRange(0.0, machine.maxTiltDegrees);
      m_tiltSlider->setRange(0, static_cast<int>(std::floor(machine.maxTiltDegrees * kAngleScale)));
      m_tilt->setValue(angles.tiltDegrees);
      if (m_dragged != m_tiltSlider)
        m_tiltSlider->setValue(static_cast<int>(std::lround(angles.tiltDegrees * kAngleScale)));
      // Straight up has no azimuth: the one set last stays.
      if (angles.tiltDegrees > 1e-6) {
        m_azimuth->setValue(wrapDegrees(angles.azimuthDegrees));
        if (m_dragged != m_azimuthSlider)
          m_azimuthSlider->setValue(static_cast<int>(std::lround(wrapDegrees(angles.azimuthDegrees) * kAngleScale)));
      }
      break;
    case core::MachineKind::RotaryPlatform: {
      const double step = machine.angleStepDegrees > 0.0 ? machine.angleStepDegrees : 1.0;
      m_rotary->setRange(machine.minAngleDegrees, machine.maxAngleDegrees);
      m_rotary->setSingleStep(step);
      m_rotarySlider->setRange(
          0, static_cast<int>(std::floor((machine.maxAngleDegrees - machine.minAngleDegrees) / step + 1e-9)));
      m_rotary->setValue(angles.rotaryDegrees);
      if (m_dragged != m_rotarySlider)
        m_rotarySlider->setValue(
            static_cast<int>(std::lround((angles.rotaryDegrees - machine.minAngleDegrees) / step)));
      break;
    }
  }
}

void PlaneEditPanel::showRefusal(const QString& message, const QString& detail) {
  m_refusal->setText(message);
  m_refusal->setToolTip(detail);
  m_refusal->setVisible(!message.isEmpty());
}

void PlaneEditPanel::offsetTyped(double offsetMm) {
  m_tiltStart.reset();
  m_editor->movePlane(m_editor->selectedPlane(), offsetMm);
}

void PlaneEditPanel::offsetSlid(int position, int dragSession) {
  m_tiltStart.reset();
  m_editor->movePlane(m_editor->selectedPlane(), sliderOffset(position), dragSession);
}

void PlaneEditPanel::refreshOffsetNote() {
  const PlanEditState& state = m_editor->state();
  const int selected = state.selectedPlane;
  if (!m_tiltStart || m_tiltStart->plane != selected || !validPlane(state.planes, selected)) {
    m_tiltStart.reset();
    m_offsetNote->setVisible(false);
    return;
  }
  const double now = state.planes[static_cast<std::size_t>(selected)].offset;
  const bool moved = std::abs(now - m_tiltStart->offsetMm) >= 0.005;  // what the offset box shows changed
  m_offsetNote->setText(tr("Tilting turns the plane about the middle of its cut, so its offset (measured from the "
                           "origin along the normal) went from %1 mm to %2 mm.")
                            .arg(number(m_tiltStart->offsetMm, 2), number(now, 2)));
  m_offsetNote->setVisible(moved);
}

double PlaneEditPanel::sliderOffset(int position) const {
  return m_rangeMin + (m_rangeMax - m_rangeMin) * position / static_cast<double>(kOffsetSteps);
}

void PlaneEditPanel::directionChanged(int dragSession) {
  const core::MachineSpec& machine = m_editor->machine();
  const int plane = m_editor->selectedPlane();
  // The offset before this tilt (before the whole drag, for a drag) is what the note compares with.
  const PlanEditState& state = m_editor->state();
  const bool sameDrag = dragSession > 0 && m_tiltStart && m_tiltStart->plane == plane &&
                        m_tiltStart->dragSession == dragSession;
  if (!sameDrag && validPlane(state.planes, plane)) {
    m_tiltStart = TiltStart{plane, state.planes[static_cast<std::size_t>(plane)].offset, dragSession};
  }
  switch (machine.kind) {
    case core::MachineKind::ThreeAxis:
      return;
    case core::MachineKind::TiltRotate:
    case core::MachineKind::Apart:
      m_editor->setPlaneNormal(plane, tiltedDirection(machine.up, m_tilt->value(), m_azimuth->value()), dragSession);
      return;
    case core::MachineKind::RotaryPlatform:
      m_editor->setPlaneNormal(plane, core::rotaryDirection(machine, snapRotaryDegrees(machine, m_rotary->value())),
                               dragSession);
      return;
  }
}

}  // namespace multidir::ui

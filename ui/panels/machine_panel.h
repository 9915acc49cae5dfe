#pragma once
// The Machine panel: which printer the plan is for. 3-DOF (up only), 4-DOF rotary platform (its axis typed
// as x,y,z, angle range, stepper step) or 5-DOF tilting arm (tilt limit), and the platform radius (0 = the
// model's footprint). Every edit is checked with core::validate(MachineSpec); the first problem is shown in
// the panel, in red, until it is fixed.
#include <QWidget>
#include <optional>

#include "multidir/core/search/machine.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QWidget;

namespace multidir::ui {

class MachinePanel : public QWidget {
  Q_OBJECT

 public:
  explicit MachinePanel(QWidget* parent = nullptr);

  // The machine as entered, with `up` as its up direction. Fields of other kinds keep their values.
  // The axis text is read with core::parseDirection and normalised; unreadable text leaves a zero axis,
  // which validate() rejects.
  [[nodiscard]] core::MachineSpec machineSpec(const core::Vec3& up) const;
  // Shows `spec` (its up is not shown: the toolbar's Up box owns it).
  void setMachineSpec(const core::MachineSpec& spec);

  // Checks the machine for `up` and shows the result; true when valid.
  bool validateFor(const core::Vec3& up);
  [[nodiscard]] QString errorText() const;
  [[nodiscard]] core::MachineKind kind() const;
  // The 4-DOF axis as typed (normalised), when it can be read.
  [[nodiscard]] std::optional<core::Vec3> rotationAxis() const;

 signals:
  // Any field changed.
  void machineChanged();

 private:
  void updateEnabled();

  QComboBox* m_kind = nullptr;
  QLineEdit* m_axis = nullptr;
  QDoubleSpinBox* m_minAngle = nullptr;
  QDoubleSpinBox* m_maxAngle = nullptr;
  QDoubleSpinBox* m_step = nullptr;
  QDoubleSpinBox* m_maxTilt = nullptr;
  QDoubleSpinBox* m_radius = nullptr;
  QWidget* m_rotaryGroup = nullptr;
  QWidget* m_tiltGroup = nullptr;
  QLabel* m_error = nullptr;
  std::vector<core::ForbiddenCone> m_cones;  // kept from a loaded profile; not edited here
  double m_marginMm = 5.0;
};

}  // namespace multidir::ui

#pragma once
// The Machine panel: which printer the plan is for. 3-DOF (up only), 4-DOF rotary platform (its axis typed
// as x,y,z, angle range, stepper step), 5-DOF tilting arm (tilt limit) or apart (a plain printer, every region
// a part of its own; its prices of a part are search options, in the Search panel), and the platform radius
// (0 = the model's footprint). Every edit is checked with core::validate(MachineSpec); the first problem is shown in
// the panel, in red, until it is fixed. The 4-DOF axis can also be picked in the 3D view ("Pick on
// platform", checkable): the panel only asks for it (pickAxisToggled) and shows the axis picked. Below the
// machine, "Best pose" (PoseSearchBox) finds the pose to stand the model on.
//
// The machine is the studio document's (StudioDocument::machine): every edit in the panel goes to the document
// (setMachine), and the panel shows the document's machine whenever it changes there (a profile loaded, a
// project opened, a pose turning the machine), so the panel never holds a machine of its own.
#include <QWidget>
#include <optional>

#include "multidir/core/search/machine.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QWidget;

namespace multidir::ui {

class PoseSearchBox;
class StudioDocument;

class MachinePanel : public QWidget {
  Q_OBJECT

 public:
  // Shows and edits `document`'s machine; `document` (not owned) must outlive the panel.
  explicit MachinePanel(StudioDocument* document, QWidget* parent = nullptr);

  // The machine as entered, with `up` as its up direction. Fields of other kinds keep their values.
  // The axis text is read with core::parseDirection and normalised; unreadable text leaves a zero axis,
  // which validate() rejects.
  [[nodiscard]] core::MachineSpec machineSpec(const core::Vec3& up) const;
  // Shows `spec` as if typed (its up is not shown: the document's up is), and so sends it to the document.
  void setMachineSpec(const core::MachineSpec& spec);

  // Checks the machine for `up` and shows the result; true when valid. Done by the panel itself for the
  // document's up whenever the document's machine or up changes.
  bool validateFor(const core::Vec3& up);
  [[nodiscard]] QString errorText() const;
  [[nodiscard]] core::MachineKind kind() const;
  // The machine is the robot cell ("5-DOF: robot arm under a fixed extruder"): a 5-DOF machine for the search,
  // whose cell (setCellSection) the tab shows.
  [[nodiscard]] bool isRobotCell() const;
  // The robot cell's section (CellPanel), shown while the robot cell is chosen; the panel takes it over.
  void setCellSection(QWidget* section);
  // The 4-DOF axis as typed (normalised), when it can be read.
  [[nodiscard]] std::optional<core::Vec3> rotationAxis() const;
  // Writes `axis` (unit length, perpendicular to `up`) into the axis field as x,y,z with four decimals, or
  // as many more as it takes for the text to stay perpendicular to `up` within validate()'s tolerance;
  // machineChanged follows as if typed.
  void setRotationAxis(const core::Vec3& axis, const core::Vec3& up);

  // Whether picking the axis on the platform makes sense (a model, and so a platform, is shown). The
  // button is enabled only then and for a 4-DOF machine.
  void setPickAvailable(bool available);
  // Shows whether picking is under way (checks the button) without emitting pickAxisToggled.
  void setPicking(bool picking);
  [[nodiscard]] bool isPicking() const;

  // "Best pose": finding the pose the model stands on together with its plan (MainWindow runs it).
  [[nodiscard]] PoseSearchBox* poseBox() const { return m_poseBox; }

 signals:
  // The machine shown changed: a field edited (and sent to the document), or the document's machine shown.
  void machineChanged();
  // The robot cell was chosen (true) or another machine (false).
  void robotCellChosen(bool chosen);
  // The "Pick on platform" button was pressed (on: start picking) or released (off: cancel). It also goes
  // off when picking stops making sense (another machine kind, or no platform).
  void pickAxisToggled(bool on);

 private:
  void updateEnabled();
  // A field edited: the machine as entered goes to the document.
  void sendToDocument();
  // The document's machine changed: shown, unless it is the panel's own edit coming back.
  void showDocumentMachine();

  QComboBox* m_kind = nullptr;
  QLineEdit* m_axis = nullptr;
  QPushButton* m_pickAxis = nullptr;
  bool m_pickAvailable = false;
  QDoubleSpinBox* m_minAngle = nullptr;
  QDoubleSpinBox* m_maxAngle = nullptr;
  QDoubleSpinBox* m_step = nullptr;
  QDoubleSpinBox* m_maxTilt = nullptr;
  QDoubleSpinBox* m_radius = nullptr;
  QWidget* m_rotaryGroup = nullptr;
  QWidget* m_tiltGroup = nullptr;
  QWidget* m_cellSection = nullptr;
  int m_cellIndex = 0;  // where the cell's section goes in the layout
  QLabel* m_error = nullptr;
  PoseSearchBox* m_poseBox = nullptr;
  std::vector<core::ForbiddenCone> m_cones;  // kept from a loaded profile; not edited here
  double m_marginMm = 5.0;
  StudioDocument* m_document;
  bool m_sending = false;  // an edit of the panel is being sent to the document
  bool m_showing = false;  // the document's machine is being shown
};

}  // namespace multidir::ui

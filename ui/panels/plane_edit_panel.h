#pragma once
// The Edit plan panel: the clipping planes of the plan shown (number, normal, offset) and controls to change
// the selected one: its offset (typed in mm, or dragged across the range where it cuts what is left of the
// model), its direction (5-DOF: tilt and azimuth; 4-DOF: the rotary angle in the machine's steps; 3-DOF:
// none, planes stay level), Add plane and Delete plane. J_G before and after is shown and kept up to date;
// a refused edit is explained in red under the controls.
//
// The panel edits through a PlanEditor (it calls it and follows its signals); it owns no plan state.
#include <QWidget>
#include <functional>

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;
class QTableWidget;

namespace multidir::ui {

class PlanEditor;

class PlaneEditPanel : public QWidget {
  Q_OBJECT

 public:
  // `editor` must outlive the panel.
  explicit PlaneEditPanel(PlanEditor* editor, QWidget* parent = nullptr);

  [[nodiscard]] QTableWidget* planeTable() const { return m_table; }
  [[nodiscard]] QDoubleSpinBox* offsetBox() const { return m_offset; }
  [[nodiscard]] QSlider* offsetSlider() const { return m_offsetSlider; }
  [[nodiscard]] QDoubleSpinBox* tiltBox() const { return m_tilt; }
  [[nodiscard]] QDoubleSpinBox* azimuthBox() const { return m_azimuth; }
  [[nodiscard]] QDoubleSpinBox* rotaryBox() const { return m_rotary; }
  // The red message under the controls (empty: none).
  [[nodiscard]] QString refusalText() const;
  // The J_G line (before and after).
  [[nodiscard]] QString jgText() const;

 private:
  void refresh();
  void refreshJg();
  void refreshTable();
  void refreshControls();
  void showRefusal(const QString& message, const QString& detail);
  void offsetTyped(double offsetMm);
  void offsetSlid(int position, int dragSession);
  void directionChanged(int dragSession);
  void connectSlider(QSlider* slider, const std::function<void(int dragSession)>& edit);
  [[nodiscard]] double sliderOffset(int position) const;
  [[nodiscard]] int dragSessionOf(const QSlider* slider) const;

  PlanEditor* m_editor;
  QLabel* m_hint = nullptr;
  QLabel* m_jg = nullptr;
  QTableWidget* m_table = nullptr;
  QDoubleSpinBox* m_offset = nullptr;
  QSlider* m_offsetSlider = nullptr;
  QDoubleSpinBox* m_tilt = nullptr;
  QSlider* m_tiltSlider = nullptr;
  QDoubleSpinBox* m_azimuth = nullptr;
  QSlider* m_azimuthSlider = nullptr;
  QDoubleSpinBox* m_rotary = nullptr;
  QSlider* m_rotarySlider = nullptr;
  QWidget* m_fiveDof = nullptr;
  QWidget* m_fourDof = nullptr;
  QWidget* m_controls = nullptr;
  QPushButton* m_add = nullptr;
  QPushButton* m_delete = nullptr;
  QLabel* m_busy = nullptr;
  QLabel* m_refusal = nullptr;
  double m_rangeMin = 0.0;  // the offset slider's range, mm
  double m_rangeMax = 1.0;
  QSlider* m_dragged = nullptr;  // the slider a drag is under way on
  int m_dragSession = 0;
};

}  // namespace multidir::ui

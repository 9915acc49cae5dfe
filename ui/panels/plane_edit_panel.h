#pragma once
// The Edit plan panel: the clipping planes of the plan shown (number in printing order, normal, offset) and
// controls to change the selected one: its offset (typed in mm, or dragged across the range where it cuts
// what is left of the model), its direction (5-DOF: tilt and azimuth, the azimuth in (-180, 180] like the
// Plan panel's; 4-DOF: the rotary angle in the machine's steps; 3-DOF: none, planes stay level), Add plane and
// Delete plane (also the Delete key in the table; a double-click on a plane puts the cursor in its offset, or
// in its direction for a double-click on the normal). J_G before and after is shown and kept up to date; a
// refused edit is explained in red under the controls; a tilt that moved the offset says so.
//
// The panel edits through a PlanEditor (it calls it and follows its signals); it owns no plan state.
#include <QWidget>
#include <functional>
#include <optional>

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
  // Says how a tilt moved the selected plane's offset (it turns about the middle of its cut); hidden otherwise.
  void refreshOffsetNote();
  // Rows list the planes in printing order (ui/edit/plane_numbering.h); planes are 0-based in clipping order.
  [[nodiscard]] int planeOfRow(int row) const;
  [[nodiscard]] int rowOfPlane(int plane) const;
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
  QLabel* m_offsetNote = nullptr;
  struct TiltStart {
    int plane = -1;
    double offsetMm = 0.0;
    int dragSession = 0;
  };
  std::optional<TiltStart> m_tiltStart;  // the selected plane's offset before it was last tilted
  double m_rangeMin = 0.0;  // the offset slider's range, mm
  double m_rangeMax = 1.0;
  QSlider* m_dragged = nullptr;  // the slider a drag is under way on
  int m_dragSession = 0;
};

}  // namespace multidir::ui

#pragma once
// The Overhangs panel: the maximal self-supporting angle alpha_max (slider in whole degrees and a spin box
// to a tenth, 0-89 degrees, default 45; MainWindow keeps it equal to the Search panel's) and what it means for the model at the current up direction: the risky area in mm^2 and the
// number of risky faces.
#include <QWidget>
#include <cstddef>

class QLabel;
class QSlider;
class QDoubleSpinBox;

namespace multidir::ui {

class OverhangPanel : public QWidget {
  Q_OBJECT

 public:
  explicit OverhangPanel(QWidget* parent = nullptr);

  [[nodiscard]] double alphaMaxDegrees() const;
  // Moves the slider and spin box (emits alphaMaxChanged when the value changes).
  void setAlphaMaxDegrees(double degrees);

  // What the analysis found; `riskyFaces` of `faces` faces.
  void showResult(double riskyAreaMm2, std::size_t riskyFaces, std::size_t faces);
  // No model, or the analysis failed (`reason`, shown as it is).
  void showUnavailable(const QString& reason);
  // The risky area exactly as the panel shows it, e.g. "1,234.5 mm²".
  [[nodiscard]] QString riskyAreaText() const;

 signals:
  void alphaMaxChanged(double degrees);

 private:
  QSlider* m_slider = nullptr;
  QDoubleSpinBox* m_spin = nullptr;
  QLabel* m_area = nullptr;
  QLabel* m_faces = nullptr;
};

}  // namespace multidir::ui

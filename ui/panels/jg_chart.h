#pragma once
// A small line chart of the best J_G (mm^2) found at each search level (Qt Charts, hidden behind this class
// so no other header needs Qt Charts).
#include <QWidget>

class QChart;
class QLineSeries;
class QValueAxis;

namespace multidir::ui {

class JgChart : public QWidget {
  Q_OBJECT

 public:
  explicit JgChart(QWidget* parent = nullptr);

  void clear();
  // Records the best J_G at `level`; a later value for the same level replaces the earlier one.
  void setBest(int level, double jgMm2);
  [[nodiscard]] int pointCount() const;

 private:
  QChart* m_chart = nullptr;
  QLineSeries* m_series = nullptr;
  QValueAxis* m_levelAxis = nullptr;
  QValueAxis* m_jgAxis = nullptr;
};

}  // namespace multidir::ui

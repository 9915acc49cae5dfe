#include "ui/panels/jg_chart.h"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QPainter>
#include <QValueAxis>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace multidir::ui {

JgChart::JgChart(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("jgChart"));
  m_chart = new QChart;
  m_chart->legend()->hide();
  m_chart->setMargins(QMargins(2, 2, 2, 2));
  m_chart->setBackgroundRoundness(0);
  m_series = new QLineSeries(m_chart);
  m_series->setPointsVisible(true);
  QPen pen(QColor(0xe6, 0x55, 0x28));
  pen.setWidth(2);
  m_series->setPen(pen);
  m_chart->addSeries(m_series);
  m_levelAxis = new QValueAxis(m_chart);
  m_levelAxis->setTitleText(tr("Level"));
  m_levelAxis->setLabelFormat(QStringLiteral("%d"));
  m_levelAxis->setRange(0, 1);
  m_levelAxis->setTickCount(2);
  m_jgAxis = new QValueAxis(m_chart);
  m_jgAxis->setTitleText(tr("Best J_G (mm²)"));
  m_jgAxis->setLabelFormat(QStringLiteral("%g"));
  m_jgAxis->setRange(0, 1);
  m_chart->addAxis(m_levelAxis, Qt::AlignBottom);
  m_chart->addAxis(m_jgAxis, Qt::AlignLeft);
  m_series->attachAxis(m_levelAxis);
  m_series->attachAxis(m_jgAxis);
  QFont small = font();
  small.setPointSizeF(small.pointSizeF() * 0.85);
  for (QValueAxis* axis : {m_levelAxis, m_jgAxis}) {
    axis->setLabelsFont(small);
    axis->setTitleFont(small);
  }

  auto* view = new QChartView(m_chart, this);  // takes ownership of the chart
  view->setRenderHint(QPainter::Antialiasing);
  view->setMinimumHeight(170);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(view);
}

void JgChart::clear() {
  m_series->clear();
  m_levelAxis->setRange(0, 1);
  m_levelAxis->setTickCount(2);
  m_jgAxis->setRange(0, 1);
}

void JgChart::setBest(int level, double jgMm2) {
  if (!std::isfinite(jgMm2)) return;
  const QList<QPointF> points = m_series->points();
  if (!points.isEmpty() && static_cast<int>(points.back().x()) == level) {
    m_series->replace(points.size() - 1, QPointF(level, jgMm2));
  } else {
    m_series->append(level, jgMm2);
  }
  double top = 0.0;
  int last = 1;
  for (const QPointF& p : m_series->points()) {
    top = std::max(top, p.y());
    last = std::max(last, static_cast<int>(p.x()));
  }
  m_levelAxis->setRange(0, last);
  m_levelAxis->setTickCount(std::min(last, 10) + 1);
  m_jgAxis->setRange(0, top > 0.0 ? top * 1.1 : 1.0);
  m_jgAxis->applyNiceNumbers();
}

int JgChart::pointCount() const { return static_cast<int>(m_series->count()); }

}  // namespace multidir::ui

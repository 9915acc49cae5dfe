#include "ui/panels/slice_panel.h"

#include <QCheckBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPixmap>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "multidir/slicing/estimates.h"
#include "ui/common/region_palette.h"
#include "ui/common/table_columns.h"

namespace multidir::ui {
namespace {

QString number(double value, int decimals) { return QLocale().toString(value, 'f', decimals); }

QTableWidgetItem* cell(const QString& text, bool numeric) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
  if (numeric) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  return item;
}

QIcon swatch(const QColor& colour) {
  QPixmap pixmap(14, 14);
  pixmap.fill(colour);
  return QIcon(pixmap);
}

}  // namespace

SlicePanel::SlicePanel(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("slicePanel"));
  m_slice = new QPushButton(tr("Slice..."), this);
  m_slice->setObjectName(QStringLiteral("sliceButton"));
  m_slice->setToolTip(tr("Slice every step of the plan shown, with its supports, into G-code (PrusaSlicer)"));
  m_cancel = new QPushButton(tr("Cancel"), this);
  m_cancel->setObjectName(QStringLiteral("cancelSlice"));
  m_progress = new QProgressBar(this);
  m_progress->setObjectName(QStringLiteral("sliceProgress"));
  m_progress->setRange(0, 1000);
  m_progress->setTextVisible(false);
  m_stage = new QLabel(this);
  m_stage->setObjectName(QStringLiteral("sliceStage"));
  m_message = new QLabel(this);
  m_message->setObjectName(QStringLiteral("sliceMessage"));
  m_message->setWordWrap(true);
  m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_message->setTextFormat(Qt::PlainText);
  m_message->hide();

  m_table = new QTableWidget(0, 4, this);
  m_table->setObjectName(QStringLiteral("estimatesTable"));
  m_table->setHorizontalHeaderLabels({tr("Step"), tr("Print time"), tr("Filament (m)"), tr("Filament (g)")});
  m_table->verticalHeader()->hide();
  fitColumnsToWidth(m_table, 0);  // the step's name, elided where the dock is narrow
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_table->setMinimumHeight(120);

  m_unsupported = new QLabel(this);
  m_unsupported->setObjectName(QStringLiteral("unsupportedExtrusion"));
  m_unsupported->setWordWrap(true);
  m_unsupported->setToolTip(
      tr("Extrusion that rests on nothing printed before it, as the audit finds it (multidir audit, check b): "
         "drawn in magenta in the G-code preview"));
  m_unsupported->hide();
  m_slowerNote = new QLabel(this);
  m_slowerNote->setObjectName(QStringLiteral("slowerThanFixedNote"));
  m_slowerNote->setWordWrap(true);
  m_slowerNote->hide();

  m_export = new QPushButton(tr("Export G-code..."), this);
  m_export->setObjectName(QStringLiteral("exportGcodeButton"));
  m_export->setToolTip(tr("Write step-NN.gcode, job.gcode (when the firmware turns the platform) and the print "
                          "job with its estimates into a folder"));
  m_preview = new QPushButton(tr("Preview G-code"), this);
  m_preview->setObjectName(QStringLiteral("previewGcode"));
  m_preview->setCheckable(true);
  m_preview->setToolTip(tr("Show the toolpaths in place of the regions; click again for the plan view"));
  m_layers = new QSlider(Qt::Horizontal, this);
  m_layers->setObjectName(QStringLiteral("gcodeLayerSlider"));
  m_layers->setToolTip(tr("Show the layers printed up to this one (all steps, in printing order)"));
  m_layerText = new QLabel(this);
  m_layerText->setObjectName(QStringLiteral("gcodeLayerText"));
  m_layerZ = new QLabel(this);
  m_layerZ->setObjectName(QStringLiteral("gcodeLayerZ"));
  m_layerZ->setToolTip(tr("The layer's height: the nozzle's Z above the platform in its step's pose"));
  // As wide as the widest height it will show, so the slider does not jump as the text changes.
  m_layerZ->setMinimumWidth(m_layerZ->fontMetrics().horizontalAdvance(tr("Z %1 mm").arg(QLocale().toString(888.88, 'f', 2))));
  m_travel = new QCheckBox(tr("Travel moves"), this);
  m_travel->setObjectName(QStringLiteral("showTravelMoves"));

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_slice);
  buttons->addWidget(m_cancel);
  buttons->addStretch(1);
  auto* progress = new QHBoxLayout;
  progress->addWidget(m_progress, 1);
  auto* exportRow = new QHBoxLayout;
  exportRow->addWidget(m_preview);
  exportRow->addWidget(m_export);
  exportRow->addStretch(1);
  auto* previewRow = new QHBoxLayout;
  previewRow->addWidget(new QLabel(tr("Layers:"), this));
  previewRow->addWidget(m_layers, 1);
  previewRow->addWidget(m_layerZ);
  previewRow->addWidget(m_travel);

  auto* box = new QGroupBox(tr("G-code"), this);
  auto* inner = new QVBoxLayout(box);
  inner->addLayout(buttons);
  inner->addLayout(progress);
  inner->addWidget(m_stage);
  inner->addWidget(m_message);
  inner->addWidget(m_table, 1);
  inner->addWidget(m_slowerNote);
  inner->addWidget(m_unsupported);
  inner->addLayout(exportRow);
  inner->addLayout(previewRow);
  inner->addWidget(m_layerText);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(box);

  connect(m_slice, &QPushButton::clicked, this, &SlicePanel::sliceClicked);
  connect(m_cancel, &QPushButton::clicked, this, &SlicePanel::cancelClicked);
  connect(m_export, &QPushButton::clicked, this, &SlicePanel::exportClicked);
  connect(m_preview, &QPushButton::toggled, this, [this](bool on) {
    updatePreviewControls();
    emit previewToggled(on);
  });
  connect(m_layers, &QSlider::valueChanged, this, &SlicePanel::layerLimitChanged);
  connect(m_travel, &QCheckBox::toggled, this, &SlicePanel::travelVisibleChanged);
  showRunning(false);
  clearResult();
  setSliceable(false, tr("Show a plan first: run a search or open a plan."));
}

void SlicePanel::setSliceable(bool sliceable, const QString& reason) {
  m_sliceable = sliceable;
  m_slice->setEnabled(sliceable && !m_running);
  m_slice->setToolTip(sliceable ? tr("Slice every step of the plan shown, with its supports, into G-code (PrusaSlicer)")
                                : reason);
}

void SlicePanel::showRunning(bool running) {
  m_running = running;
  m_slice->setEnabled(m_sliceable && !running);
  m_cancel->setVisible(running);
  m_cancel->setEnabled(running);
  m_progress->setVisible(running);
  if (running) {
    m_progress->setValue(0);
    m_stage->setText(tr("Starting the slicer..."));
  }
  m_stage->setVisible(running);
}

void SlicePanel::showProgress(double fraction, const QString& stage) {
  m_progress->setValue(static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * m_progress->maximum())));
  m_stage->setText(stage);
}

void SlicePanel::showResult(const slicing::SlicedJob& job, int layers) {
  m_table->setRowCount(0);
  auto addRow = [this](const QString& label, const slicing::Estimate& e, RowKind kind, const QIcon& icon) {
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    auto* first = cell(label, false);
    first->setData(Qt::UserRole, static_cast<int>(kind));
    if (!icon.isNull()) first->setIcon(icon);
    m_table->setItem(row, 0, first);
    auto* time = cell(QString::fromStdString(slicing::durationText(e.printSeconds)), true);
    time->setData(Qt::UserRole, e.printSeconds);
    m_table->setItem(row, kTimeColumn, time);
    m_table->setItem(row, 2, cell(number(e.filamentMm / 1000.0, 2), true));
    m_table->setItem(row, 3, cell(e.filamentGrams > 0.0 ? number(e.filamentGrams, 1) : tr("–"), true));
    if (kind != RowKind::Step) {
      QFont bold = first->font();
      bold.setBold(true);
      for (int c = 0; c < m_table->columnCount(); ++c) m_table->item(row, c)->setFont(bold);
    }
  };
  for (const slicing::SlicedStep& step : job.steps)
    addRow(tr("%1 (%2)").arg(step.index).arg(QString::fromStdString(step.gcodeFile)), step.estimate, RowKind::Step,
           swatch(regionColor(step.index - 1)));
  addRow(job.stitchedFile.empty() ? tr("Total") : tr("Total (%1)").arg(QString::fromStdString(job.stitchedFile)),
         job.total, RowKind::Total, QIcon());
  if (job.fixedDirection) {
    addRow(tr("Fixed direction, slicer supports"), *job.fixedDirection, RowKind::FixedDirection, QIcon());
    m_table->item(m_table->rowCount() - 1, 0)
        ->setToolTip(tr("The whole model printed along up with PrusaSlicer's own supports: the comparison"));
  }
  setTextTooltips(m_table, 0);
  // Beside the estimates, when the comparison surprises: why multi-directional printing takes longer here.
  const bool slower = job.fixedDirection && job.total.printSeconds > job.fixedDirection->printSeconds;
  m_slowerNote->setText(
      slower ? tr("Slower than the fixed direction: each of the %n steps starts anew (the platform turns, the "
                  "nozzle lifts and primes, a first layer on the step's base), and here that costs more time than "
                  "the slicer's supports it avoids.",
                  nullptr, static_cast<int>(job.steps.size()))
             : QString());
  m_slowerNote->setVisible(slower);
  m_hasResult = true;
  {
    const QSignalBlocker block(m_layers);
    m_layers->setRange(std::min(1, layers), std::max(0, layers));
    m_layers->setValue(layers);
  }
  m_export->setEnabled(true);
  m_preview->setEnabled(layers > 0);
  updatePreviewControls();
}

void SlicePanel::showUnsupported(bool audited, double unsupportedMm, double percent) {
  m_unsupported->setText(
      audited ? tr("Unsupported extrusion: %1 mm (%2 %) in magenta").arg(number(unsupportedMm, 1), number(percent, 1))
              : QString());
  m_unsupported->setVisible(audited);
}

void SlicePanel::clearResult() {
  m_hasResult = false;
  m_table->setRowCount(0);
  m_slowerNote->hide();
  showUnsupported(false, 0.0, 0.0);
  m_export->setEnabled(false);
  {
    const QSignalBlocker block(m_preview);
    m_preview->setChecked(false);
  }
  m_preview->setEnabled(false);
  m_layerText->clear();
  m_layerZ->clear();
  updatePreviewControls();
}

void SlicePanel::showMessage(const QString& headline, const QString& detail, bool error) {
  m_message->setText(detail.isEmpty() ? headline : headline + QStringLiteral("\n") + detail);
  m_message->setStyleSheet(error ? QStringLiteral("color: #c0392b;") : QString());
  m_message->setVisible(!headline.isEmpty());
}

void SlicePanel::setPreviewShown(bool shown) {
  {
    const QSignalBlocker block(m_preview);
    m_preview->setChecked(shown);
  }
  updatePreviewControls();
}

void SlicePanel::setLayerText(const QString& text) { m_layerText->setText(text); }

void SlicePanel::setLayerZ(std::optional<double> zMm) {
  m_layerZ->setText(zMm ? tr("Z %1 mm").arg(QLocale().toString(*zMm, 'f', 2)) : QString());
}

void SlicePanel::updatePreviewControls() {
  const bool on = m_hasResult && m_preview->isChecked();
  m_layers->setEnabled(on);
  m_travel->setEnabled(on);
  m_layerText->setVisible(on);
  m_layerZ->setVisible(on);
}

}  // namespace multidir::ui

#include "ui/panels/apart_panel.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/slicing/printer_profile.h"
#include "ui/common/region_palette.h"
#include "ui/common/table_columns.h"
#include "ui/document/studio_document.h"
#include "ui/jobs/apart_job_runner.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

// How far the exploded view moves each part from the model's middle: the share of its centroid's offset the
// assembly sheet's picture of the parts uses too (docs/apart.md, "Assembly sheet").
constexpr double kExplodeShare = 0.35;
// How wide each joint opens in the exploded view, as a share of the model's diagonal.
constexpr double kJointGapShare = 0.15;
// Dowels are drawn in one neutral colour, so the parts' colours stay one per part.
const QColor kDowelColour(0x60, 0x60, 0x60);

QString number(double value, int decimals) { return QLocale().toString(value, 'f', decimals); }

core::Vec3 centroidOf(const core::TriangleMesh& mesh) {
  core::Vec3 sum = core::Vec3::Zero();
  for (const core::Vec3& v : mesh.vertices) sum += v;
  return mesh.vertices.empty() ? sum : core::Vec3(sum / static_cast<double>(mesh.vertices.size()));
}

core::TriangleMesh moved(core::TriangleMesh mesh, const core::Vec3& by) {
  for (core::Vec3& v : mesh.vertices) v += by;
  return mesh;
}

QDoubleSpinBox* millimetres(double value, double min, double max, double step, QWidget* parent) {
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(min, max);
  box->setDecimals(2);
  box->setSingleStep(step);
  box->setSuffix(QStringLiteral(" mm"));
  box->setValue(value);
  return box;
}

// The parts exploded from the model's middle along their centroids' offsets, each dowel halfway between the
// two parts it joins (so it sits in the gap the explosion opens), numbered as on the parts and the sheet.
std::vector<ColouredSolid> explodedParts(const apart::ApartResult& result) {
  std::vector<core::Vec3> centroids;
  core::BoundingBox all = core::boundingBox(result.parts.front());
  for (const core::TriangleMesh& part : result.parts) {
    centroids.push_back(centroidOf(part));
    const core::BoundingBox box = core::boundingBox(part);
    all.min = all.min.cwiseMin(box.min);
    all.max = all.max.cwiseMax(box.max);
  }
  const core::Vec3 middle = 0.5 * (all.min + all.max);
  // Each part moves off its middle as on the sheet, and away from every part it is glued to along their
  // joint's normal, so each joint opens and shows its dowels.
  const double jointGap = kJointGapShare * (all.max - all.min).norm();
  std::vector<core::Vec3> shifts;
  for (const core::Vec3& c : centroids) shifts.push_back(kExplodeShare * (c - middle));
  for (const core::ApartJoint& joint : result.plan.joints) {
    const core::Vec3 normal = joint.plane.normal.normalized();
    shifts[static_cast<std::size_t>(joint.upper)] += 0.5 * jointGap * normal;
    shifts[static_cast<std::size_t>(joint.lower)] -= 0.5 * jointGap * normal;
  }
  std::vector<ColouredSolid> solids;
  for (std::size_t p = 0; p < result.parts.size(); ++p)
    solids.push_back({moved(result.parts[p], shifts[p]), regionColor(static_cast<int>(p)),
                      QString::number(p + 1), centroids[p] + shifts[p]});
  for (std::size_t d = 0; d < result.dowels.size() && d < result.layout.dowels.size(); ++d) {
    const core::ApartJoint& joint = result.plan.joints[static_cast<std::size_t>(result.layout.dowels[d].joint)];
    const core::Vec3 shift = 0.5 * (shifts[static_cast<std::size_t>(joint.lower)] + shifts[static_cast<std::size_t>(joint.upper)]);
    solids.push_back({moved(result.dowels[d], shift), kDowelColour, QString(), core::Vec3::Zero()});
  }
  return solids;
}

// The items of one plate as they lie on the bed (printer coordinates), parts in their colours and numbers.
std::vector<ColouredSolid> plateSolids(const apart::ApartResult& result, int plate) {
  std::vector<ColouredSolid> solids;
  for (const assembly::PlateItem& item : result.plates.items) {
    if (item.plate != plate) continue;
    const bool isPart = item.name.rfind("part-", 0) == 0;
    const int index = isPart ? std::stoi(item.name.substr(5)) - 1 : -1;
    solids.push_back({item.mesh, isPart ? regionColor(index) : kDowelColour,
                      isPart ? QString::number(index + 1) : QString(), centroidOf(item.mesh)});
  }
  return solids;
}

}  // namespace

ApartPanel::ApartPanel(StudioDocument& document, QWidget* parent)
    : QWidget(parent), m_document(document), m_runner(new ApartJobRunner(this)) {
  setObjectName(QStringLiteral("apartPanel"));
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  m_printer = new QComboBox(this);
  m_printer->setObjectName(QStringLiteral("apartPrinter"));
  // The Slice dialog's printers, by the names it shows (its translations); the shipped id in Qt::UserRole.
  for (const std::string& name : slicing::builtinPrinterNames()) {
    const core::Result<slicing::PrinterProfile> profile = slicing::loadPrinterProfile(name);
    m_printer->addItem(profile ? QCoreApplication::translate("multidir::ui::SliceDialog", profile->name.c_str())
                               : QString::fromStdString(name),
                       QString::fromStdString(name));
  }
  // An ordinary 3-axis printer is what printing apart is for.
  m_printer->setCurrentIndex(std::max(0, m_printer->findData(QStringLiteral("marlin-220"))));
  // Long printer names must not widen the dock past its width (the Export button would scroll out of sight).
  m_printer->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  m_printer->setMinimumContentsLength(16);
  m_printer->setToolTip(tr("The parts must fit this printer's bed and height; its settings slice the plates"));
  form->addRow(tr("Printer"), m_printer);
  m_slice = new QCheckBox(tr("Slice the plates (PrusaSlicer) for the estimates"), this);
  m_slice->setChecked(true);
  form->addRow(QString(), m_slice);
  const assembly::DowelOptions defaults;
  m_minDiameter = millimetres(defaults.minDiameterMm, 1.0, 20.0, 0.5, this);
  m_maxDiameter = millimetres(defaults.maxDiameterMm, 1.0, 30.0, 0.5, this);
  m_radialClearance = millimetres(defaults.radialClearanceMm, 0.0, 1.0, 0.05, this);
  m_depthClearance = millimetres(defaults.depthClearanceMm, 0.0, 2.0, 0.1, this);
  m_minWall = millimetres(defaults.minWallMm, 0.4, 5.0, 0.4, this);
  m_perJoint = new QSpinBox(this);
  m_perJoint->setRange(1, 6);
  m_perJoint->setValue(defaults.dowelsPerJoint);
  form->addRow(tr("Dowel diameter from"), m_minDiameter);
  form->addRow(tr("Dowel diameter up to"), m_maxDiameter);
  form->addRow(tr("Clearance in radius"), m_radialClearance);
  form->addRow(tr("Clearance in depth"), m_depthClearance);
  form->addRow(tr("Wall around holes"), m_minWall);
  form->addRow(tr("Dowels per joint"), m_perJoint);
  layout->addLayout(form);

  auto* buttons = new QHBoxLayout;
  m_run = new QPushButton(tr("Run"), this);
  m_run->setObjectName(QStringLiteral("apartRun"));
  m_cancel = new QPushButton(tr("Cancel"), this);
  m_cancel->setEnabled(false);
  m_export = new QPushButton(tr("Export..."), this);
  m_export->setObjectName(QStringLiteral("apartExport"));
  m_export->setToolTip(tr("Write every part and dowel (STL), the 3MF, the G-code of every plate, the assembly "
                          "sheet and apart.json to a folder"));
  buttons->addWidget(m_run);
  buttons->addWidget(m_cancel);
  buttons->addStretch(1);
  buttons->addWidget(m_export);
  layout->addLayout(buttons);
  m_progress = new QProgressBar(this);
  m_progress->setRange(0, 1000);
  m_progress->setVisible(false);
  m_stage = new QLabel(this);
  m_message = new QLabel(this);
  m_message->setWordWrap(true);
  m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_summary = new QLabel(this);
  m_summary->setWordWrap(true);
  layout->addWidget(m_progress);
  layout->addWidget(m_stage);
  layout->addWidget(m_message);
  layout->addWidget(m_summary);

  m_view = new QComboBox(this);
  m_view->setObjectName(QStringLiteral("apartView"));
  layout->addWidget(m_view);
  m_viewer = new MeshViewerWidget(this);
  m_viewer->setObjectName(QStringLiteral("apartViewer"));
  m_viewer->setMinimumHeight(260);
  layout->addWidget(m_viewer, 1);

  m_table = new QTableWidget(0, 4, this);
  m_table->setObjectName(QStringLiteral("apartEstimates"));
  m_table->setHorizontalHeaderLabels({tr("Print"), tr("Time"), tr("Filament\n(cm³)"), tr("Support\n(cm³)")});
  m_table->verticalHeader()->setVisible(false);
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  fitColumnsToWidth(m_table, 0);
  layout->addWidget(m_table);

  connect(m_run, &QPushButton::clicked, this, [this] { run(); });
  connect(m_cancel, &QPushButton::clicked, this, &ApartPanel::cancel);
  connect(m_export, &QPushButton::clicked, this, &ApartPanel::exportFromDialog);
  connect(m_view, qOverload<int>(&QComboBox::currentIndexChanged), this, &ApartPanel::showView);
  connect(m_runner, &ApartJobRunner::progressed, this, [this](double fraction, const QString& stage) {
    m_progress->setValue(static_cast<int>(fraction * 1000.0));
    m_stage->setText(stage);
  });
  connect(m_runner, &ApartJobRunner::runningChanged, this, [this](bool running) {
    m_progress->setVisible(running);
    m_cancel->setEnabled(running);
    if (!running) m_stage->clear();
    showDocument();
  });
  connect(m_runner, &ApartJobRunner::finished, this, [this](const ApartPrint& print) {
    if (const core::Status s = m_document.setApartPrint(print); !s)
      showMessage(QString::fromStdString(s.error().message), true);
  });
  connect(m_runner, &ApartJobRunner::failed, this, [this](const QString& headline, const QString& detail) {
    showMessage(detail.isEmpty() ? headline : headline + QStringLiteral("\n\n") + detail, true);
  });
  connect(m_runner, &ApartJobRunner::cancelled, this,
          [this] { showMessage(tr("Cancelled: nothing was written."), false); });
  connect(&m_document, &StudioDocument::planChanged, this, [this] {
    // A new plan: a run of the old one would give a stale plan's parts.
    m_runner->cancel();
    showDocument();
  });
  connect(&m_document, &StudioDocument::apartPrintChanged, this, &ApartPanel::showDocument);
  showDocument();
}

apart::PrintApartOptions ApartPanel::options() const {
  apart::PrintApartOptions options;
  core::Result<slicing::PrinterProfile> printer = slicing::loadPrinterProfile(m_printer->currentData().toString().toStdString());
  if (printer) options.printer = std::move(*printer);
  options.slice = m_slice->isChecked();
  options.dowels.minDiameterMm = m_minDiameter->value();
  options.dowels.maxDiameterMm = m_maxDiameter->value();
  options.dowels.radialClearanceMm = m_radialClearance->value();
  options.dowels.depthClearanceMm = m_depthClearance->value();
  options.dowels.minWallMm = m_minWall->value();
  options.dowels.dowelsPerJoint = m_perJoint->value();
  if (const std::optional<SearchRun>& plan = m_document.plan()) {
    options.alphaMaxDegrees = plan->options.alphaMaxDegrees;
    if (const std::optional<LoadedModel>& model = m_document.model())
      options.title = tr("Assembly of %1").arg(model->name).toStdString();
  }
  return options;
}

bool ApartPanel::run() {
  const std::optional<SearchRun>& plan = m_document.plan();
  if (!plan || !plan->plan) {
    showMessage(tr("There is no plan to print apart: search the model first."), true);
    return false;
  }
  const apart::PrintApartOptions chosen = options();
  if (!chosen.printer) {
    showMessage(tr("The printer '%1' could not be read: choose another one.").arg(m_printer->currentText()), true);
    return false;
  }
  if (const core::Status valid = assembly::validate(chosen.dowels); !valid) {
    showMessage(tr("The dowel options do not fit together: %1").arg(QString::fromStdString(valid.error().message)), true);
    return false;
  }
  m_document.clearApartPrint();
  showMessage(QString(), false);
  QString error;
  if (!m_runner->start(plan->plan, chosen, &error)) {
    showMessage(error, true);
    return false;
  }
  return true;
}

void ApartPanel::cancel() { m_runner->cancel(); }

bool ApartPanel::exportTo(const QString& folder) {
  const std::optional<ApartPrint>& print = m_document.apartPrint();
  if (!print) {
    showMessage(tr("Nothing to export: run Print apart first."), true);
    return false;
  }
  if (const core::Status s = apart::copyApartFiles(*print->result, folder.toStdString()); !s) {
    showMessage(tr("The files could not be written: %1").arg(QString::fromStdString(s.error().describe())), true);
    return false;
  }
  showMessage(tr("%n file(s) written to %1", nullptr, static_cast<int>(print->result->files.size())).arg(folder), false);
  return true;
}

void ApartPanel::exportFromDialog() {
  const QString folder = QFileDialog::getExistingDirectory(this, tr("Export the parts to a folder"));
  if (!folder.isEmpty()) exportTo(folder);
}

void ApartPanel::showMessage(const QString& text, bool error) {
  m_message->setText(text);
  m_message->setStyleSheet(error ? QStringLiteral("color: #b00000") : QString());
}

void ApartPanel::showDocument() {
  const bool running = m_runner->isRunning();
  m_run->setEnabled(m_document.plan().has_value() && !running);
  const std::optional<ApartPrint>& print = m_document.apartPrint();
  m_export->setEnabled(print.has_value() && !running);
  const QSignalBlocker block(m_view);
  m_view->clear();
  if (!print) {
    m_summary->clear();
    m_table->setRowCount(0);
    m_viewer->clear();
    return;
  }
  const apart::ApartResult& result = *print->result;
  m_summary->setText(tr("%1 parts, %2 joints, %3 dowels, %4 plates; J_G apart %5 mm² (the plan: %6 mm²)")
                         .arg(result.plan.parts.size())
                         .arg(result.plan.joints.size())
                         .arg(result.layout.dowels.size())
                         .arg(result.plates.plates)
                         .arg(number(result.plan.jgMm2, 2), number(result.jgPlanMm2, 2)));
  m_view->addItem(tr("Parts exploded"));
  for (int p = 0; p < result.plates.plates; ++p) m_view->addItem(tr("Plate %1").arg(p + 1));
  fillEstimates();
  showView(0);
}

void ApartPanel::showView(int index) {
  const std::optional<ApartPrint>& print = m_document.apartPrint();
  if (!print || print->result->parts.empty()) return;
  if (index <= 0) {
    m_viewer->setSolids(explodedParts(*print->result), print->plan->regions.front().printingDirection);
  } else {
    m_viewer->setSolids(plateSolids(*print->result, index - 1), core::Vec3::UnitZ());
  }
}

void ApartPanel::fillEstimates() {
  const apart::ApartResult& result = *m_document.apartPrint()->result;
  m_table->setRowCount(0);
  if (!result.sliced) return;
  auto addRow = [this](RowKind kind, const QString& what, const slicing::Estimate& e) {
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    auto* first = new QTableWidgetItem(what);
    first->setData(Qt::UserRole, static_cast<int>(kind));
    m_table->setItem(row, 0, first);
    auto* time = new QTableWidgetItem(QString::fromStdString(slicing::durationText(e.printSeconds)));
    time->setData(Qt::UserRole, e.printSeconds);
    m_table->setItem(row, kTimeColumn, time);
    m_table->setItem(row, 2, new QTableWidgetItem(number(e.filamentCm3, 2)));
    auto* support = new QTableWidgetItem(number(e.supportCm3, 2));
    support->setData(Qt::UserRole, e.supportCm3);
    m_table->setItem(row, kSupportColumn, support);
  };
  for (const apart::PlateEstimate& p : result.plateEstimates) addRow(RowKind::Plate, tr("Plate %1").arg(p.plate + 1), p.estimate);
  addRow(RowKind::AllPlates, tr("All plates"), result.total);
  addRow(RowKind::OnePiece, tr("One piece with supports"), result.whole);
  setTextTooltips(m_table, 0);
}

}  // namespace multidir::ui

#include "ui/panels/cell_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>
#include <memory>

#include "multidir/robot/cell_file.h"
#include "ui/document/plan_as_loaded.h"
#include "ui/document/studio_document.h"
#include "ui/jobs/cell_job.h"

namespace multidir::ui {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

QDoubleSpinBox* numberBox(QWidget* parent, const QString& name, double low, double high, int decimals,
                          const QString& suffix) {
  auto* box = new QDoubleSpinBox(parent);
  box->setObjectName(name);
  box->setRange(low, high);
  box->setDecimals(decimals);
  box->setSuffix(suffix);
  box->setKeyboardTracking(false);  // one edit per value typed, not one per key
  return box;
}

QWidget* row(QWidget* parent, const std::array<QDoubleSpinBox*, 3>& boxes) {
  auto* widget = new QWidget(parent);
  auto* layout = new QHBoxLayout(widget);
  layout->setContentsMargins(0, 0, 0, 0);
  for (QDoubleSpinBox* box : boxes) layout->addWidget(box);
  return widget;
}

std::filesystem::path localPath(const QString& path) { return std::filesystem::path(QFile::encodeName(path).toStdString()); }

}  // namespace

CellPanel::CellPanel(StudioDocument* document, QWidget* parent) : QWidget(parent), m_document(document) {
  setObjectName(QStringLiteral("cellPanel"));
  auto* group = new QGroupBox(tr("Robot cell: the arm carries the platform under a fixed extruder"), this);
  m_model = new QComboBox(group);
  m_model->setObjectName(QStringLiteral("cellRobotModel"));
  for (const std::string& name : robot::armModelNames()) m_model->addItem(QString::fromStdString(name).toUpper(), QString::fromStdString(name));
  const QString mm = tr(" mm");
  const QString deg = tr(" °");
  const char* axes[] = {"X", "Y", "Z"};
  for (std::size_t i = 0; i < 3; ++i) {
    const QString a = QString::fromLatin1(axes[i]);
    m_tip[i] = numberBox(group, QStringLiteral("cellNozzle") + a, -2000, 2000, 2, mm);
    m_axis[i] = numberBox(group, QStringLiteral("cellNozzleAxis") + a, -1, 1, 4, QString());
    m_flangeMm[i] = numberBox(group, QStringLiteral("cellFlange") + a, -500, 500, 3, mm);
    m_flangeDegrees[i] = numberBox(group, QStringLiteral("cellFlangeR") + a.toLower(), -180, 180, 3, deg);
  }
  m_table = numberBox(group, QStringLiteral("cellTableZ"), -2000, 2000, 2, mm);
  m_tip[0]->setToolTip(tr("The nozzle tip in the robot base frame (measure it with the TCP; docs/robot-cell.md)"));
  m_axis[0]->setToolTip(tr("Unit vector from the tip up into the extruder, robot base frame"));
  m_flangeMm[0]->setToolTip(tr("Flange to platform centre (the TCP): translation; the calibration"));
  m_flangeDegrees[0]->setToolTip(tr("Flange to platform centre: rotation vector (axis times angle), degrees"));

  auto* load = new QPushButton(tr("Load cell..."), group);
  load->setObjectName(QStringLiteral("cellLoad"));
  auto* save = new QPushButton(tr("Save cell..."), group);
  save->setObjectName(QStringLiteral("cellSave"));
  m_check = new QLabel(group);
  m_check->setObjectName(QStringLiteral("cellCheck"));
  m_check->setWordWrap(true);
  m_message = new QLabel(group);
  m_message->setObjectName(QStringLiteral("cellMessage"));
  m_message->setWordWrap(true);
  m_message->hide();

  m_find = new QPushButton(tr("Find extruder position"), group);
  m_find->setObjectName(QStringLiteral("cellFindNozzle"));
  m_find->setToolTip(tr("Scores nozzle positions over the arm's workspace by the share of the plan's platform poses "
                        "reachable with margin (multidir cell reach)"));
  m_cancel = new QPushButton(tr("Cancel"), group);
  m_cancel->setObjectName(QStringLiteral("cellReachCancel"));
  m_cancel->hide();
  m_progress = new QProgressBar(group);
  m_progress->setObjectName(QStringLiteral("cellReachProgress"));
  m_progress->setRange(0, 1000);
  m_progress->hide();
  m_reach = new QLabel(group);
  m_reach->setObjectName(QStringLiteral("cellReachResult"));
  m_reach->setWordWrap(true);
  m_use = new QPushButton(tr("Use this position"), group);
  m_use->setObjectName(QStringLiteral("cellUseReach"));
  m_use->hide();
  m_job = new CellJob(this);

  auto* form = new QFormLayout;
  form->addRow(tr("Robot:"), m_model);
  form->addRow(tr("Nozzle tip:"), row(group, m_tip));
  form->addRow(tr("Nozzle axis:"), row(group, m_axis));
  form->addRow(tr("Flange to platform:"), row(group, m_flangeMm));
  form->addRow(tr("Platform rotation:"), row(group, m_flangeDegrees));
  form->addRow(tr("Table height:"), m_table);
  auto* files = new QHBoxLayout;
  files->addWidget(load);
  files->addWidget(save);
  auto* reach = new QHBoxLayout;
  reach->addWidget(m_find);
  reach->addWidget(m_cancel);
  auto* inner = new QVBoxLayout(group);
  inner->addLayout(form);
  inner->addLayout(files);
  inner->addWidget(m_check);
  inner->addWidget(m_message);
  inner->addLayout(reach);
  inner->addWidget(m_progress);
  inner->addWidget(m_reach);
  inner->addWidget(m_use);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(group);

  connect(m_model, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &CellPanel::takeFields);
  for (auto* boxes : {&m_tip, &m_axis, &m_flangeMm, &m_flangeDegrees})
    for (QDoubleSpinBox* box : *boxes)
      connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &CellPanel::takeFields);
  connect(m_table, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &CellPanel::takeFields);
  connect(load, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Load robot cell"), QString(), tr("Robot cell (*.json)"));
    if (!path.isEmpty()) loadCellFile(path);
  });
  connect(save, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save robot cell"), QString(), tr("Robot cell (*.json)"));
    if (!path.isEmpty()) saveCellFile(path);
  });
  connect(m_find, &QPushButton::clicked, this, &CellPanel::findExtruderPosition);
  connect(m_cancel, &QPushButton::clicked, this, &CellPanel::cancelReach);
  connect(m_use, &QPushButton::clicked, this, &CellPanel::useBestPosition);
  connect(m_job, &CellJob::progressed, this, [this](double fraction) { m_progress->setValue(static_cast<int>(fraction * 1000)); });
  auto ended = [this] {
    m_progress->hide();
    m_cancel->hide();
    m_find->setEnabled(true);
  };
  connect(m_job, &CellJob::cancelled, this, [this, ended] {
    ended();
    m_reach->setText(tr("Finding the extruder position was cancelled."));
  });
  connect(m_document, &StudioDocument::cellChanged, this, [this] {
    showCell();
    if (m_map && (!m_document->cell() || !reachMapFitsCell(*m_map, *m_document->cell())))
      dropReachMap(tr("The cell changed since the reach map was made (the map scores the arm, the nozzle axis, "
                      "the platform, the table and the margins it had): find the extruder position again."));
  });
  connect(m_document, &StudioDocument::planChanged, this, [this] {
    if (m_map) {
      dropReachMap(tr("The plan changed since the reach map was made (the map scores the plan's poses): find the "
                      "extruder position again."));
    } else {
      m_best.reset();
      m_use->hide();
      m_reach->clear();
    }
  });
  connect(m_document, &StudioDocument::supportsChanged, this, [this] {
    if (m_map)
      dropReachMap(tr("Supports were grown for the plan since the reach map was made (the map scores their poses "
                      "too): find the extruder position again."));
  });
  showCell();
}

void CellPanel::ensureCell() {
  if (m_document->cell()) return;
  loadCellFile(QString::fromUtf8(MULTIDIR_CELLS_DIR) + QStringLiteral("/ur5-fixed-extruder.json"));
}

bool CellPanel::loadCellFile(const QString& path) {
  const core::Result<robot::Cell> cell = robot::parseCell(localPath(path));
  if (!cell) {
    showMessage(tr("Could not load the cell file %1: %2").arg(QFileInfo(path).fileName(),
                                                                QString::fromStdString(cell.error().message)),
                true);
    return false;
  }
  m_document->setCell(*cell);
  showMessage(tr("Cell loaded from %1.").arg(QFileInfo(path).fileName()), false);
  return true;
}

bool CellPanel::saveCellFile(const QString& path) {
  if (!m_document->cell()) {
    showMessage(tr("There is no cell to save."), true);
    return false;
  }
  const core::Status written = robot::writeCell(*m_document->cell(), localPath(path));
  if (!written) {
    showMessage(tr("Could not save the cell: %1").arg(QString::fromStdString(written.error().describe())), true);
    return false;
  }
  showMessage(tr("Cell saved as %1.").arg(QFileInfo(path).fileName()), false);
  return true;
}

void CellPanel::showMessage(const QString& text, bool error) {
  m_message->setText(text);
  m_message->setStyleSheet(error ? QStringLiteral("color: #d03030;") : QString());
  m_message->setVisible(!text.isEmpty());
}

void CellPanel::showCell() {
  const std::optional<robot::Cell>& cell = m_document->cell();
  setEnabled(cell.has_value());
  if (!cell) {
    m_check->setText(tr("No cell."));
    return;
  }
  m_showing = true;
  m_model->setCurrentIndex(m_model->findData(QString::fromStdString(cell->arm.name)));
  const Eigen::AngleAxisd turn(cell->flangeToPlatform.linear());
  const Eigen::Vector3d rotation = turn.axis() * (turn.angle() / kDeg);
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    m_tip[k]->setValue(cell->nozzleTipMm[i]);
    m_axis[k]->setValue(cell->nozzleAxis[i]);
    m_flangeMm[k]->setValue(cell->flangeToPlatform.translation()[i]);
    m_flangeDegrees[k]->setValue(rotation[i]);
  }
  m_table->setValue(cell->tableZMm);
  m_showing = false;
  const std::vector<robot::CellProblem> problems = robot::checkCell(*cell);
  if (problems.empty()) {
    m_check->setText(tr("Cell check: sound (%1, nozzle tip at %2, %3, %4 mm).")
                         .arg(m_model->currentText())
                         .arg(cell->nozzleTipMm.x(), 0, 'f', 1)
                         .arg(cell->nozzleTipMm.y(), 0, 'f', 1)
                         .arg(cell->nozzleTipMm.z(), 0, 'f', 1));
    m_check->setStyleSheet(QStringLiteral("color: #2a8a2a;"));
  } else {
    QString text = tr("Cell check: %n problem(s)", nullptr, static_cast<int>(problems.size()));
    for (const robot::CellProblem& p : problems)
      text += QStringLiteral("\n") + QString::fromStdString(p.key) + QStringLiteral(": ") + QString::fromStdString(p.message);
    m_check->setText(text);
    m_check->setStyleSheet(QStringLiteral("color: #d03030;"));
  }
}

// The fields as the document's cell: the model (with the cell's joint limits kept), the nozzle, the calibration
// and the table; everything else of the cell stays as loaded.
void CellPanel::takeFields() {
  if (m_showing || !m_document->cell()) return;
  robot::Cell cell = *m_document->cell();
  const std::string model = m_model->currentData().toString().toStdString();
  if (model != cell.arm.name) {
    const core::Result<robot::ArmModel> arm = robot::armModel(model);
    if (arm) {
      const auto limits = cell.arm.limits;
      cell.arm = *arm;
      for (std::size_t j = 0; j < 6; ++j) {  // the cell's position limits stay; speeds are the model's
        cell.arm.limits[j].minRad = limits[j].minRad;
        cell.arm.limits[j].maxRad = limits[j].maxRad;
      }
    }
  }
  Eigen::Vector3d rotation;
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    cell.nozzleTipMm[i] = m_tip[k]->value();
    cell.nozzleAxis[i] = m_axis[k]->value();
    cell.flangeToPlatform.translation()[i] = m_flangeMm[k]->value();
    rotation[i] = m_flangeDegrees[k]->value();
  }
  cell.flangeToPlatform.linear() = rotation.norm() > 0.0
                                       ? Eigen::AngleAxisd(rotation.norm() * kDeg, rotation.normalized()).toRotationMatrix()
                                       : Eigen::Matrix3d::Identity();
  // The axis typed is taken as a direction (the file wants it unit; the check would refuse a rounded one).
  if (cell.nozzleAxis.norm() > 1e-9) cell.nozzleAxis.normalize();
  cell.tableZMm = m_table->value();
  m_document->setCell(cell);  // a stale reach map goes on cellChanged
}

bool CellPanel::findExtruderPosition() {
  if (m_job->isRunning()) return false;
  if (!m_document->cell()) {
    m_reach->setText(tr("There is no cell: choose the robot cell machine or load a cell file."));
    return false;
  }
  const auto& run = m_document->plan();
  if (!run || !run->plan) {
    m_reach->setText(tr("There is no plan: the reach map scores the plan's platform poses. Run a search or open a plan."));
    return false;
  }
  const core::Result<std::vector<robot::ReachStep>> steps = robot::reachStepsOfPlan(planAsLoaded(*run, m_document->model()));
  if (!steps) {
    m_reach->setText(tr("The plan's poses cannot be found: %1").arg(QString::fromStdString(steps.error().describe())));
    return false;
  }
  auto result = std::make_shared<core::Result<robot::ReachMap>>(core::Error{core::ErrorCode::Cancelled, "not run", ""});
  const robot::Cell cell = *m_document->cell();
  const std::vector<robot::ReachStep> needed = *steps;
  const robot::ReachMapOptions options;
  const bool started = m_job->start([result, cell, needed, options](core::JobContext context) {
    *result = robot::reachMap(needed, cell, options, context);
    return result->ok() ? QString() : QString::fromStdString(result->error().describe());
  });
  if (!started) return false;
  // One pair of connections per run: the result handler and the cancel handler each drop both.
  auto connection = std::make_shared<QMetaObject::Connection>();
  auto onCancel = std::make_shared<QMetaObject::Connection>();
  // The map belongs to the plan and cell it was started for: a change while it runs makes its result stale.
  const std::shared_ptr<const core::Decomposition> plan = run->plan;
  *connection = connect(m_job, &CellJob::finished, this,
                        [this, result, connection, onCancel, cell, plan, options](const QString& error) {
    disconnect(*connection);
    disconnect(*onCancel);
    m_progress->hide();
    m_cancel->hide();
    m_find->setEnabled(true);
    if (!error.isEmpty()) {
      m_reach->setText(tr("The reach map failed: %1").arg(error));
      return;
    }
    auto map = std::make_shared<CellReachMap>();
    map->map = std::move(**result);
    map->cell = cell;
    map->gridMm = options.gridMm;
    const auto& shown = m_document->plan();
    if (!shown || shown->plan != plan || !m_document->cell() || !reachMapFitsCell(*map, *m_document->cell())) {
      m_reach->setText(tr("The plan or the cell changed while the reach map was made: find the extruder position "
                          "again."));
      return;
    }
    const robot::ReachPoint& best = map->map.best;
    m_best = best;
    m_map = map;
    m_mapGone.clear();
    emit reachMapChanged();
    m_reach->setText(tr("Best nozzle position: %1, %2, %3 mm, %4 % of the plan's poses reachable with margin "
                        "(least reach margin %5 mm) over %6 positions.")
                         .arg(best.nozzleTipMm.x(), 0, 'f', 0)
                         .arg(best.nozzleTipMm.y(), 0, 'f', 0)
                         .arg(best.nozzleTipMm.z(), 0, 'f', 0)
                         .arg(100.0 * best.score, 0, 'f', 1)
                         .arg(std::isfinite(best.leastMarginMm) ? best.leastMarginMm : 0.0, 0, 'f', 1)
                         .arg(map->map.points.size()));
    m_use->setVisible(best.score > 0.0);
  });
  *onCancel = connect(m_job, &CellJob::cancelled, this, [connection, onCancel] {
    disconnect(*connection);
    disconnect(*onCancel);
  });
  m_find->setEnabled(false);
  m_cancel->show();
  m_progress->setValue(0);
  m_progress->show();
  m_reach->setText(tr("Finding the extruder position..."));
  m_use->hide();
  return true;
}

void CellPanel::dropReachMap(const QString& why) {
  m_map = nullptr;
  m_best.reset();
  m_use->hide();
  m_mapGone = why;
  m_reach->setText(why);
  emit reachMapChanged();
}

void CellPanel::cancelReach() { m_job->cancel(); }

bool CellPanel::isFindingPosition() const { return m_job->isRunning(); }

void CellPanel::useBestPosition() {
  if (!m_best || !m_document->cell()) return;
  robot::Cell cell = *m_document->cell();
  cell.nozzleTipMm = m_best->nozzleTipMm;
  m_document->setCell(cell);
  showMessage(tr("The nozzle tip is now at the reach map's best position; move the extruder there and measure "
                 "it again."), false);
}

QString CellPanel::checkText() const { return m_check->text(); }
QString CellPanel::messageText() const { return m_message->text(); }
QString CellPanel::reachText() const { return m_reach->text(); }

}  // namespace multidir::ui

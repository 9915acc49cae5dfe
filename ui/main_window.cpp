#include "ui/main_window.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QStatusBar>
#include <QToolBar>
#include <QVector3D>
#include <cmath>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/samples/samples.h"
#include "ui/jobs/model_loader.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

QVector3D toQVector(const core::Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

core::Vec3 toVec3(const QVector3D& v) { return {v.x(), v.y(), v.z()}; }

QString formatNumber(double value, int decimals) { return QLocale().toString(value, 'f', decimals); }

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(tr("MultiDir Studio"));
  m_viewer = new MeshViewerWidget(this);
  setCentralWidget(m_viewer);
  m_loader = new ModelLoader(this);
  connect(m_loader, &ModelLoader::loaded, this, &MainWindow::showModel);
  connect(m_loader, &ModelLoader::failed, this, &MainWindow::reportLoadError);
  connect(m_loader, &ModelLoader::busyChanged, this, &MainWindow::setBusy);

  buildMenus();
  buildUpBox();
  buildStatusBar();
  updateModelStatus();
  resize(1280, 860);
}

MainWindow::~MainWindow() {
  if (m_loader->isBusy()) QApplication::restoreOverrideCursor();
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* open = file->addAction(tr("&Open..."), this, &MainWindow::chooseFile);
  open->setShortcut(QKeySequence::Open);
  open->setStatusTip(tr("Open a mesh file (STL, OBJ, OFF or PLY)"));

  QMenu* samples = file->addMenu(tr("&Samples"));
  for (const core::samples::SampleInfo& info : core::samples::catalogue()) {
    const QString id = QString::fromStdString(info.id);
    QAction* action = samples->addAction(QString::fromStdString(info.title), this, [this, id] { openSample(id); });
    action->setStatusTip(QString::fromStdString(info.description));
    action->setObjectName(QStringLiteral("sample-") + id);
  }

  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  QAction* fit = view->addAction(tr("&Fit to View"), m_viewer, &MeshViewerWidget::fitView);
  fit->setShortcut(QKeySequence(Qt::Key_F));
}

void MainWindow::buildUpBox() {
  QToolBar* bar = addToolBar(tr("Printing direction"));
  bar->setObjectName(QStringLiteral("upToolBar"));
  bar->setMovable(false);
  auto* label = new QLabel(tr("Up:"), bar);
  label->setContentsMargins(6, 0, 4, 0);
  bar->addWidget(label);
  m_upBox = new QComboBox(bar);
  m_upBox->setObjectName(QStringLiteral("upBox"));
  m_upBox->setToolTip(tr("The direction the model is printed along: the platform is below, "
                         "overhangs are measured against it"));
  const struct {
    QString text;
    core::Vec3 direction;
  } axes[] = {{tr("+X"), core::Vec3::UnitX()},  {tr("-X"), -core::Vec3::UnitX()},
              {tr("+Y"), core::Vec3::UnitY()},  {tr("-Y"), -core::Vec3::UnitY()},
              {tr("+Z"), core::Vec3::UnitZ()},  {tr("-Z"), -core::Vec3::UnitZ()}};
  for (const auto& axis : axes) m_upBox->addItem(axis.text, toQVector(axis.direction));
  m_upBox->setCurrentIndex(4);  // +Z, the samples' up
  connect(m_upBox, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &MainWindow::onUpChanged);
  bar->addWidget(m_upBox);
}

void MainWindow::buildStatusBar() {
  m_busyLabel = new QLabel(this);
  m_busyBar = new QProgressBar(this);
  m_busyBar->setRange(0, 0);  // indeterminate: loadMesh reports no progress
  m_busyBar->setMaximumWidth(120);
  m_busyBar->setTextVisible(false);
  m_busyLabel->hide();
  m_busyBar->hide();
  m_fileLabel = new QLabel(this);
  m_trianglesLabel = new QLabel(this);
  m_volumeLabel = new QLabel(this);
  m_riskyLabel = new QLabel(this);
  for (QLabel* label : {m_busyLabel, m_fileLabel, m_trianglesLabel, m_volumeLabel, m_riskyLabel}) {
    label->setContentsMargins(10, 0, 10, 0);
  }
  statusBar()->addPermanentWidget(m_busyLabel);
  statusBar()->addPermanentWidget(m_busyBar);
  statusBar()->addPermanentWidget(m_fileLabel);
  statusBar()->addPermanentWidget(m_trianglesLabel);
  statusBar()->addPermanentWidget(m_volumeLabel);
  statusBar()->addPermanentWidget(m_riskyLabel);
}

void MainWindow::openFile(const QString& path) {
  m_pendingName = QFileInfo(path).fileName();
  m_loader->loadFile(path);
}

void MainWindow::openSample(const QString& id) {
  m_pendingName = id;
  m_loader->loadSample(id);
}

void MainWindow::chooseFile() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Open Model"), m_lastDirectory,
                                                    tr("Meshes (*.stl *.obj *.off *.ply);;All files (*)"));
  if (path.isEmpty()) return;
  m_lastDirectory = QFileInfo(path).absolutePath();
  openFile(path);
}

void MainWindow::setUpDirection(const core::Vec3& up) {
  const double length = up.norm();
  if (!std::isfinite(length) || length == 0.0) return;
  const core::Vec3 unit = up / length;
  for (int i = 0; i < m_upBox->count(); ++i) {
    if ((toVec3(m_upBox->itemData(i).value<QVector3D>()) - unit).norm() < 1e-6) {
      m_upBox->setCurrentIndex(i);
      return;
    }
  }
  const QString text = tr("Custom (%1, %2, %3)")
                           .arg(formatNumber(unit.x(), 3), formatNumber(unit.y(), 3), formatNumber(unit.z(), 3));
  m_upBox->addItem(text, toQVector(unit));
  m_upBox->setCurrentIndex(m_upBox->count() - 1);
}

core::Vec3 MainWindow::upDirection() const {
  return toVec3(m_upBox->currentData().value<QVector3D>()).normalized();
}

bool MainWindow::isLoading() const { return m_loader->isBusy(); }

void MainWindow::showModel(const LoadedModel& model) {
  m_model = model;
  // Setting the up box redraws through onUpChanged only when it changes; draw once here either way.
  const QSignalBlocker blocker(m_upBox);
  if (model.naturalUp) setUpDirection(*model.naturalUp);
  m_viewer->setMesh(*model.mesh, upDirection());
  setWindowTitle(tr("%1 - MultiDir Studio").arg(model.name));
  statusBar()->clearMessage();
  statusBar()->setToolTip(QString());
  if (!model.repairs.isEmpty()) {
    statusBar()->showMessage(tr("Repaired on load: %1").arg(model.repairs.join(QStringLiteral("; "))));
  }
  updateModelStatus();
  emit modelShown(model.name);
}

void MainWindow::reportLoadError(const QString& source, const QString& headline, const QString& detail) {
  const QString text = tr("Could not open %1: %2").arg(source, headline);
  statusBar()->showMessage(text);
  statusBar()->setToolTip(detail);
  // Non-modal: the window (and any test driving it) keeps running while the message is shown.
  auto* box = new QMessageBox(QMessageBox::Warning, tr("Could not open %1").arg(source), headline,
                              QMessageBox::Ok, this);
  box->setObjectName(QStringLiteral("loadErrorBox"));
  QString informative = detail;
  if (m_model) informative += QStringLiteral("\n\n") + tr("%1 is still open.").arg(m_model->name);
  box->setInformativeText(informative.trimmed());
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->setModal(false);
  box->show();
  emit loadFailed(text);
}

void MainWindow::onUpChanged() {
  if (!m_model) return;
  m_viewer->setMesh(*m_model->mesh, upDirection());
  updateModelStatus();
}

void MainWindow::updateModelStatus() {
  if (!m_model) {
    m_fileLabel->setText(tr("No model"));
    m_trianglesLabel->clear();
    m_volumeLabel->clear();
    m_riskyLabel->clear();
    return;
  }
  const LoadedModel& model = *m_model;
  m_fileLabel->setText(model.name);
  m_fileLabel->setToolTip(model.sourcePath);
  m_trianglesLabel->setText(
      tr("Triangles: %1").arg(QLocale().toString(static_cast<qulonglong>(model.mesh->faceCount()))));
  m_volumeLabel->setText(tr("Volume: %1 mm³").arg(formatNumber(model.statistics.volumeMm3, 1)));
  const core::Result<core::OverhangAnalysis> overhang = core::analyzeOverhang(*model.mesh, upDirection());
  if (overhang) {
    m_riskyLabel->setText(tr("Risky area (%1 up): %2 mm²")
                              .arg(m_upBox->currentText(), formatNumber(overhang->riskyAreaMm2, 1)));
    m_riskyLabel->setToolTip(tr("Area of the faces that overhang by more than %1° for this up direction")
                                 .arg(formatNumber(core::kDefaultAlphaMaxDegrees, 0)));
  } else {
    m_riskyLabel->setText(tr("Risky area unavailable"));
    m_riskyLabel->setToolTip(QString::fromStdString(overhang.error().describe()));
  }
}

void MainWindow::setBusy(bool busy) {
  m_busyLabel->setText(busy ? tr("Loading %1...").arg(m_pendingName) : QString());
  m_busyLabel->setVisible(busy);
  m_busyBar->setVisible(busy);
  if (busy) {
    QApplication::setOverrideCursor(Qt::BusyCursor);
  } else {
    QApplication::restoreOverrideCursor();
  }
  emit loadingChanged(busy);
}

}  // namespace multidir::ui

#include "ui/main_window.h"

#include <QAction>
#include <QCloseEvent>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QStatusBar>
#include <QTimer>
#include <QLayout>
#include <QScreen>
#include <QToolBar>
#include <QVBoxLayout>
#include <QVector3D>
#include <cmath>
#include <iterator>
#include <limits>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/plan/checksum.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/samples/samples.h"
#include "multidir/core/search/pose_search.h"
#include "multidir/core/search/search_options.h"
#include "ui/device/hardware_panel.h"
#include "ui/edit/plan_editor.h"
#include "ui/common/error_text.h"
#include "ui/jobs/model_loader.h"
#include "ui/jobs/support_regrowth.h"
#include "ui/panels/apart_panel.h"
#include "ui/panels/machine_panel.h"
#include "ui/panels/overhang_panel.h"
#include "ui/panels/plan_panel.h"
#include "ui/panels/pose_search_box.h"
#include "ui/panels/search_panel.h"
#include "ui/panels/slice_panel.h"
#include "ui/project/project_session.h"
#include "ui/project/window_state.h"
#include "ui/slicing/slice_session.h"
#include "ui/common/picture_file.h"
#include "ui/studio_startup.h"
#include "ui/viewer/axis_picker.h"
#include "ui/viewer/mesh_viewer_widget.h"
#include "ui/viewer/view_actions.h"
#include "ui/common/wheel_needs_focus.h"

namespace multidir::ui {
namespace {

QVector3D toQVector(const core::Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

core::Vec3 toVec3(const QVector3D& v) { return {v.x(), v.y(), v.z()}; }

QString formatNumber(double value, int decimals) { return QLocale().toString(value, 'f', decimals); }

// The Up box: its first entries are the six axis directions; an entry's UpPose (when a pose search chose it)
// is kept under this role.
constexpr int kAxisEntries = 6;
constexpr int kPoseRole = Qt::UserRole + 1;

std::string localPath(const QString& path) { return QFile::encodeName(path).toStdString(); }

// One mesh holding every region of a plan: what a plan opened without its model is shown over.
core::TriangleMesh mergedRegions(const core::Decomposition& plan) {
  core::TriangleMesh merged;
  for (const core::Region& region : plan.regions) {
    const auto base = static_cast<std::int32_t>(merged.vertices.size());
    merged.vertices.insert(merged.vertices.end(), region.mesh.vertices.begin(), region.mesh.vertices.end());
    for (const core::Triangle& t : region.mesh.triangles) merged.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  merged.resetOrigins();
  return merged;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  // First, so that every field built below is polished with it: the wheel changes a field only with focus.
  qApp->installEventFilter(new WheelNeedsFocus(this));
  setWindowTitle(tr("MultiDir Studio"));
  m_document = new StudioDocument(this);
  connect(m_document, &StudioDocument::planChanged, this, &MainWindow::onDocumentPlanChanged);
  m_viewer = new MeshViewerWidget(this);
  setCentralWidget(m_viewer);
  m_loader = new ModelLoader(this);
  connect(m_loader, &ModelLoader::loaded, this, &MainWindow::showModel);
  connect(m_loader, &ModelLoader::failed, this, &MainWindow::reportLoadError);
  connect(m_loader, &ModelLoader::busyChanged, this, &MainWindow::setBusy);
  m_search = new SearchJob(this);
  m_regrowth = new SupportRegrowth(this);
  connect(m_regrowth, &SupportRegrowth::grown, this, &MainWindow::onSupportsRegrown);

  m_poseSearch = new PoseSearchJob(this);
  buildDocks();
  buildPoseSearch();
  m_project = new ProjectSession(*this);
  buildMenus();
  buildUpBox();
  buildStatusBar();
  updateModelStatus();
  onMachineChanged();
  resize(initialWindowSize(screen() != nullptr ? screen()->availableGeometry().size() : kPreferredWindowSize));
  restoreWindowState(*this);
}

MainWindow::~MainWindow() {
  if (m_loader->isBusy()) QApplication::restoreOverrideCursor();
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* open = file->addAction(tr("&Open..."), this, &MainWindow::chooseFile);
  open->setObjectName(QStringLiteral("openModel"));
  open->setShortcut(QKeySequence::Open);
  open->setStatusTip(tr("Open a mesh file (STL, OBJ, OFF or PLY) or a MultiDir project"));
  m_project->addFileActions(file);

  QMenu* samples = file->addMenu(tr("Sa&mples"));
  for (const core::samples::SampleInfo& info : core::samples::catalogue()) {
    const QString id = QString::fromStdString(info.id);
    QAction* action =
        samples->addAction(QString::fromStdString(info.title), this, [this, id] { openSampleFromUser(id); });
    action->setStatusTip(QString::fromStdString(info.description));
    action->setObjectName(QStringLiteral("sample-") + id);
  }

  file->addSeparator();
  QAction* openPlanAction = file->addAction(tr("Open pla&n..."), this, &MainWindow::chooseOpenPlan);
  openPlanAction->setObjectName(QStringLiteral("openPlan"));
  openPlanAction->setStatusTip(tr("Show a plan saved earlier (a folder with plan.json)"));
  m_exportPlanAction = file->addAction(tr("&Export plan..."), this, &MainWindow::chooseExportPlan);
  m_exportPlanAction->setObjectName(QStringLiteral("exportPlan"));
  m_exportPlanAction->setStatusTip(tr("Save the plan shown: plan.json and one STL per region"));
  m_exportPlanAction->setEnabled(false);
  QAction* exportGcode = file->addAction(tr("Export &G-code..."), m_slicing, &SliceSession::chooseExportGcode);
  exportGcode->setObjectName(QStringLiteral("exportGcode"));
  exportGcode->setStatusTip(tr("Save the sliced plan's G-code (step-NN.gcode, job.gcode) and its print job"));
  exportGcode->setEnabled(false);
  connect(m_slicing, &SliceSession::resultAvailable, exportGcode, &QAction::setEnabled);
  QAction* screenshot = file->addAction(tr("Export Screens&hot..."), this, &MainWindow::chooseExportScreenshot);
  screenshot->setObjectName(QStringLiteral("exportScreenshot"));
  screenshot->setStatusTip(tr("Save the 3D view as shown to a PNG or JPEG file"));
  file->addSeparator();
  QAction* loadMachine = file->addAction(tr("&Load machine profile..."), this, &MainWindow::chooseLoadMachine);
  loadMachine->setObjectName(QStringLiteral("loadMachine"));
  QAction* saveMachine = file->addAction(tr("Save machine pro&file..."), this, &MainWindow::chooseSaveMachine);
  saveMachine->setObjectName(QStringLiteral("saveMachine"));
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  buildEditMenu();
  m_viewMenu = menuBar()->addMenu(tr("&View"));
  QAction* fit = m_viewMenu->addAction(tr("&Fit to View"), m_viewer, &MeshViewerWidget::fitView);
  fit->setShortcut(QKeySequence(Qt::Key_F));
  QAction* modelView = m_viewMenu->addAction(tr("Show the &model (hide the plan)"), this, &MainWindow::clearPlan);
  modelView->setObjectName(QStringLiteral("showModel"));
  QToolBar* viewBar = addToolBar(tr("View"));
  viewBar->setObjectName(QStringLiteral("viewToolBar"));
  addViewActions(m_viewer, m_viewMenu, viewBar);
  m_viewMenu->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>()) m_viewMenu->addAction(dock->toggleViewAction());

  QMenu* search = menuBar()->addMenu(tr("&Search"));
  QAction* run = search->addAction(tr("&Run"), this, &MainWindow::runSearchFromUser);
  run->setObjectName(QStringLiteral("runSearch"));
  run->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
  // Esc also ends picking the rotation axis, wherever the focus is.
  QAction* cancel = search->addAction(tr("&Cancel"), this, [this] {
    if (m_axisPicker->isActive()) {
      m_axisPicker->cancel();
    } else if (isPoseSearching()) {
      cancelPoseSearch();
    } else {
      cancelSearch();
    }
  });
  cancel->setShortcut(QKeySequence(Qt::Key_Escape));

  search->addSeparator();
  // Slicing from the menu and the keyboard as from the Plan dock's button: the same dialog, the same refusals.
  QAction* slice = search->addAction(tr("S&lice the plan..."), m_slicing, &SliceSession::chooseAndSlice);
  slice->setObjectName(QStringLiteral("slicePlan"));
  slice->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
  slice->setStatusTip(tr("Slice every step of the plan shown, with its supports, into G-code (PrusaSlicer)"));
  slice->setEnabled(false);
  connect(m_slicing, &SliceSession::sliceableChanged, slice, &QAction::setEnabled);
  QAction* printApart = search->addAction(tr("Print &apart..."), this, [this] {
    auto* dock = findChild<QDockWidget*>(QStringLiteral("apartDock"));
    dock->show();
    dock->raise();
  });
  printApart->setObjectName(QStringLiteral("printApart"));
  printApart->setStatusTip(tr("Print the plan shown on an ordinary printer: every region a part, joined by dowels"));
  printApart->setEnabled(m_document->plan().has_value());
  connect(m_document, &StudioDocument::planChanged, printApart,
          [this, printApart] { printApart->setEnabled(m_document->plan().has_value()); });

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  QAction* about = help->addAction(tr("&About MultiDir Studio"), this, &MainWindow::showAbout);
  about->setObjectName(QStringLiteral("about"));
  about->setMenuRole(QAction::AboutRole);
}

void MainWindow::showAbout() {
  // Non-modal: nothing waits on it, and a test reads it like the user does.
  auto* box = new QMessageBox(QMessageBox::Information, tr("About MultiDir Studio"),
                              tr("MultiDir Studio %1").arg(studioVersion()), QMessageBox::Ok, this);
  box->setObjectName(QStringLiteral("aboutBox"));
  box->setInformativeText(tr("Plans multi-directional 3D prints: cuts a model by planes into regions, each printed "
                             "along its own direction, and drives the machine that prints them.\n\nQt %1")
                              .arg(QString::fromLatin1(qVersion())));
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->setModal(false);
  box->show();
}

void MainWindow::buildDocks() {
  // On a small screen (1280x720) the docks share little height: a panel scrolls inside its dock rather than
  // push the dock tab bar and the status bar off screen. The Hardware panel scrolls itself (E-STOP stays out).
  auto addDock = [this](QWidget* panel, const QString& title, const QString& name, bool scrolls = true) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    if (scrolls) {
      auto* scroll = new QScrollArea(dock);
      scroll->setWidgetResizable(true);
      scroll->setFrameShape(QFrame::NoFrame);
      scroll->setWidget(panel);
      dock->setWidget(scroll);
    } else {
      dock->setWidget(panel);
    }
    dock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    addDockWidget(Qt::RightDockWidgetArea, dock);
    return dock;
  };
  m_overhangPanel = new OverhangPanel(this);
  m_machinePanel = new MachinePanel(m_document, this);
  m_searchPanel = new SearchPanel(this);
  m_planPanel = new PlanPanel(this);
  QDockWidget* overhangs = addDock(m_overhangPanel, tr("Overhangs"), QStringLiteral("overhangDock"));
  QDockWidget* machine = addDock(m_machinePanel, tr("Machine"), QStringLiteral("machineDock"));
  m_searchDock = addDock(m_searchPanel, tr("Search"), QStringLiteral("searchDock"));
  // The Plan dock holds the plan and, under it, its G-code (ui/slicing).
  auto* planColumn = new QWidget(this);
  auto* planLayout = new QVBoxLayout(planColumn);
  planLayout->setContentsMargins(0, 0, 0, 0);
  planLayout->addWidget(m_planPanel, 1);
  auto* slicePanel = new SlicePanel(planColumn);
  planLayout->addWidget(slicePanel);
  m_slicing = new SliceSession(*this, slicePanel);
  m_planDock = addDock(planColumn, tr("Plan"), QStringLiteral("planDock"));
  splitDockWidget(overhangs, machine, Qt::Vertical);
  tabifyDockWidget(machine, m_searchDock);
  tabifyDockWidget(m_searchDock, m_planDock);
  // Print apart (docs/apart.md): the plan shown as parts for an ordinary printer; opened from its menu entry.
  QDockWidget* apart = addDock(new ApartPanel(*m_document, this), tr("Print apart"), QStringLiteral("apartDock"));
  tabifyDockWidget(m_planDock, apart);
  m_searchDock->raise();
  // Wide enough for the pose and estimate tables without sideways scrolling (ui/common/table_columns.h).
  resizeDocks({overhangs}, {540}, Qt::Horizontal);

  connect(m_overhangPanel, &OverhangPanel::alphaMaxChanged, this, [this] { updateOverhangs(); });
  // One alpha_max, shown in both panels: each follows the other (setting an equal value emits nothing).
  connect(m_overhangPanel, &OverhangPanel::alphaMaxChanged, m_searchPanel, &SearchPanel::setAlphaMaxDegrees);
  connect(m_searchPanel, &SearchPanel::alphaMaxChanged, m_overhangPanel, &OverhangPanel::setAlphaMaxDegrees);
  connect(m_document, &StudioDocument::machineChanged, this, &MainWindow::onMachineChanged);
  connect(m_searchPanel, &SearchPanel::runClicked, this, &MainWindow::runSearchFromUser);
  connect(m_searchPanel, &SearchPanel::cancelClicked, this, &MainWindow::cancelSearch);
  // A search being abandoned reports nothing more: the panel already shows another model.
  connect(m_search, &SearchJob::progressed, this, [this](const core::SearchProgress& progress) {
    if (!m_dropSearchResult) m_searchPanel->showProgress(progress);
  });
  connect(m_search, &SearchJob::fractionChanged, this, [this](double fraction, const QString& phase) {
    if (!m_dropSearchResult) m_searchPanel->showFraction(fraction, phase);
  });
  connect(m_search, &SearchJob::finished, this, &MainWindow::onSearchFinished);
  connect(m_search, &SearchJob::failed, this, &MainWindow::onSearchFailed);
  connect(m_search, &SearchJob::runningChanged, this, [this] { updateRunnable(); });

  connect(m_planPanel, &PlanPanel::directionsVisibleChanged, m_viewer, &MeshViewerWidget::setPrintingDirectionsVisible);
  connect(m_planPanel, &PlanPanel::clippingPlanesVisibleChanged, m_viewer, &MeshViewerWidget::setClippingPlanesVisible);
  connect(m_planPanel, &PlanPanel::explodeDistanceChanged, m_viewer, &MeshViewerWidget::setExplodeDistance);
  connect(m_planPanel, &PlanPanel::shownRegionsChanged, m_viewer, &MeshViewerWidget::setShownRegions);
  connect(m_planPanel, &PlanPanel::turnWithMachineChanged, m_viewer, &MeshViewerWidget::setTurnWithMachine);
  connect(m_planPanel, &PlanPanel::supportsVisibleChanged, m_viewer, &MeshViewerWidget::setSupportsVisible);

  // The 4-DOF axis picked on the platform goes into the Machine panel as if typed.
  m_axisPicker = new AxisPicker(m_viewer, this);
  connect(m_machinePanel, &MachinePanel::pickAxisToggled, m_axisPicker, [this](bool on) {
    if (on) {
      m_axisPicker->start();
    } else {
      m_axisPicker->cancel();
    }
  });
  connect(m_axisPicker, &AxisPicker::activeChanged, m_machinePanel, &MachinePanel::setPicking);
  connect(m_axisPicker, &AxisPicker::axisPicked, this,
          [this](const core::Vec3& axis) { m_machinePanel->setRotationAxis(axis, upDirection()); });
  buildRobotCell(m_planDock);
  connect(m_axisPicker, &AxisPicker::message, this, [this](const QString& text) { statusBar()->showMessage(text); });

  // Hardware: it reads the document's machine (the device's limits) and the device session's job (the plan
  // shown with its sliced G-code), which a print run pins while it lasts.
  auto* hardwarePanel = new HardwarePanel(m_document, this);
  m_hardwarePanel = hardwarePanel;
  tabifyDockWidget(m_planDock, addDock(hardwarePanel, tr("Hardware"), QStringLiteral("hardwareDock"), false));
  // A second E-STOP, above everything, while a device is connected: the dock may be tabbed away or closed.
  QToolBar* estopBar = addToolBar(tr("Emergency stop"));
  estopBar->setObjectName(QStringLiteral("emergencyStopToolBar"));
  estopBar->setMovable(false);
  estopBar->toggleViewAction()->setVisible(false);  // it cannot be hidden from the toolbar menu
  QAction* estop = hardwarePanel->addEmergencyStopTo(estopBar);
  // The toolbar row is as tall without the E-STOP as with it: connecting does not push the view down.
  if (QWidget* button = estopBar->widgetForAction(estop)) {
    const QMargins margins = estopBar->contentsMargins();
    estopBar->setMinimumHeight(button->sizeHint().height() + margins.top() + margins.bottom() +
                               2 * estopBar->layout()->contentsMargins().top());
  }
  // The sliced job's G-code and estimates become the document's sliced job; dropped with the slicing result.
  connect(m_slicing, &SliceSession::sliced, this, [this] {
    const std::optional<SliceOutcome>& outcome = m_slicing->outcome();
    if (!outcome || !outcome->job || !plan()) return;
    PrintJob job;
    job.plan = plan()->plan;  // SliceSession reports only a job sliced from the plan shown
    for (const slicing::SlicedStep& step : outcome->job->steps)
      job.steps.push_back({QDir(outcome->folderPath()).filePath(QString::fromStdString(step.gcodeFile)).toStdString(),
                           step.estimate.printSeconds});
    job.files = outcome->folder;
    if (const core::Status taken = m_document->setSlicedJob(std::move(job)); !taken)
      statusBar()->showMessage(QString::fromStdString(taken.error().message));
  });
  connect(m_slicing, &SliceSession::resultAvailable, m_document, [this](bool available) {
    if (!available) m_document->clearSlicedJob();
  });
  // During a run the view shows what is on the platform: the regions printed so far and the one being
  // printed; all of them again when the run ends. Through the Plan panel, so its stepper agrees (and clamps).
  connect(hardwarePanel, &HardwarePanel::currentRegionChanged, m_planPanel, [this](int region) {
    m_planPanel->setShownRegions(region >= 0 ? region + 1 : std::numeric_limits<int>::max());
  });
  buildPlanEditing();
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
  // As wide as its entries: a pose's "Pose: 0.60, 0.00, 0.80" is read whole, not as "Po:".
  m_upBox->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  m_upBox->setToolTip(tr("The direction the model is printed along: the platform is below, "
                         "overhangs are measured against it"));
  const struct {
    QString text;
    core::Vec3 direction;
  } axes[] = {{tr("+X"), core::Vec3::UnitX()},  {tr("-X"), -core::Vec3::UnitX()},
              {tr("+Y"), core::Vec3::UnitY()},  {tr("-Y"), -core::Vec3::UnitY()},
              {tr("+Z"), core::Vec3::UnitZ()},  {tr("-Z"), -core::Vec3::UnitZ()}};
  for (const auto& axis : axes) m_upBox->addItem(axis.text, toQVector(axis.direction));
  static_assert(static_cast<int>(std::size(axes)) == kAxisEntries);
  m_upBox->setCurrentIndex(4);  // +Z, the samples' up
  m_upIndex = 4;
  connect(m_upBox, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &MainWindow::onUpBoxChosen);
  bar->addWidget(m_upBox);
  // The box shows the document's up, whoever set it.
  connect(m_document, &StudioDocument::upChanged, this, &MainWindow::onDocumentUpChanged);
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
  if (ProjectSession::isProjectFile(path)) {
    m_project->openProject(path);
    return;
  }
  m_pendingName = QFileInfo(path).fileName();
  m_loader->loadFile(path);
}

void MainWindow::openSample(const QString& id) {
  m_pendingName = id;
  m_loader->loadSample(id);
}

void MainWindow::openSampleFromUser(const QString& id) {
  m_project->whenWorkMayBeReplaced([this, id] { openSample(id); });
}

void MainWindow::openPlanFromUser(const QString& directory) {
  rememberDialogFolder(FileKind::Plan, directory);
  m_project->whenWorkMayBeReplaced([this, directory] {
    QString error;
    if (!openPlan(directory, &error)) QMessageBox::warning(this, tr("Open Plan"), error);
  });
}

void MainWindow::abandonSearch() {
  if (m_poseSearch->isRunning()) {
    m_dropPoseResult = true;
    m_poseSearch->cancel();
    m_machinePanel->poseBox()->clear();
    statusBar()->showMessage(tr("The pose search was stopped; its result is dropped."));
  }
  if (!m_search->isRunning()) return;
  m_dropSearchResult = true;
  m_search->cancel();
  m_searchPanel->searchDropped();
  statusBar()->showMessage(tr("The search was stopped; its result is dropped."));
}

QString MainWindow::dialogFolder(FileKind kind) const {
  const QString remembered = rememberedDialogFolder(kind);
  if (!remembered.isEmpty()) return remembered;
  if (kind != FileKind::Model && !m_project->projectPath().isEmpty())
    return QFileInfo(m_project->projectPath()).absolutePath();
  if (model() && !model()->sourcePath.isEmpty()) return QFileInfo(model()->sourcePath).absolutePath();
  return QString();
}

void MainWindow::chooseFile() {
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Open Model or Project"), dialogFolder(FileKind::Model),
      tr("Meshes and projects (*.stl *.obj *.off *.ply *.multidir);;Meshes (*.stl *.obj *.off *.ply);;"
         "MultiDir projects (*.multidir);;All files (*)"));
  if (path.isEmpty()) return;
  m_project->openFromUser(path);
}

void MainWindow::applyUpEntry(int index) {
  const QVariant pose = m_upBox->itemData(index, kPoseRole);
  if (pose.isValid())
    m_document->setUpPose(pose.value<UpPose>());
  else
    m_document->setUp(toVec3(m_upBox->itemData(index).value<QVector3D>()));
}

void MainWindow::setUpDirection(const core::Vec3& up) {
  const double length = up.norm();
  if (!std::isfinite(length) || length == 0.0) return;
  // The direction in force already (a pose's too): nothing changes, the pose stays.
  if ((up / length - m_document->up()).norm() <= 1e-9) return;
  m_document->setUp(up);
}

void MainWindow::onDocumentUpChanged() {
  if (m_showingModel) return;  // showModel shows the new model's up and draws it once
  const int index = selectUpEntry(m_document->up(), m_document->upPose());
  if (index == m_upIndex) {
    markPoseInUse();
    return;
  }
  m_upIndex = index;
  onUpChanged();
}

int MainWindow::selectUpEntry(const core::Vec3& unit, const std::optional<UpPose>& pose) {
  // The box's own signal is for the user's choices (onUpBoxChosen); the callers apply the entry themselves.
  const QSignalBlocker blocker(m_upBox);
  auto xyz = [&unit] {
    return tr("%1, %2, %3").arg(formatNumber(unit.x(), 2), formatNumber(unit.y(), 2), formatNumber(unit.z(), 2));
  };
  int index = -1;
  for (int i = 0; i < m_upBox->count() && index < 0; ++i) {
    if ((toVec3(m_upBox->itemData(i).value<QVector3D>()) - unit).norm() < 1e-6) index = i;
  }
  if (index < 0) {
    const QString text = pose ? tr("Pose: %1").arg(xyz())
                              : tr("Custom (%1, %2, %3)")
                                    .arg(formatNumber(unit.x(), 3), formatNumber(unit.y(), 3), formatNumber(unit.z(), 3));
    m_upBox->addItem(text, toQVector(unit));
    index = m_upBox->count() - 1;
  } else if (pose && index >= kAxisEntries) {
    m_upBox->setItemText(index, tr("Pose: %1").arg(xyz()));  // a custom entry becomes the pose's
  }
  // The pose stays with its entry: choosing the entry again later is choosing the pose again.
  if (pose) m_upBox->setItemData(index, QVariant::fromValue(*pose), kPoseRole);
  m_upBox->setCurrentIndex(index);
  return index;
}

void MainWindow::onUpBoxChosen(int index) {
  if (index == m_upIndex || index < 0) return;
  const bool dropsWork = isSearching() || (plan().has_value() && m_project->isModified());
  auto apply = [this, index] {
    if (index >= m_upBox->count()) return;
    {
      const QSignalBlocker blocker(m_upBox);
      m_upBox->setCurrentIndex(index);
    }
    applyUpEntry(index);  // the document's upChanged redraws (onDocumentUpChanged)
    m_upIndex = index;    // also when the entry is the document's up already
  };
  if (!dropsWork) {
    apply();
    return;
  }
  // The box shows the direction in force until the question is answered.
  {
    const QSignalBlocker blocker(m_upBox);
    m_upBox->setCurrentIndex(m_upIndex);
  }
  m_project->whenWorkMayBeReplaced(apply);
}

// The document's: a pose's up is kept at full precision (the Up box entry's own vector is a float one): saved
// and reopened, and compared with the pose search's trials, it stays bit for bit the same.
core::Vec3 MainWindow::upDirection() const { return m_document->up(); }

std::optional<UpPose> MainWindow::upPose() const { return m_document->upPose(); }

void MainWindow::setUpPose(const UpPose& pose) { m_document->setUpPose(pose); }

bool MainWindow::isLoading() const { return m_loader->isBusy(); }

void MainWindow::showModel(const LoadedModel& model) {
  m_previewUp.reset();  // setMesh below shows the model with its own up
  m_poseRun.reset();    // the poses listed were another model's
  m_machinePanel->poseBox()->clear();
  // The document drops the last model's pose (its machine turns back with it), plan and job, and takes the up
  // the model comes with. The Up box shows that up without redrawing: it is drawn once below. Only here:
  // whoever answers modelShown (a project applying its own up direction) must redraw.
  // The Machine panel follows the document's machine (turned back with the pose) by itself.
  m_showingModel = true;
  m_document->setModel(model);
  if (m_pendingPlan) m_document->setUp(m_pendingPlan->machine.up);
  m_showingModel = false;
  {
    // A pose entry of the Up box is the last model's pose: it goes with it.
    const QSignalBlocker blocker(m_upBox);
    for (int i = m_upBox->count() - 1; i >= kAxisEntries; --i)
      if (m_upBox->itemData(i, kPoseRole).isValid()) m_upBox->removeItem(i);
  }
  m_upIndex = selectUpEntry(m_document->up());
  clearPlan();
  m_searchPanel->clearResult();
  m_viewer->setMesh(*model.mesh, upDirection());
  m_planPanel->setModelSize(modelSizeMm());
  m_machinePanel->setPickAvailable(true);
  setWindowTitle(tr("%1 - MultiDir Studio").arg(model.name));
  statusBar()->clearMessage();
  statusBar()->setToolTip(QString());
  if (!model.repairs.isEmpty()) {
    statusBar()->showMessage(tr("Repaired on load: %1").arg(model.repairs.join(QStringLiteral("; "))));
  }
  updateModelStatus();
  updateOverhangs();
  onMachineChanged();
  emit modelShown(model.name);
  if (m_pendingPlan) {
    const SearchRun pending = *m_pendingPlan;
    m_pendingPlan.reset();
    showPlan(pending);
  }
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
  if (model()) informative += QStringLiteral("\n\n") + tr("%1 is still open.").arg(model()->name);
  box->setInformativeText(informative.trimmed());
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->setModal(false);
  box->show();
  emit loadFailed(text);
}

void MainWindow::onUpChanged() {
  m_previewUp.reset();  // setMesh below shows the new up (the document dropped the plan if it moved)
  markPoseInUse();
  onMachineChanged();
  emit upDirectionChanged();
  m_viewer->setEmptyUp(upDirection());  // an empty view's axes marker follows the up too
  if (!model()) return;
  clearPlan();
  m_viewer->setMesh(*model()->mesh, upDirection());
  updateModelStatus();
  updateOverhangs();
}

void MainWindow::updateModelStatus() {
  if (!model()) {
    m_fileLabel->setText(tr("No model"));
    m_trianglesLabel->clear();
    m_volumeLabel->clear();
    m_riskyLabel->clear();
    return;
  }
  const LoadedModel& model = *this->model();
  m_fileLabel->setText(model.name);
  m_fileLabel->setToolTip(model.sourcePath);
  m_trianglesLabel->setText(
      tr("Triangles: %1").arg(QLocale().toString(static_cast<qulonglong>(model.mesh->faceCount()))));
  m_volumeLabel->setText(tr("Volume: %1 mm³").arg(formatNumber(model.statistics.volumeMm3, 1)));
}

void MainWindow::updateOverhangs() {
  if (!model()) {
    m_riskyLabel->clear();
    m_overhangPanel->showUnavailable(tr("No model"));
    return;
  }
  core::OverhangOptions options;
  options.alphaMaxDegrees = m_overhangPanel->alphaMaxDegrees();
  const core::Result<core::OverhangAnalysis> overhang = core::analyzeOverhang(*model()->mesh, upDirection(), options);
  if (!overhang) {
    const QString reason = QString::fromStdString(overhang.error().describe());
    m_riskyLabel->setText(tr("Risky area unavailable"));
    m_riskyLabel->setToolTip(reason);
    m_overhangPanel->showUnavailable(reason);
    m_viewer->setRiskyFaces(std::vector<char>(model()->mesh->faceCount(), 0));
    return;
  }
  m_viewer->setRiskyFaces(overhang->risky);
  m_overhangPanel->showResult(overhang->riskyAreaMm2, overhang->riskyFaces, model()->mesh->faceCount());
  m_riskyLabel->setText(tr("Risky area (%1 up): %2 mm²")
                            .arg(m_upBox->currentText(), formatNumber(overhang->riskyAreaMm2, 1)));
  m_riskyLabel->setToolTip(tr("Area of the faces that overhang by more than %1° for this up direction")
                               .arg(options.alphaMaxDegrees));
}

void MainWindow::onMachineChanged() {
  // The document's machine (the Machine panel sent its edits there and says what is wrong with it).
  const core::MachineSpec& machine = m_document->machine();
  const bool rotary = machine.kind == core::MachineKind::RotaryPlatform;
  std::optional<core::Vec3> axis;
  if (rotary && machine.rotationAxis.norm() > 0.0) axis = machine.rotationAxis.normalized();
  m_viewer->setRotationAxis(axis);
  if (!rotary && m_axisPicker) m_axisPicker->cancel();
  m_searchPanel->setRotaryMachine(rotary);
  m_searchPanel->setApartMachine(machine.kind == core::MachineKind::Apart);
  updateRunnable();
}

void MainWindow::updateRunnable() {
  if (!model()) {
    m_searchPanel->setRunnable(false, tr("Open a model first."));
  } else if (!m_machinePanel->errorText().isEmpty()) {
    m_searchPanel->setRunnable(false, tr("Fix the machine first: %1").arg(m_machinePanel->errorText()));
  } else if (m_poseSearch->isRunning()) {
    m_searchPanel->setRunnable(false, tr("A pose search is running: wait for it or cancel it."));
  } else {
    m_searchPanel->setRunnable(true, QString());
  }
  updatePoseRunnable();
}

double MainWindow::modelSizeMm() const {
  if (!model()) return 0.0;
  const auto box = core::boundingBox(*model()->mesh);
  return (box.max - box.min).norm();
}

bool MainWindow::isSearching() const { return m_search->isRunning() || m_poseSearch->isRunning(); }

bool MainWindow::runSearch() {
  QString problem;
  if (m_search->isRunning()) problem = tr("A search is already running.");
  else if (m_poseSearch->isRunning()) problem = tr("A pose search is running: wait for it or cancel it.");
  else if (!model()) problem = tr("Open a model first.");
  else if (!m_machinePanel->validateFor(upDirection())) problem = m_machinePanel->errorText();
  const core::SearchOptions options = m_searchPanel->searchOptions();
  if (problem.isEmpty()) {
    const core::Status valid = core::validate(options);
    if (!valid) problem = tr("%1 (%2)").arg(errorHeadline(valid.error().code),
                                             QString::fromStdString(valid.error().describe()));
  }
  if (!problem.isEmpty()) {
    statusBar()->showMessage(tr("Cannot search: %1").arg(problem));
    m_searchPanel->searchFailed(tr("Cannot search."), problem);
    emit searchFailed(problem);
    return false;
  }
  const core::MachineSpec machine = m_document->machine();
  m_searchModel = model()->mesh;
  m_searchUp = upDirection();
  core::OverhangOptions overhang;
  overhang.alphaMaxDegrees = options.alphaMaxDegrees;
  overhang.supportedBandMm = options.supportedBandMm;
  const core::Result<core::OverhangAnalysis> before = core::analyzeOverhang(*model()->mesh, m_searchUp, overhang);
  if (!m_search->start(model()->mesh, machine, options, m_searchPanel->axisSearchCount())) return false;
  m_searchPanel->searchStarted(before ? before->riskyAreaMm2 : 0.0, core::maxSearchLevels(options));
  m_searchDock->raise();
  statusBar()->showMessage(tr("Searching %1...").arg(model()->name));
  return true;
}

void MainWindow::runSearchFromUser() {
  // An edited plan that is not saved is asked about first: the search replaces it (Undo brings it back).
  if (m_search->isRunning() || !m_planEditor->isEdited() || !m_project->isModified()) {
    runSearch();
    return;
  }
  if (m_replaceQuestion) {
    m_replaceQuestion->raise();
    return;
  }
  auto* box = new QMessageBox(QMessageBox::Question, tr("Replace the Edited Plan"),
                              tr("The plan shown has edits that are not saved."), QMessageBox::NoButton, this);
  box->setObjectName(QStringLiteral("replaceEditedPlanBox"));
  box->setInformativeText(tr("A new search replaces it; Edit > Undo brings it back. Search now?"));
  QPushButton* search = box->addButton(tr("&Search"), QMessageBox::AcceptRole);
  search->setObjectName(QStringLiteral("searchAnyway"));
  box->addButton(QMessageBox::Cancel);
  box->setDefaultButton(QMessageBox::Cancel);
  box->setWindowModality(Qt::WindowModal);
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::finished, this, [this, box, search] {
    if (box->clickedButton() == search) QTimer::singleShot(0, this, [this] { runSearch(); });
  });
  m_replaceQuestion = box;
  box->open();
}

void MainWindow::cancelSearch() {
  if (!m_search->isRunning()) return;
  m_search->cancel();
  m_searchPanel->cancelRequested();
  statusBar()->showMessage(tr("Cancelling the search..."));
}

void MainWindow::onSearchFinished(const SearchRun& run) {
  if (m_dropSearchResult) {
    m_dropSearchResult = false;
    m_searchModel.reset();
    return;
  }
  const bool current = model() && model()->mesh == m_searchModel && (upDirection() - m_searchUp).norm() < 1e-9;
  m_searchModel.reset();
  m_searchPanel->searchFinished(*run.plan);
  if (!current) {
    statusBar()->showMessage(tr("The search result was dropped: the model or its up direction changed."));
    return;
  }
  // A plan shown of this model, which editing knows: the search's plan replaces it as one undo step.
  const bool replacesShown = m_planShown && plan() && plan()->plan && m_planEditor->canEdit();
  if (replacesShown && run.plan->cancelled && plan()->plan->jgAfterMm2 < run.plan->jgAfterMm2) {
    // A search cut short found less than the plan shown has: that plan stays, and the panel says so.
    const QString text = tr("Search cancelled: its best plan so far (J_G %1 mm²) is worse than the plan shown (J_G %2 mm²), "
                            "which is kept.")
                             .arg(formatNumber(run.plan->jgAfterMm2, 1), formatNumber(plan()->plan->jgAfterMm2, 1));
    m_searchPanel->noteKeptPlan(text);
    statusBar()->showMessage(text);
    emit searchFinished(run);
    return;
  }
  statusBar()->showMessage(run.plan->cancelled ? tr("Search cancelled: showing the best plan found so far.")
                                               : tr("Search finished."));
  if (!run.supportsNote.isEmpty()) statusBar()->showMessage(run.supportsNote);
  if (replacesShown) {
    endPreview();
    m_planEditor->replacePlan(run);  // shown through planEvaluated, as an edit is
    m_viewer->setPrintingDirectionsVisible(true);
    m_planDock->raise();
  } else {
    showPlan(run);
  }
  emit searchFinished(run);
}

void MainWindow::onSearchFailed(const QString& headline, const QString& detail) {
  m_searchModel.reset();
  if (m_dropSearchResult) {
    m_dropSearchResult = false;
    return;
  }
  m_searchPanel->searchFailed(headline, detail);
  statusBar()->showMessage(tr("Search failed: %1").arg(headline));
  statusBar()->setToolTip(detail);
  emit searchFailed(detail.isEmpty() ? headline : headline + QLatin1Char(' ') + detail);
}

void MainWindow::showPlan(const SearchRun& run, PlanChange change) {
  endPreview();
  if (change == PlanChange::New)
    m_document->setPlan(run);
  else
    m_document->setEditedPlan(run);
  m_planShown = true;
  using Camera = MeshViewerWidget::Camera;
  m_viewer->setPlan(run.plan, change == PlanChange::Edit ? Camera::Keep : Camera::Fit);
  m_viewer->setSupports(run.supports);
  m_planPanel->setPlan(*run.plan, run.machine.kind, run.supports ? *run.supports : std::vector<core::SupportSet>{});
  if (change == PlanChange::New) {
    m_viewer->setPrintingDirectionsVisible(true);
    m_planDock->raise();
    m_planEditor->setPlan(model() && model()->mesh != m_regionsModel ? model()->mesh : nullptr, run);
  }
  m_exportPlanAction->setEnabled(true);
  regrowSupportsIfMissing();
  emit planShown();
}

void MainWindow::regrowSupportsIfMissing() {
  const bool needed = plan() && plan()->plan && plan()->plan->jgAfterMm2 > 0.0 && !plan()->supports;
  // A plan shown over its own regions has no model to grow supports on: it keeps the ones saved with it.
  const bool modelAtHand = model() && model()->mesh != m_regionsModel;
  if (!needed || !modelAtHand) {
    m_regrowth->cancel();
    return;
  }
  if (m_regrowth->growingFor() == plan()->plan) return;
  m_regrowth->start(model()->mesh, plan()->plan, plan()->machine);
  statusBar()->showMessage(tr("Growing supports for the plan..."));
}

bool MainWindow::isGrowingSupports() const { return m_regrowth->growingFor() != nullptr; }

void MainWindow::onSupportsRegrown(const std::shared_ptr<const core::Decomposition>& plan,
                                   const std::shared_ptr<const std::vector<core::SupportSet>>& supports,
                                   const QString& note) {
  if (!m_document->attachSupports(plan, supports, note)) return;
  m_viewer->setSupports(supports);
  m_planPanel->setPlan(*plan, m_document->plan()->machine.kind, supports ? *supports : std::vector<core::SupportSet>{});
  m_planEditor->adoptSupports(plan, supports, note);
  statusBar()->showMessage(note.isEmpty() ? tr("Supports grown for the plan.") : note);
  emit supportsRegrown();
}

void MainWindow::clearPlan() {
  // The document drops the plan; onPlanChanged() clears what showed it.
  m_document->clearPlan();
}

void MainWindow::onDocumentPlanChanged() {
  if (plan() || !m_planShown) return;  // a plan shown is drawn by showPlan()
  m_planShown = false;
  if (m_regrowth) m_regrowth->cancel();
  m_viewer->clearPlan();
  m_planPanel->clearPlan();
  if (m_planEditor) m_planEditor->clear();
  if (m_exportPlanAction) m_exportPlanAction->setEnabled(false);
  emit planCleared();
}

void MainWindow::showRebuiltPlan(const SearchRun& run) { showPlan(run); }

void MainWindow::closeEvent(QCloseEvent* event) {
  // A print run first: the devices are stopped (after asking) before the unsaved-changes question, whose
  // Discard must never leave a run paused with nobody watching it.
  if (m_hardwarePanel->isRunUnderWay()) {
    event->ignore();
    askToStopRunBeforeQuitting();
    return;
  }
  if (!m_project->confirmClose()) {
    event->ignore();
    return;
  }
  saveWindowState(*this);
  QMainWindow::closeEvent(event);
}

void MainWindow::askToStopRunBeforeQuitting() {
  if (m_runQuitQuestion) {
    m_runQuitQuestion->raise();
    return;
  }
  auto* box = new QMessageBox(QMessageBox::Warning, tr("Print Run Under Way"),
                              tr("A print run is under way: step %1.").arg(m_hardwarePanel->runStepText()),
                              QMessageBox::NoButton, this);
  box->setObjectName(QStringLiteral("printRunQuitBox"));
  box->setInformativeText(tr("Quitting stops the platform and the printer first: the run is aborted (Start run "
                             "offers to resume it from the step it stopped at). Stop the devices and quit?"));
  QPushButton* stop = box->addButton(tr("S&top the Devices and Quit"), QMessageBox::DestructiveRole);
  stop->setObjectName(QStringLiteral("stopDevicesAndQuit"));
  box->addButton(QMessageBox::Cancel);
  box->setDefaultButton(QMessageBox::Cancel);
  box->setWindowModality(Qt::WindowModal);
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::finished, this, [this, box, stop] {
    if (box->clickedButton() != stop) return;
    m_hardwarePanel->stopDevicesForQuit();
    // After the box has gone: the unsaved-changes question (if any) comes next, then the window closes.
    QTimer::singleShot(0, this, [this] { close(); });
  });
  m_runQuitQuestion = box;
  box->open();
}

bool MainWindow::exportPlan(const QString& directory, QString* error, QString* warning) {
  auto fail = [error](const QString& message) {
    if (error) *error = message;
    return false;
  };
  if (!plan() || !plan()->plan) return fail(tr("There is no plan to export: run a search first."));
  const bool needsSupports = plan()->plan->jgAfterMm2 > 0.0;
  if (needsSupports && !plan()->supports && isGrowingSupports()) {
    return fail(tr("The supports of this plan are still being grown: export it again when the status bar says "
                   "they are ready."));
  }
  if (!QDir().mkpath(directory)) {
    return fail(tr("Could not create the folder %1: check that its parent exists and can be written.")
                    .arg(QDir::toNativeSeparators(directory)));
  }
  core::PlanMetadata metadata;
  metadata.up = plan()->machine.up;
  metadata.machine = plan()->machine;
  // A plan for the pose a pose search chose records it as the CLI's --pose auto does: up is the platform's
  // up the search started from, the machine the one turned to the pose.
  if (const std::optional<UpPose> pose = upPose(); pose && (pose->up - plan()->machine.up).norm() < 1e-9) {
    core::PlanPose planPose;
    planPose.up = pose->up;
    planPose.rotation = core::poseRotation(pose->up, pose->pose.platformUp);
    planPose.source = pose->pose.source;
    planPose.contactAreaMm2 = pose->pose.contactAreaMm2;
    planPose.runnersUp = pose->runnersUp;
    metadata.up = pose->pose.platformUp;
    metadata.pose = planPose;
  }
  metadata.options = plan()->options;
  metadata.axisSearchCount = plan()->axisSearchCount;
  metadata.multidirVersion = studioVersion().toStdString();
  if (model() && !model()->sourcePath.isEmpty()) {
    metadata.modelPath = localPath(model()->sourcePath);
    const core::Result<std::string> checksum = core::fileChecksum(metadata.modelPath);
    if (checksum) metadata.modelChecksum = checksum.value();
  }
  const std::vector<core::SupportSet> noSupports;
  const core::Status saved =
      core::savePlan(*plan()->plan, metadata, plan()->supports ? *plan()->supports : noSupports, localPath(directory));
  if (!saved) {
    return fail(tr("Could not export the plan to %1: %2 (%3)")
                    .arg(directory, errorHeadline(saved.error().code), QString::fromStdString(saved.error().describe())));
  }
  if (needsSupports && !plan()->supports) {
    // Written all the same (the regions are good), but never silently without them.
    const QString text =
        tr("Plan exported to %1 without supports although %2 mm² of risky area remains: %3")
            .arg(directory, formatNumber(plan()->plan->jgAfterMm2, 2),
                 plan()->supportsNote.isEmpty() ? tr("no supports were grown for it.") : plan()->supportsNote);
    statusBar()->showMessage(text);
    if (warning) *warning = text;
    return true;
  }
  statusBar()->showMessage(tr("Plan exported to %1.").arg(directory));
  return true;
}

bool MainWindow::openPlan(const QString& directory, QString* error) {
  const core::Result<core::LoadedPlan> loaded = core::loadPlan(localPath(directory));
  if (!loaded) {
    const QString message = tr("Could not open the plan %1: %2 (%3)")
                                .arg(directory, errorHeadline(loaded.error().code),
                                     QString::fromStdString(loaded.error().describe()));
    statusBar()->showMessage(message);
    if (error) *error = message;
    return false;
  }
  SearchRun run;
  run.machine = loaded->metadata.machine;
  run.options = loaded->metadata.options;
  run.axisSearchCount = loaded->metadata.axisSearchCount;
  run.plan = std::make_shared<const core::Decomposition>(loaded->decomposition);
  if (!loaded->supports.empty()) run.supports = std::make_shared<const std::vector<core::SupportSet>>(loaded->supports);
  m_document->setMachine(run.machine);
  m_searchPanel->setSearchOptions(run.options);
  m_searchPanel->setAxisSearchCount(run.axisSearchCount);

  const QString modelPath = QString::fromStdString(loaded->metadata.modelPath);
  if (!modelPath.isEmpty() && QFileInfo::exists(modelPath)) {
    // Shown once the model has loaded (showModel).
    m_pendingPlan = run;
    openFile(modelPath);
    return true;
  }
  // The model is not at hand: show the plan over its own regions.
  LoadedModel model;
  model.name = QDir(QString::fromStdString(loaded->directory)).dirName();
  auto merged = std::make_shared<const core::TriangleMesh>(mergedRegions(*run.plan));
  model.statistics = core::computeStatistics(*merged);
  model.naturalUp = run.machine.up;
  model.mesh = merged;
  m_regionsModel = merged;
  m_pendingPlan = run;
  showModel(model);
  return true;
}

bool MainWindow::saveMachineProfile(const QString& path, QString* error) {
  if (!m_machinePanel->validateFor(upDirection())) {
    if (error) *error = m_machinePanel->errorText();
    return false;
  }
  const core::Status saved = core::saveMachineProfile(m_document->machine(), localPath(path));
  if (!saved) {
    if (error) *error = QString::fromStdString(saved.error().describe());
    return false;
  }
  statusBar()->showMessage(tr("Machine profile saved to %1.").arg(path));
  return true;
}

bool MainWindow::loadMachineProfile(const QString& path, QString* error) {
  const core::Result<core::MachineSpec> loaded = core::loadMachineProfile(localPath(path));
  if (!loaded) {
    if (error) *error = QString::fromStdString(loaded.error().describe());
    return false;
  }
  setUpDirection(loaded->up);
  m_document->setMachine(loaded.value());
  statusBar()->showMessage(tr("Machine profile %1 loaded.").arg(QFileInfo(path).fileName()));
  return true;
}

void MainWindow::chooseExportPlan() {
  // A folder name to write the plan into: an existing folder, or a new one that exportPlan creates (a folder
  // dialog would accept only folders that already exist).
  const QString stem = model() ? QFileInfo(model()->name).completeBaseName() : QStringLiteral("multidir");
  const QString directory = QFileDialog::getSaveFileName(
      this, tr("Export Plan to Folder"), QDir(dialogFolder(FileKind::Plan)).filePath(stem + tr("-plan")),
      tr("Plan folders (*)"), nullptr, QFileDialog::ShowDirsOnly | QFileDialog::DontConfirmOverwrite);
  if (directory.isEmpty()) return;
  rememberDialogFolder(FileKind::Plan, directory);
  QString error;
  QString warning;
  if (!exportPlan(directory, &error, &warning)) {
    QMessageBox::warning(this, tr("Export Plan"), error);
  } else if (!warning.isEmpty()) {
    QMessageBox::warning(this, tr("Export Plan"), warning);
  }
}

bool MainWindow::exportScreenshot(const QString& path, QString* error) {
  QString problem;
  if (!savePicture(m_viewer->grabFramebuffer(), path, &problem)) {
    statusBar()->showMessage(problem);
    if (error) *error = problem;
    return false;
  }
  statusBar()->showMessage(tr("Screenshot saved to %1.").arg(path));
  return true;
}

void MainWindow::chooseExportScreenshot() {
  const QString png = tr("PNG images (*.png)");
  const QString jpeg = tr("JPEG images (*.jpg *.jpeg)");
  const QString name = model() ? QFileInfo(model()->name).completeBaseName() : QStringLiteral("multidir");
  QString filter = png;
  QString path = QFileDialog::getSaveFileName(this, tr("Export Screenshot"),
                                              QDir(dialogFolder(FileKind::Picture)).filePath(name + QStringLiteral(".png")),
                                              png + QStringLiteral(";;") + jpeg, &filter);
  if (path.isEmpty()) return;
  // A name typed without an extension gets the chosen filter's.
  if (QFileInfo(path).suffix().isEmpty()) path += filter == jpeg ? QStringLiteral(".jpg") : QStringLiteral(".png");
  rememberDialogFolder(FileKind::Picture, path);
  QString error;
  if (!exportScreenshot(path, &error)) QMessageBox::warning(this, tr("Export Screenshot"), error);
}

void MainWindow::chooseOpenPlan() {
  const QString directory =
      QFileDialog::getExistingDirectory(this, tr("Open Plan Folder"), dialogFolder(FileKind::Plan));
  if (directory.isEmpty()) return;
  openPlanFromUser(directory);
}

void MainWindow::chooseSaveMachine() {
  const QString path = QFileDialog::getSaveFileName(this, tr("Save Machine Profile"),
                                                    dialogFolder(FileKind::MachineProfile),
                                                    tr("Machine profiles (*.json)"));
  if (path.isEmpty()) return;
  rememberDialogFolder(FileKind::MachineProfile, path);
  QString error;
  if (!saveMachineProfile(path, &error)) QMessageBox::warning(this, tr("Save Machine Profile"), error);
}

void MainWindow::chooseLoadMachine() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Load Machine Profile"),
                                                    dialogFolder(FileKind::MachineProfile),
                                                    tr("Machine profiles (*.json);;All files (*)"));
  if (path.isEmpty()) return;
  rememberDialogFolder(FileKind::MachineProfile, path);
  auto load = [this, path] {
    QString error;
    if (!loadMachineProfile(path, &error)) QMessageBox::warning(this, tr("Load Machine Profile"), error);
  };
  // A profile with another up direction drops the plan shown: asked about like any other replacement.
  const core::Result<core::MachineSpec> profile = core::loadMachineProfile(localPath(path));
  const bool turnsUp = profile && (profile->up.normalized() - upDirection()).norm() > 1e-9;
  if (turnsUp && (plan() || isSearching())) {
    m_project->whenWorkMayBeReplaced(load);
  } else {
    load();
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

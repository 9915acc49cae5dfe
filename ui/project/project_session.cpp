#include "ui/project/project_session.h"

#include <QAction>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QKeySequence>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QStatusBar>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>

#include "ui/common/error_text.h"
#include "ui/common/studio_version.h"
#include "ui/document/studio_document.h"
#include "ui/main_window.h"
#include "ui/panels/search_panel.h"
#include "ui/project/autosave.h"
#include "ui/project/dialog_folders.h"
#include "ui/project/recent_files.h"

namespace multidir::ui {
namespace {

// A rebuilt plan whose J_G differs from the saved one by more than this (relative) was rebuilt on another
// model; rounding alone stays orders of magnitude below it.
constexpr double kJgRelativeTolerance = 1e-6;

std::string localPath(const QString& path) { return QFile::encodeName(path).toStdString(); }
QString fromLocal(const std::string& path) { return QFile::decodeName(QByteArray::fromStdString(path)); }

QString area(double mm2) { return QLocale().toString(mm2, 'f', 3); }

}  // namespace

// What an opening needs until its plan is shown.
struct ProjectSession::Opening {
  core::Project project;
  QString file;    // the file read (the project, or the autosave being recovered)
  QString origin;  // what projectPath() becomes: the project file; for a recovery, the file it was autosaved from
  bool recovery = false;
  quint64 generation = 0;
  QString modelPath;  // as given to the window's loader; empty for a sample
  bool modelShown = false;
  bool modelChanged = false;  // its checksum differs from the saved one
  std::shared_ptr<const core::TriangleMesh> mesh;
};

ProjectSession::ProjectSession(MainWindow& window) : QObject(&window), m_window(window) {
  m_autosave = new Autosave(this);
  connect(m_autosave, &Autosave::due, this, &ProjectSession::autosaveNow);
  connect(&m_window, &MainWindow::modelShown, this, &ProjectSession::onModelShown);
  connect(&m_window, &MainWindow::loadFailed, this, &ProjectSession::onModelLoadFailed);
  connect(&m_window, &MainWindow::upDirectionChanged, this, &ProjectSession::onChanged);
  connect(&m_window, &MainWindow::planShown, this, &ProjectSession::onChanged);
  connect(&m_window, &MainWindow::planCleared, this, &ProjectSession::onChanged);
  connect(m_window.document(), &StudioDocument::machineChanged, this, &ProjectSession::onChanged);
  connect(m_window.searchPanel(), &SearchPanel::settingsChanged, this, &ProjectSession::onChanged);
  m_window.setAcceptDrops(true);
  m_window.installEventFilter(this);
  updateTitle();
}

ProjectSession::~ProjectSession() = default;

bool ProjectSession::isProjectFile(const QString& path) {
  return path.endsWith(QLatin1String(core::kProjectFileExtension), Qt::CaseInsensitive);
}

bool ProjectSession::isMeshFile(const QString& path) {
  static const QStringList kSuffixes = {QStringLiteral("stl"), QStringLiteral("obj"), QStringLiteral("off"),
                                        QStringLiteral("ply")};
  return kSuffixes.contains(QFileInfo(path).suffix().toLower());
}

void ProjectSession::addFileActions(QMenu* file) {
  QAction* open = file->addAction(tr("Open &Project..."), this, &ProjectSession::chooseOpenProject);
  open->setObjectName(QStringLiteral("openProject"));
  open->setStatusTip(tr("Open a MultiDir project (.multidir): its model, settings and plan"));
  m_recentMenu = new RecentFilesMenu(file);
  connect(m_recentMenu, &RecentFilesMenu::fileChosen, this, &ProjectSession::openRecent);
  file->addMenu(m_recentMenu);
  QAction* saveAction = file->addAction(tr("&Save Project"), this, [this] { save(); });
  saveAction->setObjectName(QStringLiteral("saveProject"));
  saveAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_S));
  saveAction->setStatusTip(tr("Save the model reference, the settings and the plan in a project file"));
  QAction* saveAs = file->addAction(tr("Save Project &As..."), this, &ProjectSession::chooseSaveAs);
  saveAs->setObjectName(QStringLiteral("saveProjectAs"));
  saveAs->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
}

std::optional<core::Project> ProjectSession::currentProject(QString* problem) const {
  auto fail = [problem](const QString& text) -> std::optional<core::Project> {
    if (problem) *problem = text;
    return std::nullopt;
  };
  const std::optional<LoadedModel>& model = m_window.model();
  if (!model) return fail(tr("There is no model to save a project for: open a model first."));
  core::Project project;
  if (!model->sampleId.isEmpty()) {
    project.model.sampleId = model->sampleId.toStdString();
  } else if (!model->sourcePath.isEmpty()) {
    project.model.path = localPath(model->sourcePath);
    project.model.checksum = model->checksum.toStdString();
  } else {
    return fail(
        tr("The model shown has no file (it is the regions of a plan opened without its model): "
           "open the model itself to save a project."));
  }
  project.model.up = m_window.upDirection();
  if (const std::optional<UpPose> pose = m_window.upPose()) project.model.pose = pose->pose;
  project.machine = m_window.document()->machine();
  project.options = m_window.searchPanel()->searchOptions();
  project.axisSearchCount = m_window.searchPanel()->axisSearchCount();
  if (const std::optional<SearchRun>& run = m_window.plan(); run && run->plan)
    project.plan = core::projectPlanOf(*run->plan, run->machine, run->options, run->axisSearchCount);
  project.multidirVersion = studioVersion().toStdString();
  return project;
}

bool ProjectSession::saveProjectAs(const QString& path, QString* error) {
  auto fail = [this, error](const QString& text) {
    m_window.statusBar()->showMessage(text);
    if (error) *error = text;
    return false;
  };
  if (m_opening) return fail(tr("Wait until the project has opened before saving."));
  QString problem;
  const std::optional<core::Project> project = currentProject(&problem);
  if (!project) return fail(tr("Cannot save the project: %1").arg(problem));
  const core::Status saved = core::saveProject(*project, localPath(path));
  if (!saved) {
    return fail(tr("Could not save the project %1: %2 (%3)")
                    .arg(path, errorHeadline(saved.error().code), QString::fromStdString(saved.error().describe())));
  }
  m_path = QFileInfo(path).absoluteFilePath();
  setModified(false);
  remember(m_path);
  rememberDialogFolder(FileKind::Project, m_path);
  m_window.statusBar()->showMessage(tr("Project saved to %1.").arg(path));
  emit projectSaved(m_path);
  return true;
}

bool ProjectSession::save() {
  if (m_path.isEmpty()) {
    chooseSaveAs();
    return !m_modified && !m_path.isEmpty();
  }
  QString error;
  if (saveProjectAs(m_path, &error)) return true;
  QMessageBox::warning(&m_window, tr("Save Project"), error);
  return false;
}

void ProjectSession::chooseSaveAs() {
  QString suggestion = m_path;
  if (suggestion.isEmpty() && m_window.model()) {
    const QFileInfo model(m_window.model()->sourcePath);
    const QString stem = model.fileName().isEmpty() ? m_window.model()->sampleId : model.completeBaseName();
    const QString folder = m_window.dialogFolder(FileKind::Project);
    suggestion = QFileInfo(folder.isEmpty() ? model.absolutePath() : folder, stem).filePath() +
                 QLatin1String(core::kProjectFileExtension);
  }
  QString path =
      QFileDialog::getSaveFileName(&m_window, tr("Save Project"), suggestion, tr("MultiDir projects (*.multidir)"));
  if (path.isEmpty()) return;
  if (!isProjectFile(path)) path += QLatin1String(core::kProjectFileExtension);
  rememberDialogFolder(FileKind::Project, path);
  QString error;
  if (!saveProjectAs(path, &error)) QMessageBox::warning(&m_window, tr("Save Project"), error);
}

void ProjectSession::chooseOpenProject() {
  const QString path =
      QFileDialog::getOpenFileName(&m_window, tr("Open Project"), m_window.dialogFolder(FileKind::Project),
                                   tr("MultiDir projects (*.multidir);;All files (*)"));
  if (path.isEmpty()) return;
  openFromUser(path);
}

bool ProjectSession::openProject(const QString& path, QString* error) { return open(path, false, error); }

void ProjectSession::openFromUser(const QString& path) {
  const bool project = isProjectFile(path);
  rememberDialogFolder(project ? FileKind::Project : FileKind::Model, path);
  whenWorkMayBeReplaced([this, path, project] {
    if (project) {
      openProject(path);
    } else {
      m_window.openFile(path);
    }
  });
}

bool ProjectSession::whenWorkMayBeReplaced(const std::function<void()>& proceed) {
  if (!m_window.isSearching()) return settleUnsavedChanges(proceed);
  auto stopThenSettle = [this, proceed] {
    m_window.abandonSearch();
    settleUnsavedChanges(proceed);
  };
  if (m_presetSearchAnswer) {
    if (*m_presetSearchAnswer == RunningSearchAnswer::Cancel) return false;
    stopThenSettle();
    return !m_question;
  }
  if (m_question) {  // one question at a time
    m_question->raise();
    return false;
  }
  auto* box = new QMessageBox(QMessageBox::Question, tr("Search Running"),
                              tr("A search is running on %1.")
                                  .arg(m_window.model() ? m_window.model()->name : tr("the model shown")),
                              QMessageBox::NoButton, &m_window);
  box->setObjectName(QStringLiteral("searchRunningBox"));
  box->setInformativeText(tr("Stop it? Its result is then dropped."));
  QPushButton* stop = box->addButton(tr("S&top the Search"), QMessageBox::AcceptRole);
  stop->setObjectName(QStringLiteral("stopSearch"));
  box->addButton(QMessageBox::Cancel);
  box->setDefaultButton(QMessageBox::Cancel);
  box->setWindowModality(Qt::WindowModal);
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::finished, this, [this, box, stop, stopThenSettle] {
    const bool stopped = box->clickedButton() == stop;
    m_question.clear();  // answered: the unsaved-changes question may follow
    // After the box has gone, so that the next question can be asked.
    QTimer::singleShot(0, this, [stopped, stopThenSettle] {
      if (stopped) stopThenSettle();
    });
  });
  m_question = box;
  box->open();
  return false;
}

void ProjectSession::openRecent(const QString& path) {
  if (!QFileInfo::exists(path)) {
    removeRecentFile(path);
    if (m_recentMenu) m_recentMenu->refresh();
    m_window.statusBar()->showMessage(
        tr("%1 is no longer there; it was taken off the recent files.").arg(QDir::toNativeSeparators(path)));
    return;
  }
  openFromUser(path);
}

bool ProjectSession::openDropped(const QList<QUrl>& urls) {
  QStringList refused;
  QString chosen;
  for (const QUrl& url : urls) {
    const QString path = url.toLocalFile();
    const bool acceptable = !path.isEmpty() && (isMeshFile(path) || isProjectFile(path));
    if (!acceptable) {
      refused << (path.isEmpty() ? url.toDisplayString() : QFileInfo(path).fileName());
    } else if (chosen.isEmpty()) {
      chosen = path;
    }
  }
  if (!refused.isEmpty()) {
    m_window.statusBar()->showMessage(
        tr("Cannot open %1: drop a mesh file (.stl, .obj, .off, .ply) or a MultiDir project (.multidir).")
            .arg(refused.join(QStringLiteral(", "))));
  }
  if (chosen.isEmpty()) return false;
  openFromUser(chosen);
  return true;
}

QString ProjectSession::recoverableAutosave() const { return Autosave::orphans().value(0); }

bool ProjectSession::recoverAutosave(QString* error) {
  const QString orphan = recoverableAutosave();
  if (orphan.isEmpty()) {
    if (error) *error = tr("There is no autosaved project to recover.");
    return false;
  }
  return open(orphan, true, error);
}

void ProjectSession::offerRecovery() {
  const QString orphan = recoverableAutosave();
  if (orphan.isEmpty()) return;
  const QString origin = Autosave::originOf(orphan);
  auto* box = new QMessageBox(QMessageBox::Question, tr("Recover Unsaved Work"),
                              tr("MultiDir Studio did not close properly. Recover the project it autosaved on %1?")
                                  .arg(QLocale().toString(QFileInfo(orphan).lastModified(), QLocale::ShortFormat)),
                              QMessageBox::NoButton, &m_window);
  box->setObjectName(QStringLiteral("recoverAutosaveBox"));
  box->setInformativeText(origin.isEmpty()
                              ? tr("It was an untitled project.")
                              : tr("It holds unsaved changes to %1.").arg(QDir::toNativeSeparators(origin)));
  QPushButton* recover = box->addButton(tr("&Recover"), QMessageBox::AcceptRole);
  QPushButton* discard = box->addButton(tr("&Discard"), QMessageBox::DestructiveRole);
  box->addButton(tr("&Later"), QMessageBox::RejectRole);
  box->setDefaultButton(recover);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->setModal(false);
  connect(box, &QMessageBox::buttonClicked, this, [this, orphan, recover, discard](QAbstractButton* button) {
    if (button == recover) {
      open(orphan, true, nullptr);
    } else if (button == discard) {
      Autosave::removeOrphan(orphan);
    }
  });
  box->show();
}

QString ProjectSession::autosavePath() const { return m_autosave->path(); }

bool ProjectSession::confirmClose() {
  if (m_closeConfirmed || !m_modified) {
    m_autosave->discard();
    return true;
  }
  const bool closeNow = settleUnsavedChanges([this] {
    m_closeConfirmed = true;
    m_window.close();
  });
  if (closeNow) m_autosave->discard();
  return closeNow;
}

bool ProjectSession::settleUnsavedChanges(const std::function<void()>& proceed) {
  if (!m_modified) {
    proceed();
    return true;
  }
  if (m_presetAnswer) {
    if (!applyAnswer(*m_presetAnswer)) return false;
    proceed();
    return true;
  }
  if (m_question) {  // one question at a time
    m_question->raise();
    return false;
  }
  const QString name =
      m_path.isEmpty() ? (m_window.model() ? m_window.model()->name : tr("untitled")) : QFileInfo(m_path).fileName();
  auto* box = new QMessageBox(QMessageBox::Warning, tr("Unsaved Changes"),
                              tr("The project %1 has changes that are not saved.").arg(name),
                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, &m_window);
  box->setObjectName(QStringLiteral("unsavedChangesBox"));
  box->setInformativeText(tr("Save them first?"));
  box->setDefaultButton(QMessageBox::Save);
  box->setWindowModality(Qt::WindowModal);
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::finished, this, [this, box, proceed] {
    const QMessageBox::StandardButton button = box->standardButton(box->clickedButton());
    const UnsavedAnswer answer = button == QMessageBox::Save      ? UnsavedAnswer::Save
                                 : button == QMessageBox::Discard ? UnsavedAnswer::Discard
                                                                  : UnsavedAnswer::Cancel;
    // After the box has gone: proceeding may close the window that owns it.
    QTimer::singleShot(0, this, [this, answer, proceed] {
      if (applyAnswer(answer)) proceed();
    });
  });
  m_question = box;
  box->open();
  return false;
}

bool ProjectSession::applyAnswer(UnsavedAnswer answer) {
  switch (answer) {
    case UnsavedAnswer::Save:
      return save();
    case UnsavedAnswer::Discard:
      return true;
    case UnsavedAnswer::Cancel:
      return false;
  }
  return false;
}

bool ProjectSession::eventFilter(QObject* watched, QEvent* event) {
  if (watched != &m_window) return QObject::eventFilter(watched, event);
  switch (event->type()) {
    case QEvent::DragEnter:
    case QEvent::DragMove: {
      // Any local file is taken, so that a refused one can be named when it is dropped.
      auto* drag = static_cast<QDragMoveEvent*>(event);
      if (!drag->mimeData()->hasUrls()) return false;
      drag->acceptProposedAction();
      return true;
    }
    case QEvent::Drop: {
      auto* drop = static_cast<QDropEvent*>(event);
      if (!drop->mimeData()->hasUrls()) return false;
      drop->acceptProposedAction();
      openDropped(drop->mimeData()->urls());
      return true;
    }
    default:
      return QObject::eventFilter(watched, event);
  }
}

void ProjectSession::onChanged() {
  if (m_opening) return;  // opening applies its own settings; it decides the state when it ends
  // Settings chosen before any model is shown (or while a load that then fails runs) are nothing to lose:
  // there is no project to save yet.
  if (!m_window.model()) return;
  setModified(true);
}

void ProjectSession::onModelShown() {
  const std::optional<LoadedModel>& model = m_window.model();
  if (!model) return;
  if (m_opening) {
    const bool ours =
        !m_opening->modelShown &&
        (m_opening->modelPath.isEmpty() ? model->sampleId.toStdString() == m_opening->project.model.sampleId
                                        : model->sourcePath == m_opening->modelPath);
    if (ours) {
      Opening& opening = *m_opening;
      opening.modelShown = true;
      opening.mesh = model->mesh;
      opening.modelChanged = !opening.project.model.checksum.empty() && !model->checksum.isEmpty() &&
                             model->checksum.toStdString() != opening.project.model.checksum;
      if (opening.project.model.pose) {
        UpPose pose;
        pose.up = opening.project.model.up;
        pose.pose = *opening.project.model.pose;
        m_window.setUpPose(pose);
      } else {
        m_window.setUpDirection(opening.project.model.up);
      }
      m_window.document()->setMachine(opening.project.machine);
      m_window.searchPanel()->setSearchOptions(opening.project.options);
      m_window.searchPanel()->setAxisSearchCount(opening.project.axisSearchCount);
      if (opening.project.plan) {
        startRebuild();
      } else {
        finishOpening(nullptr);
      }
      return;
    }
    // Another model was opened meanwhile: the project gives way to it.
    const QString file = QFileInfo(m_opening->file).fileName();
    m_opening.reset();
    emit projectOpenFailed(tr("Opening %1 was interrupted: another model was opened.").arg(file));
  }
  // A model opened on its own leaves the project (Save then asks where): it starts a fresh, untitled
  // project with nothing to lose yet. Whoever opened it asked about unsaved changes first.
  if (!model->sourcePath.isEmpty()) remember(model->sourcePath);
  m_path.clear();
  setModified(false);
}

void ProjectSession::onModelLoadFailed(const QString& message) {
  if (!m_opening || m_opening->modelShown) return;
  m_opening.reset();
  emit projectOpenFailed(message);
}

void ProjectSession::startRebuild() {
  const Opening& opening = *m_opening;
  const quint64 generation = opening.generation;
  m_window.statusBar()->showMessage(tr("Rebuilding the plan of %1...").arg(QFileInfo(opening.file).fileName()));
  using Outcome = std::shared_ptr<const core::Result<core::Decomposition>>;
  auto* watcher = new QFutureWatcher<Outcome>(this);
  connect(watcher, &QFutureWatcher<Outcome>::finished, this, [this, watcher, generation] {
    const Outcome outcome = watcher->result();
    watcher->deleteLater();
    // A newer opening, or none (another model came in between): this rebuild is no longer wanted.
    if (!m_opening || m_opening->generation != generation) return;
    finishOpening(outcome);
  });
  watcher->setFuture(QtConcurrent::run([mesh = opening.mesh, plan = *opening.project.plan]() -> Outcome {
    return std::make_shared<const core::Result<core::Decomposition>>(core::rebuildProjectPlan(*mesh, plan));
  }));
}

void ProjectSession::finishOpening(const std::shared_ptr<const core::Result<core::Decomposition>>& rebuilt) {
  const std::optional<LoadedModel>& model = m_window.model();
  if (!model || model->mesh != m_opening->mesh) {
    const QString file = QFileInfo(m_opening->file).fileName();
    m_opening.reset();
    emit projectOpenFailed(tr("Opening %1 was interrupted: another model was opened.").arg(file));
    return;
  }
  const Opening& opening = *m_opening;
  QStringList warnings;
  QString detail;
  if (opening.modelChanged) {
    warnings << tr("The model file %1 changed since the project was saved; the plan was recomputed on the changed "
                   "file.")
                    .arg(QFileInfo(opening.modelPath).fileName());
  }
  if (rebuilt && *rebuilt) {
    const core::ProjectPlan& saved = *opening.project.plan;
    SearchRun run;
    run.machine = saved.machine;
    run.options = saved.options;
    run.axisSearchCount = saved.axisSearchCount;
    run.plan = std::make_shared<const core::Decomposition>(rebuilt->value());
    m_window.showRebuiltPlan(run);
    const double jg = run.plan->jgAfterMm2;
    if (std::abs(jg - saved.jgAfterMm2) > kJgRelativeTolerance * std::max(1.0, saved.jgAfterMm2)) {
      warnings << tr("The rebuilt plan leaves %1 mm² of risky area; the project saved %2 mm².")
                      .arg(area(jg), area(saved.jgAfterMm2));
    }
  } else if (rebuilt) {
    const core::Error& error = rebuilt->error();
    warnings << tr("The plan could not be rebuilt on this model (%1); the model is shown without it.")
                    .arg(QString::fromStdString(error.describe()));
    detail = errorHeadline(error.code);
  }
  const Opening done = std::move(*m_opening);
  m_opening.reset();

  m_path = done.origin.isEmpty() ? QString() : QFileInfo(done.origin).absoluteFilePath();
  if (done.recovery) {
    m_autosave->adopt(done.file);
  } else {
    remember(done.file);
  }
  setModified(done.recovery || !warnings.isEmpty());
  const QString name = QFileInfo(done.recovery ? done.origin : done.file).fileName();
  if (warnings.isEmpty()) {
    m_window.statusBar()->showMessage(done.recovery ? tr("Recovered the autosaved project.")
                                                    : tr("Project %1 opened.").arg(name));
  } else {
    m_window.statusBar()->showMessage(warnings.join(QLatin1Char(' ')));
    showWarning(QStringLiteral("projectWarningBox"), tr("Project %1").arg(name), warnings.join(QStringLiteral("\n\n")),
                detail);
  }
  emit projectOpened(done.file);
}

bool ProjectSession::open(const QString& path, bool recovery, QString* error) {
  const core::Result<core::Project> loaded = core::loadProject(localPath(path));
  if (!loaded) {
    return failOpening(
        tr("Could not open the project %1: %2").arg(QFileInfo(path).fileName(), errorHeadline(loaded.error().code)),
        QString::fromStdString(loaded.error().describe()), error);
  }
  auto opening = std::make_unique<Opening>();
  opening->project = loaded.value();
  opening->file = QFileInfo(path).absoluteFilePath();
  opening->origin = recovery ? Autosave::originOf(path) : opening->file;
  opening->recovery = recovery;
  opening->generation = ++m_generation;
  if (!opening->project.model.path.empty()) {
    opening->modelPath = fromLocal(opening->project.model.path);
    // A model that is itself a project would open this one again, and again.
    if (isProjectFile(opening->modelPath) || !QFileInfo(opening->modelPath).isFile()) {
      const QString model = QDir::toNativeSeparators(opening->modelPath);
      return failOpening(
          tr("Could not open the project %1: its model %2 is missing.").arg(QFileInfo(path).fileName(), model),
          tr("Put the model back at %1, or open the model where it is now and save the project again.").arg(model),
          error);
    }
  }
  m_opening = std::move(opening);
  m_window.statusBar()->showMessage(tr("Opening the project %1...").arg(QFileInfo(path).fileName()));
  if (m_opening->modelPath.isEmpty()) {
    m_window.openSample(QString::fromStdString(m_opening->project.model.sampleId));
  } else {
    m_window.openFile(m_opening->modelPath);
  }
  return true;
}

bool ProjectSession::failOpening(const QString& text, const QString& detail, QString* error) {
  m_window.statusBar()->showMessage(text);
  m_window.statusBar()->setToolTip(detail);
  QString shown = detail;
  if (m_window.model()) shown += QStringLiteral("\n\n") + tr("%1 is still open.").arg(m_window.model()->name);
  showWarning(QStringLiteral("projectErrorBox"), tr("Open Project"), text, shown);
  if (error) *error = text + QLatin1Char(' ') + detail;
  emit projectOpenFailed(text);
  return false;
}

void ProjectSession::setModified(bool modified) {
  if (!modified) m_autosave->discard();
  m_autosave->setPending(modified);
  if (modified) m_closeConfirmed = false;
  const bool changed = modified != m_modified;
  m_modified = modified;
  updateTitle();  // the window may have set a title of its own (a model shown) since
  if (changed) emit modifiedChanged(modified);
}

void ProjectSession::remember(const QString& path) {
  addRecentFile(path);
  if (m_recentMenu) m_recentMenu->refresh();
}

void ProjectSession::updateTitle() {
  QString name;
  if (!m_path.isEmpty()) {
    name = QFileInfo(m_path).fileName();
  } else if (m_window.model()) {
    name = m_window.model()->name;
  }
  // "[*]" is where Qt shows the unsaved-changes mark.
  m_window.setWindowTitle(name.isEmpty() ? tr("MultiDir Studio[*]") : tr("%1[*] - MultiDir Studio").arg(name));
  m_window.setWindowModified(m_modified);
}

void ProjectSession::autosaveNow() {
  if (!m_modified || m_opening) return;
  const std::optional<core::Project> project = currentProject();
  if (!project) return;  // nothing that could be saved yet
  QString error;
  if (!m_autosave->write(*project, m_path, &error)) {
    m_window.statusBar()->showMessage(error);
    return;
  }
  emit autosaved(m_autosave->path());
}

void ProjectSession::showWarning(const QString& objectName, const QString& title, const QString& text,
                                 const QString& detail) {
  // Non-modal: the window (and any test driving it) keeps running while the message is shown.
  auto* box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, &m_window);
  box->setObjectName(objectName);
  box->setInformativeText(detail.trimmed());
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->setModal(false);
  box->show();
}

}  // namespace multidir::ui

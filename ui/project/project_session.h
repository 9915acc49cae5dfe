#pragma once
// A studio window's project: the .multidir file File > Open Project and Save Project read and write
// (core::loadProject / saveProject), whether there are unsaved changes (the title's [*]), the question before
// they are lost, autosave and crash recovery, File > Open Recent, and files dropped on the window.
//
// Unsaved changes: the up direction, the machine or search settings, or the plan changed since the project
// was opened or saved. A model opened on its own (not as a project's) leaves the project: it starts a fresh,
// untitled project with nothing to lose yet, so Save then asks where instead of overwriting the project.
//
// Opening a project reads and checks the file, loads its model (the file, or the sample rebuilt; a missing file
// is an error and the model shown stays), applies its up direction and settings, rebuilds the plan from its
// clipping planes off the GUI thread (core::rebuildProjectPlan on QtConcurrent) and shows it. A model file that
// changed since the project was saved (its checksum), a rebuilt plan whose J_G differs from the saved one, or a
// plan that no longer fits the model is reported in the status bar and a message box; the project then counts
// as changed.
//
// No question blocks a test: the Save/Discard/Cancel question is window-modal but asynchronous and can be
// answered in advance (setUnsavedChangesAnswer); the offer to recover an autosave is a non-modal box.
//
// Thread: GUI thread only.
#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QUrl>
#include <functional>
#include <memory>
#include <optional>

#include "multidir/core/plan/project_file.h"

class QAction;
class QMenu;
class QMessageBox;

namespace multidir::ui {

class Autosave;
class MainWindow;
class RecentFilesMenu;

class ProjectSession : public QObject {
  Q_OBJECT

 public:
  enum class UnsavedAnswer { Save, Discard, Cancel };

  // Watches `window` (its parent) for changes and dropped files.
  explicit ProjectSession(MainWindow& window);
  ~ProjectSession() override;
  ProjectSession(const ProjectSession&) = delete;
  ProjectSession& operator=(const ProjectSession&) = delete;

  // Whether `path` names a project file (by its extension, .multidir).
  [[nodiscard]] static bool isProjectFile(const QString& path);
  // Whether `path` names a mesh file the studio opens (.stl .obj .off .ply).
  [[nodiscard]] static bool isMeshFile(const QString& path);

  // Adds Open Project..., Open Recent, Save Project (Ctrl+S) and Save Project As... (Ctrl+Shift+S) to `file`.
  void addFileActions(QMenu* file);
  [[nodiscard]] RecentFilesMenu* recentMenu() const { return m_recentMenu; }

  // The project file (absolute); empty while the project is untitled.
  [[nodiscard]] QString projectPath() const { return m_path; }
  [[nodiscard]] bool isModified() const { return m_modified; }
  // A project is being opened (its model loading or its plan being rebuilt).
  [[nodiscard]] bool isOpening() const { return m_opening != nullptr; }

  // The project as the window shows it now; nullopt with the reason when there is nothing to save (no model,
  // or a model without a file such as the regions of a plan opened without its model).
  [[nodiscard]] std::optional<core::Project> currentProject(QString* problem = nullptr) const;

  // Writes the project to `path`, which then is the project's file. On failure returns false with a message
  // (also in the status bar).
  bool saveProjectAs(const QString& path, QString* error = nullptr);
  // Saves to projectPath(), or asks where (a file dialog) while the project is untitled.
  bool save();
  // Starts opening a project file; false (with a message, also in the status bar and a message box) when it
  // cannot be read or its model file is missing, and the window keeps what it shows. projectOpened() or
  // projectOpenFailed() tells how it ended. Unsaved changes are not asked about: see openFromUser().
  bool openProject(const QString& path, QString* error = nullptr);
  // What the user picked (File > Open..., Open Recent, a drop): a project or a mesh file, once the work shown
  // may be replaced (whenWorkMayBeReplaced).
  void openFromUser(const QString& path);
  // Runs `proceed` once the work shown may be replaced: a running search is stopped after asking (its result
  // is dropped: MainWindow::abandonSearch), then unsaved changes are saved or discarded after asking.
  // Cancel to either question drops `proceed`. Returns whether it ran at once.
  bool whenWorkMayBeReplaced(const std::function<void()>& proceed);
  // An Open Recent entry: a file that has gone is taken off the list, with a status-bar message.
  void openRecent(const QString& path);
  // Files dropped on the window: the first mesh or project is opened; other files are refused with a
  // status-bar message naming them and what is accepted. Returns whether a file was opened.
  bool openDropped(const QList<QUrl>& urls);

  // Crash recovery: the newest autosave no running studio owns (empty: none).
  [[nodiscard]] QString recoverableAutosave() const;
  // Opens recoverableAutosave() (model and plan), marks it changed and makes it this window's autosave; it
  // stands for the project file it was autosaved from, if any. Ends like openProject().
  bool recoverAutosave(QString* error = nullptr);
  // Interactive start: when there is an autosave to recover, asks (non-modal) whether to recover or discard it.
  void offerRecovery();
  // This window's autosave file (empty until it autosaved).
  [[nodiscard]] QString autosavePath() const;

  // Called when the window is about to close: true when it may close now (no unsaved changes, or they were
  // saved or discarded). Otherwise the question is shown and the window closes once it is answered Save (and
  // saved) or Discard. A clean close deletes the autosave.
  bool confirmClose();
  // Answers the unsaved-changes question in advance (tests); nullopt: ask.
  void setUnsavedChangesAnswer(std::optional<UnsavedAnswer> answer) { m_presetAnswer = answer; }
  // Answers "A search is running: stop it?" in advance (tests); nullopt: ask (a window-modal, asynchronous box
  // named "searchRunningBox").
  enum class RunningSearchAnswer { Stop, Cancel };
  void setRunningSearchAnswer(std::optional<RunningSearchAnswer> answer) { m_presetSearchAnswer = answer; }

 signals:
  // A project (or a recovered autosave, `path` being the autosave) is shown with its plan.
  void projectOpened(const QString& path);
  // Opening a project failed or was superseded; `message` is what the status bar says.
  void projectOpenFailed(const QString& message);
  void projectSaved(const QString& path);
  void modifiedChanged(bool modified);
  void autosaved(const QString& autosavePath);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  struct Opening;

  void onChanged();
  void onModelShown();
  void onModelLoadFailed(const QString& message);
  void startRebuild();
  void finishOpening(const std::shared_ptr<const core::Result<core::Decomposition>>& rebuilt);
  bool open(const QString& path, bool recovery, QString* error);
  bool failOpening(const QString& text, const QString& detail, QString* error);
  void setModified(bool modified);
  // Puts `path` first in Open Recent.
  void remember(const QString& path);
  void updateTitle();
  void autosaveNow();
  void chooseOpenProject();
  void chooseSaveAs();
  // Runs `proceed` once unsaved changes are saved or discarded: at once when there are none or the answer
  // was given in advance, else when the question is answered. Returns whether it ran at once.
  bool settleUnsavedChanges(const std::function<void()>& proceed);
  bool applyAnswer(UnsavedAnswer answer);
  void showWarning(const QString& objectName, const QString& title, const QString& text, const QString& detail);

  MainWindow& m_window;
  Autosave* m_autosave = nullptr;
  RecentFilesMenu* m_recentMenu = nullptr;
  QString m_path;
  bool m_modified = false;
  bool m_closeConfirmed = false;
  std::optional<UnsavedAnswer> m_presetAnswer;
  std::optional<RunningSearchAnswer> m_presetSearchAnswer;
  QPointer<QMessageBox> m_question;
  std::unique_ptr<Opening> m_opening;
  quint64 m_generation = 0;  // of the latest opening: older rebuilds finishing late are dropped
};

}  // namespace multidir::ui

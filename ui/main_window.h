#pragma once
// MultiDir Studio's main window: a 3D view of one model, the File menu (models, samples, plans, machine
// profiles), the up direction it is printed along, docks for overhangs, the machine, the search and the
// plan, and a status bar with the model's size, volume and risky overhang area.
//
// Loading and searching run off the GUI thread (ModelLoader, SearchJob); the window stays responsive and
// shows a busy indicator. A failed load keeps the current model and reports the error in the status bar,
// in a non-modal message box and through loadFailed().
//
// Steps and what invalidates them: a new model or up direction clears the plan (and cancels a running
// search, whose result is then dropped); alpha_max recolours the overhangs (and is the search's: the
// Overhangs and Search panels show one value); machine and search settings apply to the next search, the plan
// shown keeps the settings it was made with.
//
// Nothing the user made is replaced without asking: what the user starts from the menus, the Up box or a drop
// (another model, sample, project or plan folder, another up direction) first asks to stop a running search
// and to save or discard unsaved changes (ProjectSession::whenWorkMayBeReplaced). The functions below that
// take a path or a direction are the program's own and do not ask.
//
// A plan that leaves risky area is never shown or exported without its supports for long: a plan that comes
// without them (a reopened or recovered project, a cancelled search) gets them regrown (SupportRegrowth), and
// exportPlan() refuses while they are being grown.
#include <QMainWindow>
#include <QPointer>
#include <QString>
#include <cstddef>
#include <optional>

#include "ui/jobs/pose_search_job.h"
#include "ui/jobs/search_job.h"
#include "ui/document/loaded_model.h"
#include "ui/document/studio_document.h"
#include "ui/document/up_pose.h"
#include "ui/project/dialog_folders.h"

class QCloseEvent;
class QComboBox;
class QDockWidget;
class QLabel;
class QMenu;
class QMessageBox;
class QProgressBar;
class QUndoStack;

namespace multidir::ui {

class AxisPicker;
class CellPanel;
class CellViewPanel;
class HardwarePanel;
class MachinePanel;
class MeshViewerWidget;
class ModelLoader;
class OverhangPanel;
class PlanEditor;
class PlanPanel;
class PlaneEditPanel;
class ProjectSession;
class SearchPanel;
class SliceSession;
class StudioDocument;
class SupportRegrowth;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;
  MainWindow(const MainWindow&) = delete;
  MainWindow& operator=(const MainWindow&) = delete;

  // Starts loading a mesh file (.stl .obj .off .ply); the up direction stays as it is.
  void openFile(const QString& path);
  // Starts building a sample (a core::samples id); the up direction becomes the sample's (+Z).
  void openSample(const QString& id);
  // The same from the File menu: asks first when a search runs or there are unsaved changes.
  void openSampleFromUser(const QString& id);
  // File > Open plan with `directory` chosen: asks first like openSampleFromUser, then openPlan().
  void openPlanFromUser(const QString& directory);
  // Stops the running search (or pose search) and drops its result (another model is about to replace the
  // one searched): the Search panel (or the Best pose box) then shows nothing of it.
  void abandonSearch();
  // Where the file dialog for `kind` starts: the folder last used for that kind (models where models were
  // opened from, projects where projects were saved), else the project's folder, else the model's; empty when
  // none is known (the dialog's own default).
  [[nodiscard]] QString dialogFolder(FileKind kind) const;
  // Help > About: a non-modal box with the version.
  void showAbout();

  // The printing (up) direction; a zero or non-finite vector is ignored. Axis directions select the
  // matching entry of the Up box; any other direction adds a "custom" entry.
  void setUpDirection(const core::Vec3& up);
  [[nodiscard]] core::Vec3 upDirection() const;
  // The up direction a pose search chose, as setUpDirection does it but with the Up box entry named "Pose: x,
  // y, z" and the pose kept with it (upPose()). The program's own: it does not ask.
  void setUpPose(const UpPose& pose);
  // How the up in force was chosen by a pose search (nullopt: the user chose it).
  [[nodiscard]] std::optional<UpPose> upPose() const;

  // Best pose (the Machine panel's "Best pose" group; ui/main_window_pose.cpp). findBestPose() starts
  // core::decomposeWithPoseSearch off the GUI thread with the Search panel's settings and the machine as
  // entered; false (with the reason in the status bar and the box) when there is no model, the machine is
  // invalid or a search runs. A finished search lists its poses and uses the chosen one (usePoseFromUser); a
  // cancelled one lists the poses that finished and leaves the plan shown as it is.
  bool findBestPose();
  void cancelPoseSearch();
  [[nodiscard]] bool isPoseSearching() const;
  // The last pose search listed in the box (nullopt: none, or dropped with its model).
  [[nodiscard]] const std::optional<PoseRun>& poseRun() const { return m_poseRun; }
  // Shows the model standing on trial `trial`'s pose (platform below it, its up pointing up on screen, its
  // overhangs) without changing the up, the plan or the project; showCurrentUp() ends it, and so does any
  // new model, up or plan.
  void previewPose(int trial);
  void showCurrentUp();
  [[nodiscard]] std::optional<core::Vec3> previewedUp() const { return m_previewUp; }
  // Makes trial `trial`'s pose the model's up: its machine turned to it, and the chosen trial's plan shown
  // (another trial is searched). Asks first like the Up box when that would drop a running search or an
  // unsaved plan.
  void usePoseFromUser(int trial);

  [[nodiscard]] bool isLoading() const;
  // What every dock and the viewer show: the model, up, machine, plan, sliced job and the device's job.
  [[nodiscard]] StudioDocument* document() const { return m_document; }
  [[nodiscard]] bool hasModel() const { return m_document->model().has_value(); }
  // The model shown (nullopt before the first successful load): the document's.
  [[nodiscard]] const std::optional<LoadedModel>& model() const { return m_document->model(); }
  [[nodiscard]] MeshViewerWidget* viewer() const { return m_viewer; }
  [[nodiscard]] OverhangPanel* overhangPanel() const { return m_overhangPanel; }
  [[nodiscard]] MachinePanel* machinePanel() const { return m_machinePanel; }
  [[nodiscard]] SearchPanel* searchPanel() const { return m_searchPanel; }
  [[nodiscard]] PlanPanel* planPanel() const { return m_planPanel; }
  // The robot cell (main_window_cell.cpp): its section of the Machine tab, and the Cell view dock.
  [[nodiscard]] CellPanel* cellPanel() const { return m_cellPanel; }
  [[nodiscard]] CellViewPanel* cellViewPanel() const { return m_cellViewPanel; }
  // The Hardware dock: devices and the print run.
  [[nodiscard]] HardwarePanel* hardwarePanel() const { return m_hardwarePanel; }
  // The project (ui/project): Open/Save Project, unsaved changes, autosave and recovery, Open Recent, drops.
  [[nodiscard]] ProjectSession* projectSession() const { return m_project; }
  // Plan editing (ui/edit): the Edit plan dock, its editor and the undo stack behind Edit > Undo/Redo (the
  // document's edit history). A new plan (searched or opened) or a new model clears the stack.
  [[nodiscard]] QUndoStack* undoStack() const { return m_document->editHistory(); }
  [[nodiscard]] PlanEditor* planEditor() const { return m_planEditor; }
  [[nodiscard]] PlaneEditPanel* planeEditPanel() const { return m_planeEditPanel; }
  // Slicing the plan shown into G-code (ui/slicing): the Slice button and estimates under the Plan dock,
  // the G-code preview, File > Export G-code.
  [[nodiscard]] SliceSession* sliceSession() const { return m_slicing; }

  // Starts a search of the model with the Machine and Search panels' settings; false (with the reason in
  // the status bar) when there is no model, the machine is invalid or a search is running.
  bool runSearch();
  // The same from Search > Run and the Search panel: when the plan shown has unsaved edits, asks first (a
  // window-modal, asynchronous box named "replaceEditedPlanBox"). A search's plan replacing a plan shown of the
  // same model is one undo step ("New search"): Undo brings back the plan it replaced. A cancelled search whose
  // best plan is worse (higher J_G) than the plan shown does not replace it, and says so.
  void runSearchFromUser();
  // Asks the running search to stop; it finishes with the best plan found so far.
  void cancelSearch();
  // A search or a pose search is running.
  [[nodiscard]] bool isSearching() const;
  // The plan shown, with what it was computed with (nullopt: none): the document's.
  [[nodiscard]] const std::optional<SearchRun>& plan() const { return m_document->plan(); }
  // Shows a plan made elsewhere (a project's plan rebuilt from its planes) as a new plan.
  void showRebuiltPlan(const SearchRun& run);

  // Writes the plan shown into `directory` (core::savePlan), creating the folder when it does not exist. On
  // failure returns false with a message; refuses (saying why) while the plan's supports are being grown. A
  // plan that needs supports but has none (they could not be grown) is written with `warning` saying so.
  bool exportPlan(const QString& directory, QString* error = nullptr, QString* warning = nullptr);
  // Supports are being grown for the plan shown (SupportRegrowth).
  [[nodiscard]] bool isGrowingSupports() const;
  // Saves the 3D view as shown (its framebuffer, at its size) to `path`, PNG or JPEG by the extension
  // (savePicture). On failure returns false with the message, also shown in the status bar.
  bool exportScreenshot(const QString& path, QString* error = nullptr);
  // Picking the 4-DOF rotation axis on the platform (the Machine panel's "Pick on platform").
  [[nodiscard]] AxisPicker* axisPicker() const { return m_axisPicker; }
  // Reads a plan folder (core::loadPlan) and shows it: over its model when that file is still there
  // (loaded first), else over the regions themselves.
  bool openPlan(const QString& directory, QString* error = nullptr);
  // Machine profiles (core::saveMachineProfile / loadMachineProfile) for the Machine panel.
  bool saveMachineProfile(const QString& path, QString* error = nullptr);
  bool loadMachineProfile(const QString& path, QString* error = nullptr);

 signals:
  // A search ended and its plan is shown (run.plan->cancelled tells a cancelled one), except a cancelled
  // search's plan worse than the plan shown: plan() then keeps the better one.
  void searchFinished(const multidir::ui::SearchRun& run);
  // A search could not run or failed; `message` is what the Search panel says.
  void searchFailed(const QString& message);
  // A plan (searched, opened, or edited: plan() has the edited one) is now shown.
  void planShown();
  // A model was loaded and is now shown.
  void modelShown(const QString& name);
  // Loading failed; the previous model (if any) is still shown. `message` is what the status bar says:
  // the file and a translated sentence on the problem (core's detail is in the message box).
  void loadFailed(const QString& message);
  void loadingChanged(bool loading);
  // The user (or setUpDirection) chose another up direction.
  void upDirectionChanged();
  // A pose search ended and its poses are listed (poseRun()); cancelled ones too.
  void poseSearchFinished();
  // A pose search could not run, failed or was cancelled before any pose finished.
  void poseSearchFailed(const QString& message);
  // The plan shown was dropped (a new model or up direction, or View > Show the model).
  void planCleared();
  // Supports grown later for the plan shown were attached to it (plan()->supports), or could not be grown
  // (plan()->supportsNote says why).
  void supportsRegrown();

 protected:
  // During a print run asks first whether to stop the devices ("printRunQuitBox"): Stop aborts the run through
  // its stop path before anything else happens; Cancel keeps the window and the run. Then asks about unsaved
  // project changes (ProjectSession::confirmClose); saves the window's layout.
  void closeEvent(QCloseEvent* event) override;

 private:
  void askToStopRunBeforeQuitting();
  void buildMenus();
  // The robot cell's section in the Machine tab and the Cell view dock (main_window_cell.cpp).
  void buildRobotCell(QDockWidget* besideDock);
  void buildUpBox();
  void buildStatusBar();
  void buildDocks();
  void updateOverhangs();
  void onMachineChanged();
  void updateRunnable();
  // New: a searched or opened plan (fits the view, raises the Plan dock, restarts editing). Edit: the
  // editor's plan replaces the one shown (the camera and the docks stay as they are).
  enum class PlanChange { New, Edit };
  void showPlan(const SearchRun& run, PlanChange change = PlanChange::New);
  // Defined in ui/main_window_editing.cpp.
  void buildPlanEditing();
  void buildEditMenu();
  void clearPlan();
  // The document's plan changed: what showed a plan that is gone is cleared.
  void onDocumentPlanChanged();
  // The Up box's applied entry becomes the document's up (with its pose, when a pose search chose it).
  // The Up box's entry `index` becomes the document's up (with its pose, when a pose search chose it).
  void applyUpEntry(int index);
  // The document's up changed (whoever set it): the Up box shows it, and the view, overhangs and plan follow.
  void onDocumentUpChanged();
  void onSearchFinished(const SearchRun& run);
  void onSearchFailed(const QString& headline, const QString& detail);
  void chooseExportPlan();
  void chooseExportScreenshot();
  void chooseOpenPlan();
  void chooseSaveMachine();
  void chooseLoadMachine();
  [[nodiscard]] double modelSizeMm() const;
  void chooseFile();
  void showModel(const LoadedModel& model);
  void reportLoadError(const QString& source, const QString& headline, const QString& detail);
  void onUpChanged();
  // The user picked entry `index` of the Up box: applied at once, or after asking when it would drop work.
  void onUpBoxChosen(int index);
  // Selects the Up box entry for `unit` (adding a custom one, or a pose one when `pose` is given) without
  // applying it; returns its index.
  int selectUpEntry(const core::Vec3& unit, const std::optional<UpPose>& pose = std::nullopt);
  // Best pose (ui/main_window_pose.cpp).
  void buildPoseSearch();
  void onPoseSearchFinished(const PoseRun& run);
  void onPoseSearchFailed(const QString& headline, const QString& detail, bool cancelled);
  void applyPose(int trial);
  void endPreview();
  void updatePoseRunnable();
  // Marks the listed trial whose up is the one in force (if any) as in use.
  void markPoseInUse();
  void regrowSupportsIfMissing();
  void onSupportsRegrown(const std::shared_ptr<const core::Decomposition>& plan,
                         const std::shared_ptr<const std::vector<core::SupportSet>>& supports, const QString& note);
  void updateModelStatus();
  void setBusy(bool busy);

  MeshViewerWidget* m_viewer = nullptr;
  ModelLoader* m_loader = nullptr;
  QComboBox* m_upBox = nullptr;
  QLabel* m_fileLabel = nullptr;
  QLabel* m_trianglesLabel = nullptr;
  QLabel* m_volumeLabel = nullptr;
  QLabel* m_riskyLabel = nullptr;
  QLabel* m_busyLabel = nullptr;
  QProgressBar* m_busyBar = nullptr;
  QString m_pendingName;
  StudioDocument* m_document = nullptr;
  bool m_planShown = false;  // the views show a plan (the document's)

  SearchJob* m_search = nullptr;
  OverhangPanel* m_overhangPanel = nullptr;
  MachinePanel* m_machinePanel = nullptr;
  CellPanel* m_cellPanel = nullptr;
  CellViewPanel* m_cellViewPanel = nullptr;
  SearchPanel* m_searchPanel = nullptr;
  PlanPanel* m_planPanel = nullptr;
  QDockWidget* m_planDock = nullptr;
  QDockWidget* m_searchDock = nullptr;
  QMenu* m_viewMenu = nullptr;
  QAction* m_exportPlanAction = nullptr;
  AxisPicker* m_axisPicker = nullptr;
  // What the running search was started for: its result is dropped when the model or up changed since.
  std::shared_ptr<const core::TriangleMesh> m_searchModel;
  core::Vec3 m_searchUp = core::Vec3::UnitZ();
  // A plan opened from a folder, waiting for its model to load.
  std::optional<SearchRun> m_pendingPlan;
  // A plan opened without its model is shown over this mesh of its regions: such a plan cannot be edited.
  std::shared_ptr<const core::TriangleMesh> m_regionsModel;
  PlanEditor* m_planEditor = nullptr;
  PlaneEditPanel* m_planeEditPanel = nullptr;
  ProjectSession* m_project = nullptr;
  SupportRegrowth* m_regrowth = nullptr;
  SliceSession* m_slicing = nullptr;
  bool m_showingModel = false;  // showModel() is handing the document a new model
  int m_upIndex = -1;               // the Up box entry applied (the box shows another one while asking)
  bool m_dropSearchResult = false;  // abandonSearch(): the running search's result is not shown
  QPointer<QMessageBox> m_replaceQuestion;  // "replace the edited plan?" while it is asked
  QPointer<QMessageBox> m_runQuitQuestion;  // "stop the devices and quit?" while it is asked
  HardwarePanel* m_hardwarePanel = nullptr;
  PoseSearchJob* m_poseSearch = nullptr;
  std::optional<PoseRun> m_poseRun;
  std::optional<core::Vec3> m_previewUp;
  bool m_dropPoseResult = false;  // abandonSearch() during a pose search
};

}  // namespace multidir::ui

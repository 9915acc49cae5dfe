#pragma once
// The studio document: everything the studio's panels show and act on, held once. The model and where it
// came from, the up direction (and the pose a pose search chose), the machine, the plan with its edit history
// and supports, the sliced job, and the job the device session runs. Every dock and the viewer read it and
// send their edits through it; none keeps a copy, so none can act on a stale model, plan or job.
//
// The invariants live here and nowhere else:
//  - a new model clears the pose (the up goes back to the one the pose search started from), the plan, its
//    supports, its edit history and the sliced job;
//  - another up direction clears the plan (its regions were cut for the old one) and so the sliced job;
//  - a new plan (searched, opened, rebuilt) clears the edit history and the sliced job; an edited plan keeps
//    the history (its edits are on it) and clears the sliced job; supports attached later clear it too. A
//    search's plan replacing a plan of the same model comes as an edit (the editor's "New search" step), so
//    Undo brings back the plan it replaced;
//  - a sliced job is accepted only for the plan shown;
//  - the plan printed apart is accepted only for the plan shown and goes with it (any new or edited plan, a new
//    model, another up), so the Print apart view can never show a stale plan's parts;
//  - the device session's job follows the plan and its sliced job, except while a print run pins it
//    (pinSessionJob): then nothing replaces it until the run unpins it, whatever the model or plan become.
//
// No widgets: the document is a value holder with change signals. Thread: GUI thread only.
#include <QObject>
#include <QString>
#include <optional>

#include "multidir/core/common/result.h"
#include "multidir/core/search/machine.h"
#include "multidir/robot/cell.h"
#include "ui/document/apart_print.h"
#include "ui/document/loaded_model.h"
#include "ui/document/print_job.h"
#include "ui/document/search_run.h"
#include "ui/document/up_pose.h"

class QUndoStack;

namespace multidir::ui {

class StudioDocument : public QObject {
  Q_OBJECT

 public:
  explicit StudioDocument(QObject* parent = nullptr);
  StudioDocument(const StudioDocument&) = delete;
  StudioDocument& operator=(const StudioDocument&) = delete;

  // The model shown (nullopt before the first).
  [[nodiscard]] const std::optional<LoadedModel>& model() const { return m_model; }
  // A new model: the pose, plan, supports, edit history and sliced job go (see the header comment). The up
  // becomes the model's natural up when it has one; a pose's up goes back to the up the pose search started
  // from, and the machine turned with the pose turns back; an up the user chose stays.
  void setModel(LoadedModel model);

  // The printing (up) direction, unit length.
  [[nodiscard]] const core::Vec3& up() const { return m_up; }
  // How the up in force was chosen by a pose search (nullopt: the user chose it).
  [[nodiscard]] const std::optional<UpPose>& upPose() const { return m_upPose; }
  // An up the user chose; a zero or non-finite vector is ignored. Another direction clears the plan.
  void setUp(const core::Vec3& up);
  // The up a pose search chose, kept with its pose. Another direction clears the plan.
  void setUpPose(const UpPose& pose);

  // The machine the next search is for (its up is the document's). A changed machine does not clear the plan:
  // the plan keeps the machine it was made with (plan()->machine).
  [[nodiscard]] const core::MachineSpec& machine() const { return m_machine; }
  void setMachine(const core::MachineSpec& machine);
  // The machine is the robot cell ("robot arm under a fixed extruder", the Machine tab's choice): a 5-DOF
  // machine for the search whose device is the cell (cell()), not an arm tilting the platform under a printer.
  // Only a 5-DOF machine can be the cell. A change emits machineChanged.
  [[nodiscard]] bool machineIsRobotCell() const {
    return m_machineIsRobotCell && m_machine.kind == core::MachineKind::TiltRotate;
  }
  void setMachineIsRobotCell(bool robotCell);

  // The robot cell (docs/robot-cell.md): the arm carrying the platform under the fixed extruder, for the machine
  // "robot arm under a fixed extruder" (nullopt: none). The Machine tab edits it, the cell view poses the job
  // on it. Replaced whole; a changed cell clears nothing (slicing does not depend on it).
  [[nodiscard]] const std::optional<robot::Cell>& cell() const { return m_cell; }
  void setCell(std::optional<robot::Cell> cell);

  // The plan shown, with what it was made with and its supports (nullopt: none).
  [[nodiscard]] const std::optional<SearchRun>& plan() const { return m_plan; }
  // A new plan (searched, opened or rebuilt): the edit history starts again and the sliced job goes.
  // `run.plan` must not be null (ignored otherwise).
  void setPlan(SearchRun run);
  // The plan after an edit (or undo/redo): the edit history stays, the sliced job goes.
  void setEditedPlan(SearchRun run);
  // No plan: the edit history and the sliced job go too.
  void clearPlan();
  // Supports grown later for `plan`; ignored (false) when `plan` is no longer the one shown. The sliced job
  // goes: it was sliced without them.
  bool attachSupports(const std::shared_ptr<const core::Decomposition>& plan,
                      std::shared_ptr<const std::vector<core::SupportSet>> supports, const QString& note);
  // The plan's edit history (Edit > Undo/Redo); owned by the document.
  [[nodiscard]] QUndoStack* editHistory() const { return m_editHistory; }

  // The plan shown sliced into G-code (nullopt: not sliced).
  [[nodiscard]] const std::optional<PrintJob>& slicedJob() const { return m_slicedJob; }
  // Refused (naming why) when `job` was not sliced from the plan shown.
  core::Status setSlicedJob(PrintJob job);
  void clearSlicedJob();

  // The plan shown printed apart (nullopt: not printed apart, or the plan changed since).
  [[nodiscard]] const std::optional<ApartPrint>& apartPrint() const { return m_apartPrint; }
  // Refused (naming why) when `print` was not made from the plan shown.
  core::Status setApartPrint(ApartPrint print);
  void clearApartPrint();

  // The job the device session runs: the pinned one while a print run holds it, else the plan shown with the
  // sliced job's G-code (none when the plan is not sliced). Its plan is null when there is nothing to run.
  [[nodiscard]] PrintJob sessionJob() const;
  [[nodiscard]] bool isSessionJobPinned() const { return m_pinnedJob.has_value(); }
  // A print run starts with the session's job: from now on it stays the job until unpinSessionJob(). Refused
  // when there is no plan to run or a run already pins one.
  core::Result<PrintJob> pinSessionJob();
  // The run ended: the session's job follows the plan shown again.
  void unpinSessionJob();

 signals:
  void modelChanged();
  void upChanged();
  void machineChanged();
  void cellChanged();
  // The plan shown changed: a new one, an edit, or none.
  void planChanged();
  // Supports were attached to the plan shown.
  void supportsChanged();
  void slicedJobChanged();
  void apartPrintChanged();
  // What sessionJob() returns changed (or was pinned, or unpinned).
  void sessionJobChanged();

 private:
  // Sets the up and pose; true when the direction changed (the plan then goes).
  bool replaceUp(const core::Vec3& unit, std::optional<UpPose> pose);
  // Drops the plan, its history and the sliced job, with their signals.
  void dropPlan();
  void dropSlicedJob();
  void dropApartPrint();

  std::optional<LoadedModel> m_model;
  core::Vec3 m_up = core::Vec3::UnitZ();
  std::optional<UpPose> m_upPose;
  core::MachineSpec m_machine;
  bool m_machineIsRobotCell = false;
  std::optional<robot::Cell> m_cell;
  std::optional<SearchRun> m_plan;
  QUndoStack* m_editHistory;
  std::optional<PrintJob> m_slicedJob;
  std::optional<ApartPrint> m_apartPrint;
  std::optional<PrintJob> m_pinnedJob;
};

}  // namespace multidir::ui

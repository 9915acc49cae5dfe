#pragma once
// Editing the plan shown: moving, tilting, adding and deleting clipping planes, with undo and redo.
//
// The order of things, so that what is shown is always a plan core accepted:
//  1. An edit asks for its new plane list to be evaluated (PlanEvaluationJob, off the GUI thread; the latest
//     request wins). The editor's state (what the controls show) is the one asked for at once.
//  2. When it evaluates, the edit is pushed onto the undo stack as a command; pushing applies it, and the
//     plan is shown (planEvaluated). Steps of one drag (beginDrag/endDrag) are pushed as they evaluate and
//     merge into one undo step, so a drag shows its live result and leaves one step.
//  3. When core refuses it, nothing is pushed, the plan shown stays the last valid one and refusalChanged
//     says why (naming the plane). Outside a drag the state goes back to the plan shown at once; in a drag
//     the controls keep following the mouse until it is released.
//  Undo and redo apply the command's state: from a small cache of recent plans at once (so undoing a recent
//  step restores exactly the plan that was shown, the searched one included), else by evaluating it again.
//
// A new plan (setPlan: an opened plan, a search of another model) is a new start: the undo stack is cleared. A
// new search's plan replacing the plan shown (replacePlan) is one undo step instead: Undo brings back the plan
// it replaced, edited or not, and the edits before it stay on the stack.
//
// Thread: GUI thread only.
#include <QObject>
#include <QString>
#include <deque>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "ui/edit/plan_edit_commands.h"
#include "ui/edit/plan_edit_state.h"
#include "ui/edit/plan_evaluation_job.h"
#include "ui/jobs/search_job.h"

class QUndoStack;

namespace multidir::ui {

class PlanEditor : public QObject, public PlanEditTarget, public PlanReplaceTarget {
  Q_OBJECT

 public:
  // `undoStack` (not owned) receives the edits; it must outlive the editor.
  explicit PlanEditor(QUndoStack* undoStack, QObject* parent = nullptr);
  ~PlanEditor() override;
  PlanEditor(const PlanEditor&) = delete;
  PlanEditor& operator=(const PlanEditor&) = delete;

  // A new start: `run`'s plan, cut from `model`. A null model (a plan shown over its own regions) cannot be
  // edited. Clears the undo stack and drops evaluations under way.
  void setPlan(std::shared_ptr<const core::TriangleMesh> model, const SearchRun& run);
  // A new search's `run`, of the model being edited, replaces the plan shown as one undo step ("New search");
  // without a plan to edit it is a new start (setPlan with the model kept).
  void replacePlan(const SearchRun& run);
  // No plan: nothing to edit; clears the undo stack.
  void clear();
  // Supports grown later for the plan shown (MainWindow regrows them for a plan opened or recovered without
  // them): kept with it, also for undo and redo. Ignored when `plan` is no longer the one shown.
  void adoptSupports(const std::shared_ptr<const core::Decomposition>& plan,
                     const std::shared_ptr<const std::vector<core::SupportSet>>& supports, const QString& note);

  [[nodiscard]] bool hasPlan() const { return m_run.has_value(); }
  // There is a plan and its model, so planes can be changed.
  [[nodiscard]] bool canEdit() const { return m_run.has_value() && m_model != nullptr; }
  // The plan shown: the last one core accepted (null: none).
  [[nodiscard]] std::shared_ptr<const core::Decomposition> plan() const;
  // The machine the plan is edited for: the search's, with the plan's rotation axis.
  [[nodiscard]] const core::MachineSpec& machine() const { return m_machine; }
  // J_G of the plan at the start (the searched or opened one), mm².
  [[nodiscard]] double startJgMm2() const { return m_startJgMm2; }
  // The plan shown is not the one editing started from: edits changed its planes.
  [[nodiscard]] bool isEdited() const;

  // What the controls show: the planes last asked for and the selected plane.
  [[nodiscard]] const PlanEditState& state() const { return m_desired; }
  [[nodiscard]] int selectedPlane() const { return m_desired.selectedPlane; }
  // Selects plane `plane` (-1: none); out of range counts as none.
  void selectPlane(int plane);

  // Edits of plane `plane` (0-based, clipping order). `dragSession` is 0 for a single edit, or the number
  // beginDrag() returned for every step of one drag. An edit that changes nothing is ignored.
  void movePlane(int plane, double offsetMm, int dragSession = 0);
  // A new normal (normalized here); the plane turns about its pivot (planePivot), so its cut stays in place.
  void setPlaneNormal(int plane, const core::Vec3& normal, int dragSession = 0);
  // A new plane where suggestNewPlane puts it for the selected plane; it becomes the selected one.
  void addPlane();
  void deletePlane(int plane);
  // A drag of one control starts: returns its session number (> 0).
  int beginDrag();
  // The drag ended: when its last step was refused, the controls go back to the plan shown.
  void endDrag();

  [[nodiscard]] bool isEvaluating() const;
  // Why the last edit was refused (translated; empty when the last evaluation succeeded).
  [[nodiscard]] const QString& refusal() const { return m_refusal; }
  [[nodiscard]] const PlanEvaluationJob* evaluationJob() const { return m_job; }

  // PlanEditTarget: what the commands' undo() and redo() call.
  void applyEditState(const PlanEditState& state) override;
  // PlanReplaceTarget: what a ReplacePlanCommand's undo() and redo() call.
  void applyPlanBasis(const PlanBasis& basis) override;

 signals:
  // A plan to show: an edit evaluated, or undo/redo reached another state. run.plan is never null; the
  // supports (and supportsNote) are the edited plan's.
  void planEvaluated(const multidir::ui::SearchRun& run);
  // The state (planes or selection) the controls should show changed.
  void stateChanged();
  void selectionChanged(int plane);
  // Why the last edit was refused; empty when an edit was accepted since.
  void refusalChanged(const QString& message, const QString& detail);
  void evaluatingChanged(bool evaluating);

 private:
  enum class EditKind { Move, Tilt, Add, Delete };
  // What the evaluation awaited was for.
  struct Awaited {
    quint64 ticket = 0;
    PlanEditState state;
    std::optional<EditKind> edit;  // none: a state applied by undo/redo
    int plane = -1;
    int dragSession = 0;
  };

  void requestEdit(EditKind kind, int plane, PlanEditState after, int dragSession);
  void onEvaluated(quint64 ticket, const EvaluatedPlan& plan);
  void onRefused(quint64 ticket, const core::Error& error);
  void show(const PlanEditState& state, const EvaluatedPlan& plan);
  void setDesired(const PlanEditState& state);
  void setRefusal(const QString& message, const QString& detail);
  void remember(const std::vector<core::Plane>& planes, const EvaluatedPlan& plan);
  [[nodiscard]] std::optional<EvaluatedPlan> remembered(const std::vector<core::Plane>& planes) const;
  [[nodiscard]] core::Vec3 pivotFor(int plane, int dragSession);
  void evaluate(Awaited awaited);
  void resetState();

  QUndoStack* m_undoStack;
  PlanEvaluationJob* m_job;
  std::shared_ptr<const core::TriangleMesh> m_model;
  std::optional<SearchRun> m_run;  // run.plan: the plan shown
  core::MachineSpec m_machine;
  double m_startJgMm2 = 0.0;
  std::vector<core::Plane> m_startPlanes;  // of the plan editing started from
  PlanEditState m_shown;       // the plan shown's state
  PlanEditState m_stackState;  // the state the undo stack's index stands for
  PlanEditState m_desired;     // the state last asked for
  std::optional<Awaited> m_awaited;
  std::deque<std::pair<std::vector<core::Plane>, EvaluatedPlan>> m_cache;  // most recent first
  int m_lastDragSession = 0;
  int m_activeDrag = 0;
  std::optional<std::pair<int, core::Vec3>> m_dragPivot;  // (plane, pivot) of the drag under way
  QString m_refusal;
};

}  // namespace multidir::ui

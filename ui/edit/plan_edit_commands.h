#pragma once
// The undoable plan edits. Each command holds the whole edit state before and after (the plane list and
// the selected plane), so undo and redo restore exactly what was there; applying a state (rebuilding its
// plan) is the target's job. Commands are pushed only once their "after" state evaluated to a plan, so
// redo() never meets a refused state.
//
// Moves and tilts of one plane made during one drag (the same drag session, > 0) merge into one undo step;
// a drag that ends where it started leaves no step at all.
#include <QCoreApplication>
#include <QUndoCommand>

#include "ui/document/search_run.h"
#include "ui/edit/plan_edit_state.h"

namespace multidir::ui {

class PlanEditTarget {
 public:
  virtual ~PlanEditTarget() = default;
  // Shows `state` (called by undo() and redo()).
  virtual void applyEditState(const PlanEditState& state) = 0;

 protected:
  PlanEditTarget() = default;
  PlanEditTarget(const PlanEditTarget&) = default;
  PlanEditTarget& operator=(const PlanEditTarget&) = default;
};

class PlanEditCommand : public QUndoCommand {
 public:
  PlanEditCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, const QString& text);

  void undo() override;
  void redo() override;
  [[nodiscard]] const PlanEditState& before() const { return m_before; }
  [[nodiscard]] const PlanEditState& after() const { return m_after; }

 protected:
  PlanEditTarget& m_target;
  PlanEditState m_before;
  PlanEditState m_after;
};

// A change of one plane that a drag repeats: successive commands of the same kind, plane and drag session
// merge (QUndoStack asks through id() and mergeWith()).
class DraggablePlaneCommand : public PlanEditCommand {
 public:
  [[nodiscard]] int id() const override { return m_dragSession > 0 ? m_kindId : -1; }
  bool mergeWith(const QUndoCommand* other) override;
  [[nodiscard]] int plane() const { return m_plane; }
  [[nodiscard]] int dragSession() const { return m_dragSession; }

 protected:
  DraggablePlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, const QString& text,
                        int kindId, int plane, int dragSession);

 private:
  int m_kindId;
  int m_plane;
  int m_dragSession;
};

// A new offset for plane `plane` (0-based, clipping order; the text names it by its printing-order number).
class MovePlaneCommand : public DraggablePlaneCommand {
  Q_DECLARE_TR_FUNCTIONS(MovePlaneCommand)

 public:
  static constexpr int kId = 0x4d4f;
  MovePlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane, int dragSession = 0);
};

// A new normal for plane `plane` (tilt and azimuth on 5-DOF machines, the rotary angle on 4-DOF ones).
class TiltPlaneCommand : public DraggablePlaneCommand {
  Q_DECLARE_TR_FUNCTIONS(TiltPlaneCommand)

 public:
  static constexpr int kId = 0x5449;
  TiltPlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane, int dragSession = 0);
};

// A plane inserted at `plane` in clipping order.
class AddPlaneCommand : public PlanEditCommand {
  Q_DECLARE_TR_FUNCTIONS(AddPlaneCommand)

 public:
  AddPlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane);
};

// What a plan's edits stand on: the plan shown (with the machine and settings it was made with), the edit state
// that names it, and the plan its edits started from (a search's result), whose planes and J_G tell whether it
// was edited and by how much.
struct PlanBasis {
  SearchRun run;  // run.plan: the plan shown; never null
  PlanEditState state;
  std::vector<core::Plane> startPlanes;
  double startJgMm2 = 0.0;
};

// What a ReplacePlanCommand calls: shows `basis` and edits from there on.
class PlanReplaceTarget {
 public:
  virtual ~PlanReplaceTarget() = default;
  virtual void applyPlanBasis(const PlanBasis& basis) = 0;

 protected:
  PlanReplaceTarget() = default;
  PlanReplaceTarget(const PlanReplaceTarget&) = default;
  PlanReplaceTarget& operator=(const PlanReplaceTarget&) = default;
};

// A new search's plan replacing the plan shown (searched or edited): one undo step, so Undo brings back the
// plan the search replaced, its edits' undo steps below it still in order.
class ReplacePlanCommand : public QUndoCommand {
  Q_DECLARE_TR_FUNCTIONS(ReplacePlanCommand)

 public:
  ReplacePlanCommand(PlanReplaceTarget& target, PlanBasis before, PlanBasis after);

  void undo() override;
  void redo() override;
  [[nodiscard]] const PlanBasis& before() const { return m_before; }
  [[nodiscard]] const PlanBasis& after() const { return m_after; }

 private:
  PlanReplaceTarget& m_target;
  PlanBasis m_before;
  PlanBasis m_after;
};

// Plane `plane` removed.
class DeletePlaneCommand : public PlanEditCommand {
  Q_DECLARE_TR_FUNCTIONS(DeletePlaneCommand)

 public:
  DeletePlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane);
};

}  // namespace multidir::ui

#include "ui/edit/plan_edit_commands.h"

#include <utility>

#include "ui/edit/plane_numbering.h"

namespace multidir::ui {

PlanEditCommand::PlanEditCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, const QString& text)
    : QUndoCommand(text), m_target(target), m_before(std::move(before)), m_after(std::move(after)) {}

void PlanEditCommand::undo() { m_target.applyEditState(m_before); }

void PlanEditCommand::redo() { m_target.applyEditState(m_after); }

DraggablePlaneCommand::DraggablePlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after,
                                             const QString& text, int kindId, int plane, int dragSession)
    : PlanEditCommand(target, std::move(before), std::move(after), text),
      m_kindId(kindId),
      m_plane(plane),
      m_dragSession(dragSession) {}

bool DraggablePlaneCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = dynamic_cast<const DraggablePlaneCommand*>(other);
  if (!next || next->id() != id() || next->m_plane != m_plane || next->m_dragSession != m_dragSession ||
      m_dragSession <= 0)
    return false;
  m_after = next->m_after;
  // Dragged back to where it started: nothing to undo, and QUndoStack drops an obsolete command.
  setObsolete(samePlanes(m_before.planes, m_after.planes));
  return true;
}

// The texts name the plane by its number in printing order (plane_numbering.h), counted in the plan after a
// move, tilt or addition and before a deletion: as the Edit plan table showed it when the edit was made.
MovePlaneCommand::MovePlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane,
                                   int dragSession)
    : DraggablePlaneCommand(target, std::move(before), std::move(after), QString(), kId, plane, dragSession) {
  setText(tr("Move plane %1").arg(planeNumber(plane, static_cast<int>(m_after.planes.size()))));
}

TiltPlaneCommand::TiltPlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane,
                                   int dragSession)
    : DraggablePlaneCommand(target, std::move(before), std::move(after), QString(), kId, plane, dragSession) {
  setText(tr("Tilt plane %1").arg(planeNumber(plane, static_cast<int>(m_after.planes.size()))));
}

AddPlaneCommand::AddPlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane)
    : PlanEditCommand(target, std::move(before), std::move(after), QString()) {
  setText(tr("Add plane %1").arg(planeNumber(plane, static_cast<int>(m_after.planes.size()))));
}

DeletePlaneCommand::DeletePlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane)
    : PlanEditCommand(target, std::move(before), std::move(after), QString()) {
  setText(tr("Delete plane %1").arg(planeNumber(plane, static_cast<int>(m_before.planes.size()))));
}

ReplacePlanCommand::ReplacePlanCommand(PlanReplaceTarget& target, PlanBasis before, PlanBasis after)
    : QUndoCommand(tr("New search")), m_target(target), m_before(std::move(before)), m_after(std::move(after)) {}

void ReplacePlanCommand::undo() { m_target.applyPlanBasis(m_before); }

void ReplacePlanCommand::redo() { m_target.applyPlanBasis(m_after); }

}  // namespace multidir::ui

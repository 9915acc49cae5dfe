#include "ui/edit/plan_edit_commands.h"

#include <utility>

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

MovePlaneCommand::MovePlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane,
                                   int dragSession)
    : DraggablePlaneCommand(target, std::move(before), std::move(after), tr("Move plane %1").arg(plane + 1), kId, plane,
                            dragSession) {}

TiltPlaneCommand::TiltPlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane,
                                   int dragSession)
    : DraggablePlaneCommand(target, std::move(before), std::move(after), tr("Tilt plane %1").arg(plane + 1), kId, plane,
                            dragSession) {}

AddPlaneCommand::AddPlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane)
    : PlanEditCommand(target, std::move(before), std::move(after), tr("Add plane %1").arg(plane + 1)) {}

DeletePlaneCommand::DeletePlaneCommand(PlanEditTarget& target, PlanEditState before, PlanEditState after, int plane)
    : PlanEditCommand(target, std::move(before), std::move(after), tr("Delete plane %1").arg(plane + 1)) {}

}  // namespace multidir::ui

#include "ui/edit/plan_editor.h"

#include <QUndoStack>
#include <algorithm>
#include <cmath>

#include "multidir/core/mesh/mesh_measure.h"
#include "ui/edit/plan_evaluation_job.h"
#include "ui/edit/plane_edit_geometry.h"
#include "ui/edit/refusal_text.h"

namespace multidir::ui {
namespace {

// Recent plans kept for undo and redo: enough for the steps a person undoes in a row, few enough that the
// region meshes of a big model do not pile up (older states are evaluated again).
constexpr std::size_t kCachedPlans = 8;

bool validPlane(const PlanEditState& state, int plane) {
  return plane >= 0 && static_cast<std::size_t>(plane) < state.planes.size();
}

}  // namespace

PlanEditor::PlanEditor(QUndoStack* undoStack, QObject* parent)
    : QObject(parent), m_undoStack(undoStack), m_job(new PlanEvaluationJob(this)) {
  connect(m_job, &PlanEvaluationJob::evaluated, this, &PlanEditor::onEvaluated);
  connect(m_job, &PlanEvaluationJob::refused, this, &PlanEditor::onRefused);
  connect(m_job, &PlanEvaluationJob::busyChanged, this, &PlanEditor::evaluatingChanged);
  // The commands refer to this editor: they must go first.
  connect(this, &QObject::destroyed, m_undoStack, &QUndoStack::clear);
}

PlanEditor::~PlanEditor() = default;

std::shared_ptr<const core::Decomposition> PlanEditor::plan() const { return m_run ? m_run->plan : nullptr; }

void PlanEditor::setPlan(std::shared_ptr<const core::TriangleMesh> model, const SearchRun& run) {
  if (!run.plan) {
    clear();
    return;
  }
  m_model = std::move(model);
  m_run = run;
  m_machine = run.machine;
  if (m_machine.kind == core::MachineKind::RotaryPlatform) m_machine.rotationAxis = run.plan->rotationAxis;
  m_startJgMm2 = run.plan->jgAfterMm2;
  m_startPlanes = run.plan->clippingPlanes;
  resetState();
}

void PlanEditor::replacePlan(const SearchRun& run) {
  if (!run.plan) return;
  if (!m_run) {
    setPlan(m_model, run);
    return;
  }
  PlanBasis before{*m_run, m_stackState, m_startPlanes, m_startJgMm2};
  PlanBasis after{run, PlanEditState{run.plan->clippingPlanes, -1}, run.plan->clippingPlanes, run.plan->jgAfterMm2};
  // Pushing runs redo(), which shows the new plan.
  m_undoStack->push(new ReplacePlanCommand(*this, std::move(before), std::move(after)));
}

bool PlanEditor::isEdited() const { return m_run.has_value() && !samePlanes(m_stackState.planes, m_startPlanes); }

void PlanEditor::applyPlanBasis(const PlanBasis& basis) {
  if (!basis.run.plan) return;
  m_job->discard();
  m_awaited.reset();
  // Plans of another basis were cut with other settings: none of them stands for this basis's planes.
  m_cache.clear();
  m_activeDrag = 0;
  m_dragPivot.reset();
  m_run = basis.run;
  m_machine = basis.run.machine;
  if (m_machine.kind == core::MachineKind::RotaryPlatform) m_machine.rotationAxis = basis.run.plan->rotationAxis;
  m_startJgMm2 = basis.startJgMm2;
  m_startPlanes = basis.startPlanes;
  remember(basis.state.planes, EvaluatedPlan{basis.run.plan, basis.run.supports, basis.run.supportsNote});
  m_shown = basis.state;
  m_stackState = basis.state;
  setDesired(basis.state);
  setRefusal(QString(), QString());
  emit planEvaluated(*m_run);
}

void PlanEditor::clear() {
  m_model.reset();
  m_run.reset();
  m_startJgMm2 = 0.0;
  m_startPlanes.clear();
  resetState();
}

void PlanEditor::resetState() {
  m_job->discard();
  m_awaited.reset();
  m_cache.clear();
  m_activeDrag = 0;
  m_dragPivot.reset();
  PlanEditState start;
  if (m_run) {
    start.planes = m_run->plan->clippingPlanes;
    remember(start.planes, EvaluatedPlan{m_run->plan, m_run->supports, m_run->supportsNote});
  }
  m_shown = start;
  m_stackState = start;
  m_undoStack->clear();
  setDesired(start);
  setRefusal(QString(), QString());
}

void PlanEditor::selectPlane(int plane) {
  if (!validPlane(m_desired, plane)) plane = -1;
  if (plane == m_desired.selectedPlane) return;
  m_shown.selectedPlane = plane;
  m_stackState.selectedPlane = plane;
  PlanEditState state = m_desired;
  state.selectedPlane = plane;
  setDesired(state);
}

void PlanEditor::movePlane(int plane, double offsetMm, int dragSession) {
  if (!canEdit() || !validPlane(m_desired, plane) || !std::isfinite(offsetMm)) return;
  PlanEditState after = m_desired;
  after.planes[static_cast<std::size_t>(plane)].offset = offsetMm;
  after.selectedPlane = plane;
  requestEdit(EditKind::Move, plane, std::move(after), dragSession);
}

void PlanEditor::setPlaneNormal(int plane, const core::Vec3& normal, int dragSession) {
  const double length = normal.norm();
  if (!canEdit() || !validPlane(m_desired, plane) || !std::isfinite(length) || length < 1e-12) return;
  const core::Vec3 unit = normal / length;
  const core::Vec3 pivot = pivotFor(plane, dragSession);
  PlanEditState after = m_desired;
  after.planes[static_cast<std::size_t>(plane)] = core::Plane{unit, unit.dot(pivot)};
  after.selectedPlane = plane;
  requestEdit(EditKind::Tilt, plane, std::move(after), dragSession);
}

void PlanEditor::addPlane() {
  if (!canEdit()) return;
  const core::Decomposition& shown = *m_run->plan;
  // The suggestion is read off the plan shown; its plane numbers are the state's when no edit is under way.
  const int selected = shown.clippingPlanes.size() == m_desired.planes.size() ? m_desired.selectedPlane : -1;
  const NewPlanePlacement placement = suggestNewPlane(shown, selected, m_machine.up);
  PlanEditState after = m_desired;
  const int index = std::clamp(placement.index, 0, static_cast<int>(after.planes.size()));
  after.planes.insert(after.planes.begin() + index, placement.plane);
  after.selectedPlane = index;
  requestEdit(EditKind::Add, index, std::move(after), 0);
}

void PlanEditor::deletePlane(int plane) {
  if (!canEdit() || !validPlane(m_desired, plane)) return;
  PlanEditState after = m_desired;
  after.planes.erase(after.planes.begin() + plane);
  after.selectedPlane = after.planes.empty() ? -1 : std::min(plane, static_cast<int>(after.planes.size()) - 1);
  requestEdit(EditKind::Delete, plane, std::move(after), 0);
}

int PlanEditor::beginDrag() {
  m_activeDrag = ++m_lastDragSession;
  m_dragPivot.reset();
  return m_activeDrag;
}

void PlanEditor::endDrag() {
  const bool dragging = m_activeDrag != 0;
  m_activeDrag = 0;
  m_dragPivot.reset();
  // A step still being evaluated is settled when it arrives; a refused last step is undone now.
  if (dragging && !m_awaited && !samePlanes(m_desired.planes, m_stackState.planes)) {
    setDesired(m_stackState);
    if (!samePlanes(m_shown.planes, m_stackState.planes)) applyEditState(m_stackState);
  }
}

bool PlanEditor::isEvaluating() const { return m_job->isBusy(); }

void PlanEditor::applyEditState(const PlanEditState& state) {
  if (!m_run) return;
  setRefusal(QString(), QString());
  m_stackState = state;
  setDesired(state);
  if (std::optional<EvaluatedPlan> cached = remembered(state.planes)) {
    m_job->discard();
    m_awaited.reset();
    show(state, *cached);
    return;
  }
  evaluate(Awaited{0, state, std::nullopt, -1, 0});
}

void PlanEditor::requestEdit(EditKind kind, int plane, PlanEditState after, int dragSession) {
  if (samePlanes(after.planes, m_desired.planes)) {
    selectPlane(after.selectedPlane);
    return;
  }
  setDesired(after);
  Awaited awaited{0, std::move(after), kind, plane, dragSession};
  if (std::optional<EvaluatedPlan> cached = remembered(awaited.state.planes)) {
    // Known already (a drag back over a step it passed): settled at once; the job's tickets start at 1.
    m_job->discard();
    m_awaited = std::move(awaited);
    onEvaluated(0, *cached);
    return;
  }
  evaluate(std::move(awaited));
}

void PlanEditor::evaluate(Awaited awaited) {
  PlanEvaluationRequest request;
  request.model = m_model;
  request.machine = m_machine;
  request.options = m_run->options;
  request.planes = awaited.state.planes;
  awaited.ticket = m_job->evaluate(std::move(request));
  m_awaited = std::move(awaited);
}

void PlanEditor::onEvaluated(quint64 ticket, const EvaluatedPlan& plan) {
  if (!m_awaited || m_awaited->ticket != ticket || !plan.plan || !m_run) return;
  const Awaited awaited = std::move(*m_awaited);
  m_awaited.reset();
  remember(awaited.state.planes, plan);
  if (!awaited.edit) {
    show(awaited.state, plan);
    return;
  }
  // Pushing runs the command's redo(), which applies its state: from the cache, so at once.
  const PlanEditState before = m_stackState;
  switch (*awaited.edit) {
    case EditKind::Move:
      m_undoStack->push(new MovePlaneCommand(*this, before, awaited.state, awaited.plane, awaited.dragSession));
      break;
    case EditKind::Tilt:
      m_undoStack->push(new TiltPlaneCommand(*this, before, awaited.state, awaited.plane, awaited.dragSession));
      break;
    case EditKind::Add:
      m_undoStack->push(new AddPlaneCommand(*this, before, awaited.state, awaited.plane));
      break;
    case EditKind::Delete:
      m_undoStack->push(new DeletePlaneCommand(*this, before, awaited.state, awaited.plane));
      break;
  }
}

void PlanEditor::onRefused(quint64 ticket, const core::Error& error) {
  if (!m_awaited || m_awaited->ticket != ticket) return;
  const Awaited awaited = std::move(*m_awaited);
  m_awaited.reset();
  // A deletion leaves no edited plane in the list to name.
  const bool namesPlane = awaited.edit && *awaited.edit != EditKind::Delete;
  setRefusal(refusalText(error, static_cast<int>(awaited.state.planes.size()), namesPlane ? awaited.plane : -1),
             QString::fromStdString(error.describe()));
  if (!awaited.edit) {
    // A state undo or redo reached could not be rebuilt: keep showing (and offering) the plan shown.
    setDesired(m_shown);
    return;
  }
  // During a drag the controls keep following the mouse; endDrag() settles a refused last step.
  if (awaited.dragSession > 0 && awaited.dragSession == m_activeDrag) return;
  setDesired(m_stackState);
  // An undo or redo whose evaluation this edit replaced: its state must still be shown.
  if (!samePlanes(m_shown.planes, m_stackState.planes)) {
    if (std::optional<EvaluatedPlan> cached = remembered(m_stackState.planes)) {
      show(m_stackState, *cached);
    } else {
      evaluate(Awaited{0, m_stackState, std::nullopt, -1, 0});
    }
  }
}

void PlanEditor::adoptSupports(const std::shared_ptr<const core::Decomposition>& plan,
                               const std::shared_ptr<const std::vector<core::SupportSet>>& supports,
                               const QString& note) {
  if (!m_run || m_run->plan != plan) return;
  m_run->supports = supports;
  m_run->supportsNote = note;
  remember(m_shown.planes, EvaluatedPlan{plan, supports, note});
}

void PlanEditor::show(const PlanEditState& state, const EvaluatedPlan& plan) {
  m_shown = state;
  m_run->plan = plan.plan;
  m_run->supports = plan.supports;
  m_run->supportsNote = plan.supportsNote;
  emit planEvaluated(*m_run);
}

void PlanEditor::setDesired(const PlanEditState& state) {
  const bool selectionMoved = state.selectedPlane != m_desired.selectedPlane;
  m_desired = state;
  emit stateChanged();
  if (selectionMoved) emit selectionChanged(m_desired.selectedPlane);
}

void PlanEditor::setRefusal(const QString& message, const QString& detail) {
  if (message == m_refusal) return;
  m_refusal = message;
  emit refusalChanged(message, detail);
}

void PlanEditor::remember(const std::vector<core::Plane>& planes, const EvaluatedPlan& plan) {
  const auto same = [&planes](const auto& entry) { return samePlanes(entry.first, planes); };
  m_cache.erase(std::remove_if(m_cache.begin(), m_cache.end(), same), m_cache.end());
  m_cache.emplace_front(planes, plan);
  while (m_cache.size() > kCachedPlans) m_cache.pop_back();
}

std::optional<EvaluatedPlan> PlanEditor::remembered(const std::vector<core::Plane>& planes) const {
  for (const auto& entry : m_cache) {
    if (samePlanes(entry.first, planes)) return entry.second;
  }
  return std::nullopt;
}

core::Vec3 PlanEditor::pivotFor(int plane, int dragSession) {
  const bool inDrag = dragSession > 0 && dragSession == m_activeDrag;
  if (inDrag && m_dragPivot && m_dragPivot->first == plane) return m_dragPivot->second;
  const core::Plane& current = m_desired.planes[static_cast<std::size_t>(plane)];
  core::Vec3 pivot;
  if (samePlanes(m_shown.planes, m_desired.planes)) {
    pivot = current.project(planePivot(*m_run->plan, plane));
  } else {
    const core::BoundingBox box = core::boundingBox(*m_model);
    pivot = current.project(0.5 * (box.min + box.max));
  }
  if (inDrag) m_dragPivot.emplace(plane, pivot);
  return pivot;
}

}  // namespace multidir::ui

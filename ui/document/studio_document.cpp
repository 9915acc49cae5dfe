#include "ui/document/studio_document.h"

#include <QUndoStack>
#include <cmath>
#include <utility>

#include "multidir/core/search/pose_search.h"

namespace multidir::ui {
namespace {

// Two ups closer than this are one direction (the Up box's entries are float vectors).
constexpr double kSameUp = 1e-9;

std::optional<core::Vec3> unitOf(const core::Vec3& v) {
  const double length = v.norm();
  if (!std::isfinite(length) || length == 0.0) return std::nullopt;
  // A unit vector is kept as it is: normalising it again could change its last bits, and a pose's up must
  // stay bit for bit the one its trial was searched for.
  if (std::abs(length - 1.0) <= 1e-12) return v;
  return v / length;
}

core::Error documentError(const QString& message, const char* where) {
  return core::Error{core::ErrorCode::InvalidParameter, message.toStdString(), where};
}

}  // namespace

StudioDocument::StudioDocument(QObject* parent) : QObject(parent), m_editHistory(new QUndoStack(this)) {
  m_machine.up = m_up;
}

void StudioDocument::setModel(LoadedModel model) {
  m_model = std::move(model);
  // The pose was the last model's: its up goes back to the one the pose search started from.
  std::optional<core::Vec3> up;
  if (m_upPose) up = unitOf(m_upPose->pose.platformUp);
  if (m_model->naturalUp) up = unitOf(*m_model->naturalUp);
  const bool hadPose = m_upPose.has_value();
  m_upPose.reset();
  bool upMoved = false;
  if (up && (*up - m_up).norm() > kSameUp) {
    // The machine was turned with the pose (its 4-DOF axis and cones stay where they are on the platform):
    // it turns back with it, else the axis is no longer in the platform's plane.
    if (hadPose) m_machine = core::machineForPose(m_machine, *up);
    m_up = *up;
    m_machine.up = m_up;
    upMoved = true;
  }
  dropPlan();
  emit modelChanged();
  if (upMoved || hadPose) emit upChanged();
  if (upMoved && hadPose) emit machineChanged();
}

void StudioDocument::setUp(const core::Vec3& up) {
  const std::optional<core::Vec3> unit = unitOf(up);
  if (unit) replaceUp(*unit, std::nullopt);
}

void StudioDocument::setUpPose(const UpPose& pose) {
  const std::optional<core::Vec3> unit = unitOf(pose.up);
  if (!unit) return;
  UpPose kept = pose;
  kept.up = *unit;
  replaceUp(*unit, std::move(kept));
}

bool StudioDocument::replaceUp(const core::Vec3& unit, std::optional<UpPose> pose) {
  const bool moved = (unit - m_up).norm() > kSameUp;
  const bool poseChanged = pose.has_value() != m_upPose.has_value();
  m_up = unit;
  m_machine.up = unit;
  m_upPose = std::move(pose);
  if (moved) dropPlan();
  if (moved || poseChanged) emit upChanged();
  return moved;
}

void StudioDocument::setCell(std::optional<robot::Cell> cell) {
  m_cell = std::move(cell);
  emit cellChanged();
}

void StudioDocument::setMachine(const core::MachineSpec& machine) {
  m_machine = machine;
  m_machine.up = m_up;
  emit machineChanged();
}

void StudioDocument::setMachineIsRobotCell(bool robotCell) {
  if (robotCell == m_machineIsRobotCell) return;
  m_machineIsRobotCell = robotCell;
  emit machineChanged();
}

void StudioDocument::setPlan(SearchRun run) {
  if (!run.plan) return;
  m_plan = std::move(run);
  m_editHistory->clear();
  dropSlicedJob();
  dropApartPrint();
  emit planChanged();
  if (!m_pinnedJob) emit sessionJobChanged();
}

void StudioDocument::setEditedPlan(SearchRun run) {
  if (!run.plan) return;
  m_plan = std::move(run);
  dropSlicedJob();
  dropApartPrint();
  emit planChanged();
  if (!m_pinnedJob) emit sessionJobChanged();
}

void StudioDocument::clearPlan() { dropPlan(); }

void StudioDocument::dropPlan() {
  const bool had = m_plan.has_value();
  m_plan.reset();
  m_editHistory->clear();
  dropSlicedJob();
  dropApartPrint();
  if (!had) return;
  emit planChanged();
  if (!m_pinnedJob) emit sessionJobChanged();
}

bool StudioDocument::attachSupports(const std::shared_ptr<const core::Decomposition>& plan,
                                    std::shared_ptr<const std::vector<core::SupportSet>> supports,
                                    const QString& note) {
  if (!m_plan || !plan || m_plan->plan != plan) return false;
  m_plan->supports = std::move(supports);
  m_plan->supportsNote = note;
  dropSlicedJob();
  emit supportsChanged();
  return true;
}

core::Status StudioDocument::setSlicedJob(PrintJob job) {
  if (!m_plan || !job.plan || job.plan != m_plan->plan)
    return documentError(tr("This job was sliced from another plan than the one shown: slice the plan shown "
                            "again."),
                         "sliced job");
  m_slicedJob = std::move(job);
  emit slicedJobChanged();
  if (!m_pinnedJob) emit sessionJobChanged();
  return core::Done{};
}

void StudioDocument::clearSlicedJob() { dropSlicedJob(); }

void StudioDocument::dropSlicedJob() {
  if (!m_slicedJob) return;
  m_slicedJob.reset();
  emit slicedJobChanged();
  if (!m_pinnedJob) emit sessionJobChanged();
}

core::Status StudioDocument::setApartPrint(ApartPrint print) {
  if (!m_plan || !print.plan || print.plan != m_plan->plan || !print.result)
    return documentError(tr("These parts were made from another plan than the one shown: print the plan shown "
                            "apart again."),
                         "print apart");
  m_apartPrint = std::move(print);
  emit apartPrintChanged();
  return core::Done{};
}

void StudioDocument::clearApartPrint() { dropApartPrint(); }

void StudioDocument::dropApartPrint() {
  if (!m_apartPrint) return;
  m_apartPrint.reset();
  emit apartPrintChanged();
}

PrintJob StudioDocument::sessionJob() const {
  if (m_pinnedJob) return *m_pinnedJob;
  if (!m_plan) return {};
  if (m_slicedJob && m_slicedJob->plan == m_plan->plan) return *m_slicedJob;
  PrintJob job;
  job.plan = m_plan->plan;
  return job;
}

core::Result<PrintJob> StudioDocument::pinSessionJob() {
  if (m_pinnedJob)
    return documentError(tr("A print run already holds the device session's job: stop it before starting another."),
                         "print run");
  PrintJob job = sessionJob();
  if (!job.plan || job.plan->regions.empty())
    return documentError(tr("There is no plan to run: run a search or open a plan first."), "print run");
  m_pinnedJob = job;
  emit sessionJobChanged();
  return job;
}

void StudioDocument::unpinSessionJob() {
  if (!m_pinnedJob) return;
  m_pinnedJob.reset();
  emit sessionJobChanged();
}

}  // namespace multidir::ui

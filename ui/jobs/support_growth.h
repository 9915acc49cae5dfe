#pragma once
// Supports for a plan just made, grown on the worker thread of the job that made it (SearchJob after a
// search, PlanEvaluationJob after an edit): core::generateSupports with default SupportOptions. The plan is
// good whatever happens here, so a failure becomes a note shown with the plan, never an error.
#include <QString>
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/core/supports/support_set.h"

namespace multidir::ui {

struct GrownSupports {
  // One set per region in printing order; null when none were grown.
  std::shared_ptr<const std::vector<core::SupportSet>> sets;
  QString note;  // translated: why there are none although the plan needs them; empty otherwise
};

// Supports for a complete plan that still has risky area (J_G > 0); nothing for a support-free plan, nor for
// a cancelled search's plan unless `growForCancelledPlan` (the plan is shown and exported all the same, so it
// gets them once the search has ended: SupportRegrowth). On a 4-DOF machine they stand on the plan's rotation axis, which an axis search may have chosen
// instead of `machine`'s. Reports `phase` through `job` at the start and the end; cancelling `job` stops
// them, with a note saying so. Never throws; may run on any thread.
GrownSupports growSupports(const core::TriangleMesh& model, const core::Decomposition& plan, core::MachineSpec machine,
                           core::JobContext& job, const std::string& phase = {}, bool growForCancelledPlan = false);

}  // namespace multidir::ui

#include "ui/jobs/support_growth.h"

#include <exception>
#include <new>

#include "multidir/core/supports/projected_supports.h"
#include "ui/common/error_text.h"
#include "ui/jobs/search_job.h"

namespace multidir::ui {

// The notes keep SearchJob's translation context, where they were first written and translated.
GrownSupports growSupports(const core::TriangleMesh& model, const core::Decomposition& plan, core::MachineSpec machine,
                           core::JobContext& job, const std::string& phase, bool growForCancelledPlan) {
  GrownSupports grown;
  if ((plan.cancelled && !growForCancelledPlan) || !(plan.jgAfterMm2 > 0.0)) return grown;
  if (machine.kind == core::MachineKind::RotaryPlatform) machine.rotationAxis = plan.rotationAxis;
  job.setProgress(0.0, phase);
  try {
    core::Result<core::ProjectedSupports> result =
        core::generateSupports(model, plan, machine, core::SupportOptions{}, job);
    if (result) {
      grown.sets = std::make_shared<const std::vector<core::SupportSet>>(std::move(result->regions));
      job.setProgress(1.0, phase);
    } else if (result.error().code == core::ErrorCode::Cancelled) {
      grown.note = SearchJob::tr("The search was cancelled while growing supports: the plan is shown without them.");
    } else {
      grown.note = SearchJob::tr("The supports could not be grown: %1 (%2)")
                       .arg(errorHeadline(result.error().code), QString::fromStdString(result.error().describe()));
    }
  } catch (const std::bad_alloc&) {
    grown.note = SearchJob::tr("Not enough memory to grow the supports: the plan is shown without them.");
  } catch (const std::exception& e) {
    grown.note = SearchJob::tr("Unexpected error while growing the supports: %1").arg(QString::fromLocal8Bit(e.what()));
  } catch (...) {
    grown.note = SearchJob::tr("Unexpected error while growing the supports.");
  }
  return grown;
}

}  // namespace multidir::ui

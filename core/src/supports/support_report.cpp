#include "multidir/core/supports/support_report.h"

namespace multidir::core {

Result<SupportReport> supportReport(const TriangleMesh& model, const MachineSpec& machine,
                                    const SearchOptions& searchOptions, const SupportOptions& supportOptions,
                                    JobContext& job) {
  if (Status s = validate(supportOptions); !s) return s.error();
  const Result<Decomposition> plan = decompose(model, machine, searchOptions, job);
  if (!plan) return plan.error();
  const Result<ProjectedSupports> multi = generateSupports(model, *plan, machine, supportOptions, job);
  if (!multi) return multi.error();
  const Result<ProjectedSupports> fixed = generateFixedDirectionSupports(model, machine.up, supportOptions, job);
  if (!fixed) return fixed.error();

  SupportReport report;
  report.triangles = model.faceCount();
  report.searchSeconds = plan->statistics.seconds;
  report.regions = static_cast<int>(plan->regions.size());
  report.jgBeforeMm2 = plan->jgBeforeMm2;
  report.jgAfterMm2 = plan->jgAfterMm2;
  report.fixedVolumeMm3 = fixed->volumeMm3;
  report.fixedContactAreaMm2 = fixed->contactAreaMm2;
  report.multiVolumeMm3 = multi->volumeMm3;
  report.multiContactAreaMm2 = multi->contactAreaMm2;
  report.fixedStatistics = fixed->statistics;
  report.multiStatistics = multi->statistics;
  report.supportSeconds = fixed->statistics.seconds + multi->statistics.seconds;
  report.cancelled = plan->cancelled;
  return report;
}

}  // namespace multidir::core

#include "ui/jobs/preview_audit.h"

#include "multidir/slicing/audit.h"
#include "ui/viewer/gcode_toolpaths.h"

namespace multidir::ui {

core::Status markUnsupportedExtrusions(GcodePreview& preview, const std::string& folder,
                                       std::optional<double> alphaMaxDegrees, core::JobContext& context) {
  core::Result<slicing::AuditJob> job = slicing::readAuditJob(folder);
  if (!job) return job.error();
  slicing::AuditOptions options;
  options.alphaMaxDegrees = alphaMaxDegrees;
  core::Result<slicing::AuditReport> report = slicing::auditJob(*job, options, context);
  if (!report) return report.error();
  // The first program is always the step programs (auditJob): their lines are the preview's.
  if (report->programs.empty())
    return core::Error{core::ErrorCode::InvalidParameter, "the audit replayed no program", folder};
  const slicing::ProgramAudit& programs = report->programs.front();
  for (const slicing::StepAudit& row : programs.steps) markUnsupported(preview, row.step, row.unsupportedLines);
  preview.audited = true;
  preview.auditedExtrusionMm = programs.total.extrusionMm;
  preview.unsupportedMm = programs.total.unsupportedMm;
  return core::Done{};
}

}  // namespace multidir::ui

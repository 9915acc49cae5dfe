#pragma once
// The audit's check (b) on a job just sliced, for the G-code preview: the step programs replayed by
// slicing::auditJob (docs/slicing.md "Audit") and every extrusion it finds resting on nothing printed before
// it marked in the preview (ToolpathSegment::unsupported), with the totals.
//
// Thread: any; the slicing runner calls it on its worker thread after building the preview.
#include <optional>
#include <string>

#include "multidir/core/common/job_context.h"
#include "multidir/core/common/result.h"

namespace multidir::ui {

struct GcodePreview;

// Audits the job in `folder` (slicing::readAuditJob) at `alphaMaxDegrees` (none: the job's own, else 45
// degrees) and marks `preview`. Errors: those of readAuditJob and auditJob (the file and line named), the
// preview left unmarked.
core::Status markUnsupportedExtrusions(GcodePreview& preview, const std::string& folder,
                                       std::optional<double> alphaMaxDegrees, core::JobContext& context);

}  // namespace multidir::ui

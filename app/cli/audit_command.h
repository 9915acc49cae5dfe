#pragma once
// `multidir audit JOB [--json OUT] [--strict] [--alpha DEGREES]`: the sliced job's G-code replayed through the
// machine's kinematics into the model's frame and checked (slicing/audit.h, docs/slicing.md "Audit").
#include <ostream>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kAuditHelp;

// Exit code 0 when the job passes, kExitAuditFailed when a check fails; throws UsageError for command-line
// mistakes and FileError for a job that cannot be read.
int runAudit(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// The job failed the audit: a violation of (a), (c), (d), (e) or a pose that disagrees (with --strict, (b)).
constexpr int kExitAuditFailed = 5;

}  // namespace multidir::cli

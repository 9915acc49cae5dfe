#pragma once
// The decomposition search without the public entry's bookkeeping, for searches that run many of them (4-DOF
// axes, poses) and report their own progress.
#include "multidir/core/common/job_context.h"
#include "multidir/core/search/decomposition.h"

namespace multidir::core::detail {

// Options, machine and model as decompose() checks them.
Status checkSearchInputs(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options);

// The search itself, for checked inputs; reports levels but leaves the job's overall progress alone. Always
// returns a plan (the uncut model at least); `cancelled` is set when the job was cancelled.
Decomposition runDecomposition(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                               JobContext& job, const SearchProgressSink& progress);

}  // namespace multidir::core::detail

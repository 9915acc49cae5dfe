#pragma once
// The apart machine's search (docs/apart.md, "Never more support than the multi-directional plan"). Internal
// to core: decompose() runs it for MachineKind::Apart.
#include "multidir/core/common/job_context.h"
#include "multidir/core/search/decomposition.h"
#include "search/run_decomposition.h"
#include "search/staged_progress.h"

namespace multidir::core::detail {

// decompose()'s search and polish for checked inputs, on any machine (on a proxy for a model of more than
// options.proxyFaces faces), without the job's final progress: the apart machine runs two of them. `proxy`:
// the proxy makeSearchProxy(model, machine.up, options) makes, when the caller has it already; else made here.
Result<Decomposition> searchedAndPolished(const TriangleMesh& model, const MachineSpec& machine,
                                          const SearchOptions& options, JobContext& job,
                                          const SearchProgressSink& progress,
                                          const Result<SearchProxy>* proxy = nullptr);

// The apart machine's plan: the apart search's plans (its best, polished, and its best for every number of
// cuts, as found and without its unpaid planes) and the model's default 5-DOF plan (MachineSpec's defaults
// with the same up, and the same options) cut again on the apart machine; of those whose J_G apart
// (core::apartPlan) is at most that 5-DOF plan's, the one with the least J_G apart + options.partCostMm2 x
// (parts - 1) + options.cutFaceCost x the joints' area. statistics.notes says which and why.
// A cancelled search returns the best plan so far, with `cancelled` set. `progress` has two stages: the apart
// search reports through the first, the 5-DOF search through the second.
Result<Decomposition> decomposeApart(const TriangleMesh& model, const MachineSpec& machine,
                                     const SearchOptions& options, JobContext& job, const StagedProgress& progress,
                                     const Result<SearchProxy>* proxy = nullptr);

}  // namespace multidir::core::detail

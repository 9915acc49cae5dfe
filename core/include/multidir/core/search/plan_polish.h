#pragma once
// Polishing a plan: its planes moved continuously, past the sampled candidates, to lower J_G.
#include "multidir/core/common/job_context.h"
#include "multidir/core/search/decomposition.h"

namespace multidir::core {

// Moves each of `plan`'s planes (normal and offset), one plane at a time in printing order, to where the plan's
// J_G (docs/jg-definition.md, measured on the region meshes as the final plan is) is lower, keeping every
// constraint the search keeps: what the machine can print along (tilt limit, forbidden cones, the 4-DOF axis
// and its whole stepper steps), Criteria II and III, the minimum region height, and every plane paying for
// itself. A pattern search with steps from 2 degrees and half the offset step, halved
// `options.polishEffort` - 1 times (docs/search.md, "Polishing"). The result's J_G is never above `plan`'s;
// it does not depend on the thread count. Cancelling returns the best plan reached so far.
// `plan` must be a plan of `model` for `machine` (its rotation axis is used); the statistics are `plan`'s,
// with the polishing's added. Errors: InvalidParameter (options, machine, or a plane of `plan` that the
// machine or the criteria refuse, named), EmptyMesh.
Result<Decomposition> polishPlan(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                                 const Decomposition& plan, JobContext& job, const SearchProgressSink& progress = {});

}  // namespace multidir::core

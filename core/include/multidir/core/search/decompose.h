#pragma once
// Entry points of the decomposition search.
#include <memory>

#include "multidir/core/common/job_context.h"
#include "multidir/core/search/decomposition.h"

namespace multidir::core {

// Decomposes a closed model (from loadMesh or a sample) for a machine. Results do not depend on the thread
// count. Cancellation is checked once per normal scored and once per clip; a cancelled search returns the
// best complete plan found so far with `cancelled` set (the uncut model is always such a plan).
// Errors: InvalidParameter (options or machine), EmptyMesh.
Result<Decomposition> decompose(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                                JobContext& job, const SearchProgressSink& progress = {});

// 4-DOF: tries `axisCount` rotation axes evenly spread over 180 degrees in the platform plane (the machine's
// own axis first), runs the search for each (threads across axes) and keeps the plan with the least J_G.
Result<Decomposition> decomposeWithAxisSearch(const TriangleMesh& model, const MachineSpec& machine,
                                              const SearchOptions& options, int axisCount, JobContext& job,
                                              const SearchProgressSink& progress = {});

}  // namespace multidir::core

#pragma once
// After polishing: the plan's later planes searched again from each of its polished states (docs/search.md,
// "Searching the tails again"). decompose() runs it with SearchOptions::searchTails (off by default: it costs
// about twice the default search).
#include <optional>

#include "multidir/core/common/job_context.h"
#include "multidir/core/search/decomposition.h"

namespace multidir::core::detail {

// `plan` (a polished plan for `model`) or a lower one: from the state after each of its first k planes
// (k = 0 .. N-1), the planes after them are searched again by a beam of two (abandoning the states that already
// hold the J_G a tail must beat), the best plan found that pays for itself is polished (options.polish) and
// returned when its J_G is lower than `plan`'s. Every plan is cut with every criterion checked. The same plan for any thread count. `platform`:
// as for polishDecomposition.
Decomposition withTailsSearchedAgain(const TriangleMesh& model, const MachineSpec& machine,
                                     const SearchOptions& options, Decomposition plan, JobContext& job,
                                     const std::optional<PlatformRegion>& platform = std::nullopt);

}  // namespace multidir::core::detail

#pragma once
// Welding on load: an STL repeats every corner of every facet, and other exporters leave near-copies of a
// vertex a rounding error apart. checkAndRepair merges them before anything else looks at the topology.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

// Welds every used point to the earliest kept point within `tolerance` (Euclidean; exact copies, -0 and +0
// alike, always), keeping the others in their order. Returns the new index of every point (-1 for unused
// ones); `welded` receives the kept points, `merged` the number of used points that were not kept and
// `firstMerged` the first `firstFew` of them.
//
// Runs on `threads` threads (0: all) and gives the same result, bit for bit, for any thread count: exact
// copies are found in slices of the hash space, each slice in point order; points with another point within
// the tolerance (a grid of cells twice the tolerance wide) are found on threads, each point by itself; only
// those few go through the welding's order-dependent choice on one thread.
std::vector<std::int32_t> weldVertices(const std::vector<Vec3>& points, const std::vector<char>& used, double tolerance,
                                       int threads, std::vector<Vec3>& welded, std::size_t& merged,
                                       std::vector<std::int64_t>& firstMerged, std::size_t firstFew);

}  // namespace multidir::core::detail

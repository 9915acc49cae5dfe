#pragma once
// 64-bit keys of mesh edges, for hash maps and sorted edge lists.
#include <algorithm>
#include <cstdint>

namespace multidir::core::detail {

// The edge a->b with its direction: b->a has another key.
inline std::uint64_t directedEdgeKey(std::int32_t a, std::int32_t b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
// The edge {a, b} whichever way it is walked.
inline std::uint64_t undirectedEdgeKey(std::int32_t a, std::int32_t b) { return directedEdgeKey(std::min(a, b), std::max(a, b)); }

}  // namespace multidir::core::detail

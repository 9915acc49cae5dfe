#pragma once
// Open addressing over 64-bit hashes, for finding repeated points (welding on load, float corners on save): an
// unordered_map allocates a node per entry, which was most of the cost of loading a million-triangle STL. The
// slots hold the caller's indices; the caller says what equality means.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "detail/huge_pages.h"

namespace multidir::core::detail {

class FlatIndex {
 public:
  // Room for `entries` values at most half full.
  explicit FlatIndex(std::size_t entries) {
    std::size_t capacity = 16;
    while (capacity < 2 * entries) capacity *= 2;
    m_slots = filledInHugePages<std::int32_t>(capacity, -1);
    m_mask = capacity - 1;
  }
  // The slot where `matches` holds for the stored value, or the empty slot where it would go.
  template <typename Matches>
  std::int32_t& find(std::uint64_t hash, Matches matches) {
    for (std::size_t i = mix(hash) & m_mask;; i = (i + 1) & m_mask)
      if (m_slots[i] < 0 || matches(m_slots[i])) return m_slots[i];
  }

  static std::size_t mix(std::uint64_t h) {
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    return static_cast<std::size_t>(h);
  }

 private:
  std::vector<std::int32_t> m_slots;
  std::size_t m_mask = 0;
};

}  // namespace multidir::core::detail

#pragma once
// Disjoint sets over 0..n-1 with path halving. The smaller index is kept as the root, so a set's root is its
// smallest member whatever order the unions came in.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "detail/huge_pages.h"

namespace multidir::core::detail {

struct UnionFind {
  std::vector<std::int32_t> parent;
  explicit UnionFind(std::size_t n) {
    reserveInHugePages(parent, n);  // a million-face mesh's corners: 12 MB
    parent.resize(n);
    std::iota(parent.begin(), parent.end(), 0);
  }
  std::int32_t find(std::int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace multidir::core::detail

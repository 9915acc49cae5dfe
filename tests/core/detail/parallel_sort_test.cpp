#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "detail/parallel.h"

using multidir::core::detail::parallelSort;

namespace {

// 50,000 (key, index) pairs with many equal keys: a strict total order only through the index.
std::vector<std::pair<int, int>> shuffledPairs() {
  std::vector<std::pair<int, int>> pairs;
  std::uint32_t state = 12345;
  for (int i = 0; i < 50000; ++i) {
    state = state * 1664525u + 1013904223u;
    pairs.emplace_back(static_cast<int>(state >> 24), i);
  }
  return pairs;
}

}  // namespace

TEST(ParallelSort, GivesTheOneSortedOrderForAnyThreadCount) {
  std::vector<std::pair<int, int>> expected = shuffledPairs();
  std::sort(expected.begin(), expected.end());
  for (const int threads : {1, 2, 3, 7}) {
    std::vector<std::pair<int, int>> pairs = shuffledPairs();
    parallelSort(pairs.begin(), pairs.end(), std::less<>(), threads, 1000);
    EXPECT_EQ(pairs, expected) << threads << " threads";
  }
}

TEST(ParallelSort, SortsRangesSmallerThanAPiece) {
  std::vector<int> values{5, 3, 9, 1};
  parallelSort(values.begin(), values.end(), std::less<>(), 4);
  EXPECT_EQ(values, (std::vector<int>{1, 3, 5, 9}));
}

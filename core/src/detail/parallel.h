#pragma once
// Static, deterministic parallel loops: item i always goes to the same slot of the output, so results do not
// depend on how many threads ran or how they were scheduled.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace multidir::core::detail {

inline int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware ? static_cast<int>(hardware) : 1;
}

// Calls body(i) for i in [0, count) on up to `threads` threads. Items are handed out one at a time to
// whichever thread is free (their costs differ widely: a clip, a normal's sweep); body(i) must write only
// what belongs to item i, so that the result does not depend on which thread ran it.
template <typename Body>
void parallelFor(int count, int threads, const Body& body) {
  const int workers = std::max(1, std::min(threads, count));
  if (workers == 1) {
    for (int i = 0; i < count; ++i) body(i);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  std::atomic<int> next{0};
  auto run = [&] {
    for (int i = next.fetch_add(1, std::memory_order_relaxed); i < count; i = next.fetch_add(1, std::memory_order_relaxed))
      body(i);
  };
  for (int w = 1; w < workers; ++w) pool.emplace_back(run);
  run();
  for (std::thread& t : pool) t.join();
}

// Sorts [first, last) by `less`, which must be a strict total order (no two elements equivalent), in a piece
// per thread (at least minPiece elements each) merged after: there is only one sorted order then, so the
// result does not depend on the thread count.
template <typename Iterator, typename Less>
void parallelSort(Iterator first, Iterator last, Less less, int threads, std::size_t minPiece = 8192) {
  const auto count = static_cast<std::size_t>(last - first);
  const int pieces = std::max(1, std::min(threads, static_cast<int>(count / std::max<std::size_t>(1, minPiece))));
  std::vector<Iterator> bounds;
  for (int k = 0; k <= pieces; ++k)
    bounds.push_back(first + static_cast<std::ptrdiff_t>(count * static_cast<std::size_t>(k) / static_cast<std::size_t>(pieces)));
  parallelFor(pieces, threads, [&](int k) { std::sort(bounds[k], bounds[k + 1], less); });
  for (int k = 1; k < pieces; ++k) std::inplace_merge(first, bounds[k], bounds[k + 1], less);
}

}  // namespace multidir::core::detail

#pragma once
// Static, deterministic parallel loops: item i always goes to the same slot of the output, so results do not
// depend on how many threads ran or how they were scheduled.
#include <algorithm>
#include <atomic>
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

}  // namespace multidir::core::detail

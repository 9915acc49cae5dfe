#pragma once
// Static, deterministic parallel loops: item i always goes to the same slot of the output, so results do not
// depend on how many threads ran or how they were scheduled.
#include <algorithm>
#include <thread>
#include <vector>

namespace multidir::core::detail {

inline int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware ? static_cast<int>(hardware) : 1;
}

// Calls body(i) for i in [0, count) on up to `threads` threads; items are handed out round-robin.
template <typename Body>
void parallelFor(int count, int threads, const Body& body) {
  const int workers = std::max(1, std::min(threads, count));
  if (workers == 1) {
    for (int i = 0; i < count; ++i) body(i);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  auto run = [&](int worker) {
    for (int i = worker; i < count; i += workers) body(i);
  };
  for (int w = 1; w < workers; ++w) pool.emplace_back(run, w);
  run(0);
  for (std::thread& t : pool) t.join();
}

}  // namespace multidir::core::detail

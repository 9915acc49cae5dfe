// The greedy schemes (paper Eq. 7 and 8).
#include <algorithm>

#include "search/search_schemes.h"

namespace multidir::core::detail {

bool runGreedy(SearchEngine& engine, bool constrained, double minRegionVolume, BestPlan& best,
               const SearchProgressSink& sink, int& levels, NodePtr start) {
  NodePtr node = start ? std::move(start) : engine.root();
  best.offer(node);
  constexpr double kRiskFree = 1e-6;  // mm^2: what counts as R = 0 after floating-point sums
  while (!engine.isTerminal(*node, minRegionVolume)) {
    bool cancelled = false;
    std::vector<ScoredCandidate> pool = engine.score(*node, 0, cancelled);
    if (cancelled) return true;
    dropSmallerThan(pool, minRegionVolume);
    releaseParentSweeps(engine, *node);
    levels = node->level + 1;
    const bool anyRiskFree = constrained && std::any_of(pool.begin(), pool.end(), [&](const ScoredCandidate& c) {
                               return c.riskyAboveMm2 < kRiskFree && c.localGainMm2() > 0;
                             });
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < pool.size(); ++i)
      if (pool[i].localGainMm2() > 0 && (!anyRiskFree || pool[i].riskyAboveMm2 < kRiskFree)) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return pool[a].localGainMm2() > pool[b].localGainMm2();
    });
    // The first candidate in order that extends, tried a thread-count batch at a time.
    std::optional<NodePtr> child;
    const std::vector<NodePtr> beams = {node};
    for (std::size_t position = 0; !child && position < order.size();) {
      if (engine.job().isCancelled()) return true;
      const std::size_t end = std::min(order.size(), position + static_cast<std::size_t>(engine.threads()));
      const std::vector<std::size_t> batch(order.begin() + static_cast<std::ptrdiff_t>(position),
                                           order.begin() + static_cast<std::ptrdiff_t>(end));
      position = end;
      for (std::optional<NodePtr>& extended : extendAll(engine, beams, pool, batch))
        if (extended) {
          child = std::move(extended);
          break;
        }
    }
    if (!child) break;
    node = *child;
    best.offer(node);
    report(sink, node->level, 1, best, engine);
  }
  return false;
}

}  // namespace multidir::core::detail

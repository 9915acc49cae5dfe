// Steps every search scheme shares: candidates by region size, releasing sweeps, extending beams in parallel.
#include "search/search_schemes.h"

#include <algorithm>

#include "detail/parallel.h"

namespace multidir::core::detail {

std::vector<NodePtr> chainOf(NodePtr node) {
  std::vector<NodePtr> chain;
  for (; node; node = node->parent) chain.push_back(node);
  std::reverse(chain.begin(), chain.end());
  return chain;
}

Result<NodePtr> cutInTurn(SearchEngine& engine, NodePtr start, const std::vector<Plane>& planes) {
  NodePtr node = std::move(start);
  for (const Plane& plane : planes) {
    auto child = engine.cut(node, plane);
    if (!child.ok()) return child.error();
    node = *child;
  }
  return node;
}

void dropSmallerThan(std::vector<ScoredCandidate>& candidates, double minRegionVolume) {
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [&](const ScoredCandidate& c) { return c.volumeAboveMm3 < minRegionVolume; }),
                   candidates.end());
}

void releaseParentSweeps(const SearchEngine& engine, const SearchNode& scored) {
  if (scored.parent && scored.parent != engine.root()) scored.parent->latticeSweeps.reset();
}

std::vector<std::optional<NodePtr>> extendAll(SearchEngine& engine, const std::vector<NodePtr>& beams,
                                              const std::vector<ScoredCandidate>& pool,
                                              const std::vector<std::size_t>& indices) {
  std::vector<std::optional<NodePtr>> children(indices.size());
  detail::parallelFor(static_cast<int>(indices.size()), engine.threads(), [&](int i) {
    const ScoredCandidate& c = pool[indices[i]];
    children[i] = engine.extend(beams[c.beam], c);
  });
  return children;
}

void report(const SearchProgressSink& sink, int level, int alive, const BestPlan& best, const SearchEngine& engine) {
  if (!sink) return;
  SearchProgress p;
  p.level = level;
  p.beamsAlive = alive;
  p.bestJgMm2 = best.node()->jg();
  p.candidatesScored = engine.candidatesScored();
  sink(p);
}

}  // namespace multidir::core::detail

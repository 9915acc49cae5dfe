#pragma once
// The search schemes run on one SearchEngine (greedy chains, Algorithm 1's beam) and the beam scheme that runs
// them side by side; decompose.cpp picks one. Internal to core.
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "multidir/core/search/search_options.h"
#include "search/search_engine.h"

namespace multidir::core::detail {

using NodePtr = std::shared_ptr<const SearchNode>;

// Keeps the best plan seen: least J_G, then fewer regions (Criterion IV), then first found. With
// `keepFinalists` (the apart machine, which prices every part: docs/apart.md) it also keeps the best plan of
// every number of cuts, the candidates a priced choice picks from.
class BestPlan {
 public:
  explicit BestPlan(bool keepFinalists = false) : m_keepFinalists(keepFinalists) {}

  void offer(const NodePtr& node) {
    if (better(node, m_node)) m_node = node;
    offerFinalist(node);
  }
  // Another search's finalists, as if offered here (only the finalists: node() keeps its own order).
  void offerFinalistsOf(const BestPlan& other) {
    for (const NodePtr& node : other.m_finalists)
      if (node) offerFinalist(node);
  }
  const NodePtr& node() const { return m_node; }  // null before anything was offered
  // By number of cuts (index), the least J_G seen, first found on ties; null where none was offered.
  const std::vector<NodePtr>& finalists() const { return m_finalists; }

 private:
  static bool better(const NodePtr& node, const NodePtr& than) {
    constexpr double kTie = 1e-9;
    return !than || node->jg() < than->jg() - kTie ||
           (std::abs(node->jg() - than->jg()) <= kTie && node->level < than->level);
  }
  void offerFinalist(const NodePtr& node) {
    if (!m_keepFinalists) return;
    const auto level = static_cast<std::size_t>(node->level);
    if (m_finalists.size() <= level) m_finalists.resize(level + 1);
    if (better(node, m_finalists[level])) m_finalists[level] = node;
  }

  bool m_keepFinalists = false;
  NodePtr m_node;
  std::vector<NodePtr> m_finalists;
};

// One scale of the beam search: the smallest region it may cut off, its beams and its levels.
struct BeamScale {
  double minRegionVolume = 0.0;
  int beamWidth = 1;
  int maxLevels = 1;
  // A state whose regions cut off already hold this much risky area cannot lead to a plan below it (J_G only
  // grows as regions are cut): it is neither clipped (by its score) nor kept (by its measure). The tails
  // searched again after polishing set it to the J_G they must beat; the search's own scales leave it off.
  double abandonAtMm2 = INFINITY;
};

// What the scales' own engines did, for the plan's statistics.
struct BeamWork {
  long long candidatesScored = 0;
  int clipsPerformed = 0;
  std::vector<NodePtr> searchBests;  // each search's best plan, in the order offered
};

// The nodes of a node's chain, the root first: chain[k] is what plane k cuts.
std::vector<NodePtr> chainOf(NodePtr node);

// The node `planes` make, cut one after another from `start` with every criterion checked; or the first
// refusal (SearchEngine::cut's error, naming the plane).
Result<NodePtr> cutInTurn(SearchEngine& engine, NodePtr start, const std::vector<Plane>& planes);

// Candidates whose region is below `minRegionVolume` are not the scheme's to take.
void dropSmallerThan(std::vector<ScoredCandidate>& candidates, double minRegionVolume);

// Once every child of a node was scored, its sweeps are no longer needed (the root's serve all schemes).
void releaseParentSweeps(const SearchEngine& engine, const SearchNode& scored);

// Extends beams by the pool's candidates at `indices`, on the engine's threads; results in the order given.
// The callers take these in order as if made one by one, so only the wasted work depends on the threads.
std::vector<std::optional<NodePtr>> extendAll(SearchEngine& engine, const std::vector<NodePtr>& beams,
                                              const std::vector<ScoredCandidate>& pool,
                                              const std::vector<std::size_t>& indices);

// Tells `sink` (when set) where a scheme is: its level, beams alive and best plan so far.
void report(const SearchProgressSink& sink, int level, int alive, const BestPlan& best, const SearchEngine& engine);

// Paper Eq. 7 (unconstrained) and Eq. 8 (constrained): one beam, the cut with the largest J_L, among regions
// of at least `minRegionVolume`. Returns true when cancelled; `levels` is the chain's length. `start`: the
// state the chain starts from (null: the uncut model), a node of `engine`.
bool runGreedy(SearchEngine& engine, bool constrained, double minRegionVolume, BestPlan& best,
               const SearchProgressSink& sink, int& levels, NodePtr start = nullptr);

// Algorithm 1 of the paper at one scale. Returns true when cancelled; `levels` is the deepest level reached.
// `start`: as for runGreedy; the scale's levels count from it.
bool runBeamSearch(SearchEngine& engine, const SearchOptions& o, const BeamScale& scale, BestPlan& best,
                   const SearchProgressSink& sink, int& levels, NodePtr start = nullptr);

// The beam scheme: both greedy chains at w, then the beam search at every scale, w, 2w, ..., each on an engine
// of its own that shares `engine`'s scored root. They run side by side with the threads divided among them
// (independent searches use two cores better than one search's short parallel loops do), and a search that
// finishes gives its threads to the finest still running. Each search is deterministic whatever its thread
// count, and their plans are offered to `best` in that order (the greedy chains seed the result, so the beam
// plan is never worse than either greedy scheme, as the paper observes), so the result does not depend on
// which finishes first.
bool runBeamScheme(SearchEngine& engine, const SearchOptions& o, BestPlan& best, const SearchProgressSink& sink,
                   int& levels, BeamWork& work);

}  // namespace multidir::core::detail

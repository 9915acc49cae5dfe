// Algorithm 1 of the paper: the beam-guided search with progressive relaxation, at one region scale.
#include <algorithm>
#include <cmath>

#include "multidir/core/search/candidate_planes.h"
#include "search/search_schemes.h"

namespace multidir::core::detail {
namespace {

// Progressive relaxation as one ordering: a candidate with R(M+) below delta_0 * growth^i enters in round i,
// and inside a round by J_G. Walking this order and filling beams is the paper's loop of widening delta.
int relaxationRound(double risky, const SearchOptions& o) {
  int round = 0;
  for (double delta = o.initialDeltaMm2; risky >= delta && round < 200; delta *= o.deltaGrowth) ++round;
  return round;
}

bool tooClose(const ScoredCandidate& a, const ScoredCandidate& b, const std::vector<Vec3>& normals,
              const SearchOptions& o) {
  return a.beam == b.beam && std::abs(normals[a.normal].dot(normals[b.normal])) > o.diversityCosine &&
         std::abs(a.offsetMm - b.offsetMm) < o.diversityOffsetMm;
}

// Two beams hold the same remaining part (up to rounding): same volume, same risky area, same face count.
bool sameState(const SearchNode& a, const SearchNode& b) {
  return a.remaining->faceCount() == b.remaining->faceCount() &&
         std::abs(a.volumeMm3 - b.volumeMm3) <= 1e-9 * std::max(a.volumeMm3, b.volumeMm3) &&
         std::abs(a.jg() - b.jg()) <= 1e-9 * std::max(1.0, a.jg());
}

// Key of a candidate in Algorithm 1: its relaxation round, then J_G.
struct CandidateKey {
  int round = 0;
  double jg = 0.0;
  bool operator<(const CandidateKey& other) const { return round != other.round ? round < other.round : jg < other.jg; }
};

CandidateKey keyOf(const ScoredCandidate& c, const SearchOptions& o) { return {relaxationRound(c.riskyAboveMm2, o), c.jgMm2}; }

// The pool in the order Algorithm 1 takes it: relaxation round, then J_G, then pool position (a total order, so
// the order is one whatever the sort). A level takes a few dozen candidates of a pool of tens of thousands, so
// the order is sorted only as far as it is read: each time a position past the sorted part is asked for, the
// next smallest chunk of the rest is selected (nth_element) and sorted; everything before it is no greater
// than anything after, so the positions read are those of the full sort.
class BeamOrder {
 public:
  BeamOrder(const std::vector<ScoredCandidate>& pool, const SearchOptions& o) : m_keys(pool.size()), m_order(pool.size()) {
    for (std::size_t i = 0; i < pool.size(); ++i) {
      m_keys[i] = keyOf(pool[i], o);
      m_order[i] = i;
    }
  }
  std::size_t size() const { return m_order.size(); }
  // The pool index at `position` (< size()).
  std::size_t operator[](std::size_t position) {
    while (position >= m_sorted) {
      const std::size_t end = std::min(m_order.size(), m_sorted + std::max(kFirstChunk, m_sorted));
      const auto first = m_order.begin() + static_cast<std::ptrdiff_t>(m_sorted);
      const auto last = m_order.begin() + static_cast<std::ptrdiff_t>(end);
      const auto before = [&](std::size_t a, std::size_t b) {
        if (m_keys[a] < m_keys[b]) return true;
        if (m_keys[b] < m_keys[a]) return false;
        return a < b;  // pool order is (beam, normal, offset): fixed
      };
      std::nth_element(first, last - 1, m_order.end(), before);
      std::sort(first, last, before);
      m_sorted = end;
    }
    return m_order[position];
  }

 private:
  static constexpr std::size_t kFirstChunk = 64;
  std::vector<CandidateKey> m_keys;
  std::vector<std::size_t> m_order;
  std::size_t m_sorted = 0;
};

// Refines the best candidates between the lattice normals (a pattern search on the sphere per seed: six
// normals around the best so far, the radius halved each round) and adds what it scores to the pool. The
// lattice spacing (~13 degrees for 250 normals) is coarse enough that which side of a feature a lattice
// normal falls on decides whether a region comes out risk-free; the bunny's plan swung between 3 % and 15 %
// of J_G with the number of normals before this. Returns true when cancelled.
bool refineCandidates(SearchEngine& engine, const std::vector<NodePtr>& beams, const SearchOptions& o,
                      const BeamScale& scale, std::vector<ScoredCandidate>& pool) {
  if (o.refinementRounds == 0) return false;
  const double spacing = normalSpacingRadians(engine.machine(), o.candidates);
  if (spacing <= 0) return false;
  // Seeds: the first beamWidth distinct (beam, normal) pairs in Algorithm 1's order.
  std::vector<ScoredCandidate> seeds;
  BeamOrder order(pool, o);
  for (std::size_t position = 0; position < order.size(); ++position) {
    if (static_cast<int>(seeds.size()) >= scale.beamWidth) break;
    const ScoredCandidate& c = pool[order[position]];
    const bool seen = std::any_of(seeds.begin(), seeds.end(),
                                  [&](const ScoredCandidate& s) { return s.beam == c.beam && s.normal == c.normal; });
    if (!seen) seeds.push_back(c);
  }
  for (const ScoredCandidate& seed : seeds) {
    Vec3 center = engine.normals()[seed.normal];
    CandidateKey best = keyOf(seed, o);
    double radius = spacing / 2;
    for (int round = 0; round < o.refinementRounds; ++round, radius /= 2) {
      std::vector<int> indices;
      for (const Vec3& n : neighbourNormals(engine.machine(), center, radius, round * kPi / 6))
        indices.push_back(engine.addNormal(n));
      if (indices.empty()) break;
      bool cancelled = false;
      std::vector<ScoredCandidate> scored = engine.scoreNormals(*beams[seed.beam], seed.beam, indices, cancelled);
      if (cancelled) return true;
      dropSmallerThan(scored, scale.minRegionVolume);
      for (const ScoredCandidate& c : scored) {
        if (keyOf(c, o) < best) {
          best = keyOf(c, o);
          center = engine.normals()[c.normal];
        }
      }
      // Every plane scored joins the pool: near-best planes of other normals give the beam its choices.
      pool.insert(pool.end(), scored.begin(), scored.end());
    }
  }
  return false;
}

}  // namespace

bool runBeamSearch(SearchEngine& engine, const SearchOptions& o, const BeamScale& scale, BestPlan& best,
                   const SearchProgressSink& sink, int& levels, NodePtr start) {
  if (!start) start = engine.root();
  std::vector<NodePtr> beams = {start};
  best.offer(start);
  if (engine.isTerminal(*start, scale.minRegionVolume)) return false;
  for (int level = 0; !beams.empty() && level < scale.maxLevels; ++level) {
    levels = std::max(levels, level + 1);
    std::vector<ScoredCandidate> pool;
    for (int b = 0; b < static_cast<int>(beams.size()); ++b) {
      bool cancelled = false;
      std::vector<ScoredCandidate> scored = engine.score(*beams[b], b, cancelled);
      if (cancelled) return true;
      dropSmallerThan(scored, scale.minRegionVolume);
      pool.insert(pool.end(), scored.begin(), scored.end());
    }
    if (refineCandidates(engine, beams, o, scale, pool)) return true;
    for (const NodePtr& beam : beams) releaseParentSweeps(engine, *beam);
    BeamOrder order(pool, o);
    std::vector<NodePtr> next;
    std::vector<ScoredCandidate> chosen;
    auto closeToChosen = [&](const ScoredCandidate& c) {
      return std::any_of(chosen.begin(), chosen.end(),
                         [&](const ScoredCandidate& other) { return tooClose(c, other, engine.normals(), o); });
    };
    // Candidates in Algorithm 1's order, clipped a batch at a time on the engine's threads; a batch holds
    // as many as beams are still missing (at most the thread count), and its children are taken in order.
    for (std::size_t position = 0; static_cast<int>(next.size()) < scale.beamWidth && position < order.size();) {
      if (engine.job().isCancelled()) return true;
      const std::size_t wanted =
          static_cast<std::size_t>(std::min(engine.threads(), scale.beamWidth - static_cast<int>(next.size())));
      std::vector<std::size_t> batch;
      for (; batch.size() < wanted && position < order.size(); ++position) {
        const ScoredCandidate& c = pool[order[position]];
        if (!closeToChosen(c) && beams[c.beam]->prefixJgMm2 + c.riskyAboveMm2 < scale.abandonAtMm2)
          batch.push_back(order[position]);
      }
      const std::vector<std::optional<NodePtr>> children = extendAll(engine, beams, pool, batch);
      for (std::size_t i = 0; i < batch.size() && static_cast<int>(next.size()) < scale.beamWidth; ++i) {
        const ScoredCandidate& c = pool[batch[i]];
        if (closeToChosen(c)) continue;  // close to one chosen earlier in this batch
        const std::optional<NodePtr>& child = children[i];
        if (!child || (*child)->prefixJgMm2 >= scale.abandonAtMm2) continue;
        // The same cuts in another order leave the same part: keep one of them.
        bool duplicate = false;
        for (const NodePtr& other : next) duplicate = duplicate || sameState(**child, *other);
        if (duplicate) continue;
        chosen.push_back(c);
        best.offer(*child);
        next.push_back(*child);
      }
    }
    beams.clear();
    for (const NodePtr& node : next)
      if (!engine.isTerminal(*node, scale.minRegionVolume)) beams.push_back(node);
    report(sink, level + 1, static_cast<int>(beams.size()), best, engine);
  }
  return false;
}

}  // namespace multidir::core::detail

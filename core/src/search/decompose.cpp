#include "multidir/core/search/decompose.h"
#include "multidir/core/search/plan_from_planes.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <tuple>
#include <cmath>

#include "detail/freed_memory.h"
#include "detail/parallel.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "search/run_decomposition.h"
#include "search/search_engine.h"

namespace multidir::core {
namespace {

using detail::ScoredCandidate;
using detail::SearchEngine;
using detail::SearchNode;
using NodePtr = std::shared_ptr<const SearchNode>;

// Keeps the best plan seen: least J_G, then fewer regions (Criterion IV), then first found.
class BestPlan {
 public:
  void offer(const NodePtr& node) {
    constexpr double kTie = 1e-9;
    if (!m_node || node->jg() < m_node->jg() - kTie ||
        (std::abs(node->jg() - m_node->jg()) <= kTie && node->level < m_node->level))
      m_node = node;
  }
  const NodePtr& node() const { return m_node; }  // null before anything was offered

 private:
  NodePtr m_node;
};

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

// One scale of the beam search: the smallest region it may cut off, its beams and its levels.
struct BeamScale {
  double minRegionVolume = 0.0;
  int beamWidth = 1;
  int maxLevels = 1;
};

// Candidates whose region is below the scale's smallest are not this scale's to take.
void dropSmallerThan(std::vector<ScoredCandidate>& candidates, double minRegionVolume) {
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [&](const ScoredCandidate& c) { return c.volumeAboveMm3 < minRegionVolume; }),
                   candidates.end());
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

// The pool in the order Algorithm 1 takes it: relaxation round, then J_G, then pool position.
std::vector<std::size_t> beamOrder(const std::vector<ScoredCandidate>& pool, const SearchOptions& o) {
  std::vector<CandidateKey> keys(pool.size());
  for (std::size_t i = 0; i < pool.size(); ++i) keys[i] = keyOf(pool[i], o);
  std::vector<std::size_t> order(pool.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (keys[a] < keys[b]) return true;
    if (keys[b] < keys[a]) return false;
    return a < b;  // pool order is (beam, normal, offset): fixed
  });
  return order;
}

// Once every child of a node was scored, its sweeps are no longer needed (the root's serve all schemes).
void releaseParentSweeps(const SearchEngine& engine, const SearchNode& scored) {
  if (scored.parent && scored.parent != engine.root()) scored.parent->latticeSweeps.reset();
}

// Extends beams by the pool's candidates at `indices`, on the engine's threads; results in the order given.
// The callers take these in order as if made one by one, so only the wasted work depends on the threads.
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
  for (std::size_t index : beamOrder(pool, o)) {
    if (static_cast<int>(seeds.size()) >= scale.beamWidth) break;
    const ScoredCandidate& c = pool[index];
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

// Algorithm 1 of the paper.
bool runBeamSearch(SearchEngine& engine, const SearchOptions& o, const BeamScale& scale, BestPlan& best,
                   const SearchProgressSink& sink, int& levels) {
  std::vector<NodePtr> beams = {engine.root()};
  best.offer(engine.root());
  if (engine.isTerminal(*engine.root(), scale.minRegionVolume)) return false;
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
    const std::vector<std::size_t> order = beamOrder(pool, o);
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
      for (; batch.size() < wanted && position < order.size(); ++position)
        if (!closeToChosen(pool[order[position]])) batch.push_back(order[position]);
      const std::vector<std::optional<NodePtr>> children = extendAll(engine, beams, pool, batch);
      for (std::size_t i = 0; i < batch.size() && static_cast<int>(next.size()) < scale.beamWidth; ++i) {
        const ScoredCandidate& c = pool[batch[i]];
        if (closeToChosen(c)) continue;  // close to one chosen earlier in this batch
        const std::optional<NodePtr>& child = children[i];
        if (!child) continue;
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

// Paper Eq. 7 (unconstrained) and Eq. 8 (constrained): one beam, the cut with the largest J_L.
bool runGreedy(SearchEngine& engine, bool constrained, double minRegionVolume, BestPlan& best,
               const SearchProgressSink& sink, int& levels) {
  NodePtr node = engine.root();
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

// What the scales' own engines did, for the plan's statistics.
struct BeamWork {
  long long candidatesScored = 0;
  int clipsPerformed = 0;
};

// The beam scheme: both greedy chains at w, then the beam search at every scale, w, 2w, ..., each on an engine
// of its own that shares `engine`'s scored root. They run side by side with the threads divided among them
// (independent searches use two cores better than one search's short parallel loops do), and a search that
// finishes gives its threads to the finest still running. Each search is deterministic whatever its thread
// count, and their plans are offered to `best` in that order (the greedy chains seed the result, so the beam
// plan is never worse than either greedy scheme, as the paper observes), so the result does not depend on
// which finishes first.
bool runBeamScheme(SearchEngine& engine, const SearchOptions& o, BestPlan& best, const SearchProgressSink& sink,
                   int& levels, BeamWork& work) {
  best.offer(engine.root());
  bool rootCancelled = false;
  engine.score(*engine.root(), 0, rootCancelled);  // once, with every thread: the forks share it
  if (rootCancelled) return true;
  const int scales = o.volumeScales;
  constexpr int kGreedyChains = 2;
  const int searches = kGreedyChains + scales;
  const int threads = engine.threads();
  SearchOptions perScale = o;
  perScale.threads = std::max(1, threads / std::min(threads, searches));
  perScale.beamWidth = (o.beamWidth + scales - 1) / scales;

  // Progress: the levels of all scales added up (maxSearchLevels counts them so), the best plan of any.
  std::mutex progressMutex;
  std::vector<int> scaleLevels(static_cast<std::size_t>(scales), 0), scaleBeams(static_cast<std::size_t>(scales), 0);
  double bestJg = engine.root()->jg();
  long long scoredBefore = engine.candidatesScored();
  std::vector<long long> scaleScored(static_cast<std::size_t>(scales), 0);

  std::vector<BestPlan> found(static_cast<std::size_t>(searches));
  std::vector<int> reached(static_cast<std::size_t>(searches), 0);
  std::vector<char> stopped(static_cast<std::size_t>(searches), 0);
  std::vector<BeamWork> done(static_cast<std::size_t>(searches));
  std::vector<std::unique_ptr<SearchEngine>> engines;
  for (int k = 0; k < searches; ++k) engines.push_back(std::make_unique<SearchEngine>(engine, perScale));
  enum State : char { Waiting, Running, Finished };
  std::vector<State> state(static_cast<std::size_t>(searches), Waiting);
  detail::parallelFor(searches, std::min(threads, searches), [&](int task) {
    SearchEngine& own = *engines[static_cast<std::size_t>(task)];
    {
      std::lock_guard<std::mutex> lock(progressMutex);
      state[static_cast<std::size_t>(task)] = Running;
    }
    // A search that finishes gives its threads to the finest one running, unless one still waits (the thread
    // that ran this one takes it next).
    auto finished = [&] {
      done[static_cast<std::size_t>(task)] = {own.candidatesScored(), own.clipsPerformed()};
      std::lock_guard<std::mutex> lock(progressMutex);
      state[static_cast<std::size_t>(task)] = Finished;
      if (std::find(state.begin(), state.end(), Waiting) != state.end()) return;
      for (int k = searches - 1; k >= 0; --k)
        if (state[static_cast<std::size_t>(k)] == Running) {
          engines[static_cast<std::size_t>(k)]->addThreads(own.threads());
          break;
        }
    };
    if (task < kGreedyChains) {
      stopped[static_cast<std::size_t>(task)] =
          runGreedy(own, task == 1, own.minRegionVolume(o.minVolumeDivisor), found[static_cast<std::size_t>(task)], {},
                    reached[static_cast<std::size_t>(task)]);
      reached[static_cast<std::size_t>(task)] = 0;  // the levels reported are the beam's
      finished();
      return;
    }
    const int s = task - kGreedyChains;
    const double divisor = std::ldexp(o.minVolumeDivisor, s);
    BeamScale scale;
    scale.minRegionVolume = own.minRegionVolume(divisor);
    scale.maxLevels = static_cast<int>(std::ceil(divisor)) + 1;
    scale.beamWidth = perScale.beamWidth;
    const SearchProgressSink scaleSink = [&, s](const SearchProgress& p) {
      if (!sink) return;
      std::lock_guard<std::mutex> lock(progressMutex);
      scaleLevels[static_cast<std::size_t>(s)] = p.level;
      scaleBeams[static_cast<std::size_t>(s)] = p.beamsAlive;
      scaleScored[static_cast<std::size_t>(s)] = p.candidatesScored;
      bestJg = std::min(bestJg, p.bestJgMm2);
      SearchProgress total = p;
      total.level = 0;
      total.beamsAlive = 0;
      total.candidatesScored = scoredBefore;
      for (int k = 0; k < scales; ++k) {
        total.level += scaleLevels[static_cast<std::size_t>(k)];
        total.beamsAlive += scaleBeams[static_cast<std::size_t>(k)];
        total.candidatesScored += scaleScored[static_cast<std::size_t>(k)];
      }
      total.bestJgMm2 = bestJg;
      sink(total);
    };
    stopped[static_cast<std::size_t>(task)] = runBeamSearch(own, perScale, scale, found[static_cast<std::size_t>(task)],
                                                            scaleSink, reached[static_cast<std::size_t>(task)]);
    finished();
  });
  bool cancelled = false;
  for (int task = 0; task < searches; ++task) {
    const auto k = static_cast<std::size_t>(task);
    if (found[k].node()) best.offer(found[k].node());
    levels = std::max(levels, reached[k]);
    cancelled = cancelled || stopped[k];
    work.candidatesScored += done[k].candidatesScored;
    work.clipsPerformed += done[k].clipsPerformed;
  }
  return cancelled;
}

// The planes of a node's chain, in clipping order.
std::vector<Plane> planesOf(const NodePtr& node) {
  std::vector<Plane> planes;
  for (const SearchNode* n = node.get(); n && n->parent; n = n->parent.get()) planes.push_back(n->plane);
  std::reverse(planes.begin(), planes.end());
  return planes;
}

// The nodes of a node's chain, the root first.
std::vector<NodePtr> chainOf(const NodePtr& node) {
  std::vector<NodePtr> chain;
  for (NodePtr n = node; n; n = n->parent) chain.push_back(n);
  std::reverse(chain.begin(), chain.end());
  return chain;
}

// The node that the planes make from `start`, or null when some plane is refused.
NodePtr rebuild(SearchEngine& engine, NodePtr start, const std::vector<Plane>& planes) {
  NodePtr node = std::move(start);
  for (const Plane& plane : planes) {
    auto child = engine.cut(node, plane);
    if (!child.ok()) return nullptr;
    node = *child;
  }
  return node;
}

}  // namespace

// A plane is kept only if it pays for itself: each region costs a platform move and a seam.
NodePtr detail::withoutUnpaidPlanes(SearchEngine& engine, NodePtr node, const SearchOptions& o) {
  const double threshold = std::max(o.minPlaneGainMm2, o.minPlaneGainPercent / 100.0 * engine.root()->riskyUpAreaMm2);
  std::vector<Plane> planes = planesOf(node);
  while (!planes.empty()) {
    // Without plane k, the first k cuts are unchanged: start from the node they made.
    const std::vector<NodePtr> chain = chainOf(node);
    std::vector<NodePtr> without(planes.size());
    detail::parallelFor(static_cast<int>(planes.size()), engine.threads(), [&](int k) {
      const std::vector<Plane> later(planes.begin() + k + 1, planes.end());
      without[k] = rebuild(engine, chain[k], later);
    });
    NodePtr bestNode;
    for (const NodePtr& candidate : without) {
      if (!candidate || candidate->jg() - node->jg() >= threshold) continue;
      if (!bestNode || candidate->jg() < bestNode->jg()) bestNode = candidate;
    }
    if (!bestNode) break;
    node = bestNode;
    planes = planesOf(node);  // as cut: each kept off the vertices of what it cuts now
  }
  return node;
}

Status detail::checkSearchInputs(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options) {
  if (Status s = validate(options); !s) return s;
  if (Status s = validate(machine); !s) return s;
  if (model.empty()) return Error{ErrorCode::EmptyMesh, "the model has no faces: load a closed mesh first", "model"};
  if (!(signedVolume(model) > 0))
    return Error{ErrorCode::InvalidParameter, "the model has no positive volume: load it with loadMesh, which orients it",
                 "model"};
  // Before the engine allocates anything: a model in the wrong units would ask for gigabytes.
  return checkCandidateCount(model, machine, options.candidates);
}

Decomposition detail::runDecomposition(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                               JobContext& job, const SearchProgressSink& progress,
                               const std::optional<PlatformRegion>& platform) {
  const auto start = std::chrono::steady_clock::now();
  SearchEngine engine(model, machine, options, job, platform);
  BestPlan best;
  int levels = 0;
  bool cancelled = false;
  BeamWork scaleWork;
  switch (options.scheme) {
    case SearchScheme::Beam: cancelled = runBeamScheme(engine, options, best, progress, levels, scaleWork); break;
    case SearchScheme::Greedy:
      cancelled = runGreedy(engine, false, engine.minRegionVolume(options.minVolumeDivisor), best, progress, levels);
      break;
    case SearchScheme::ConstrainedGreedy:
      cancelled = runGreedy(engine, true, engine.minRegionVolume(options.minVolumeDivisor), best, progress, levels);
      break;
  }
  Decomposition plan = engine.planOf(*withoutUnpaidPlanes(engine, best.node(), options));
  plan.cancelled = cancelled;
  plan.rotationAxis = machine.rotationAxis;
  plan.statistics.candidatesScored = engine.candidatesScored() + scaleWork.candidatesScored;
  plan.statistics.candidatesPerLevel = std::max(0, engine.firstLevelCandidates());
  plan.statistics.normals = engine.latticeSize();
  plan.statistics.levels = levels;
  plan.statistics.clipsPerformed = engine.clipsPerformed() + scaleWork.clipsPerformed;
  plan.statistics.threads = engine.threads();
  plan.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return plan;
}

using detail::checkSearchInputs;
using detail::runDecomposition;

Result<Decomposition> decompose(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                                JobContext& job, const SearchProgressSink& progress) {
  if (Status s = checkSearchInputs(model, machine, options); !s) return s.error();
  Decomposition plan;
  if (detail::needsProxy(model, options)) {
    auto searched = detail::runProxyDecomposition(
        model, machine, options, job, [&](const TriangleMesh& mesh, const SearchOptions& o, const PlatformRegion& p) {
          return Result<Decomposition>(runDecomposition(mesh, machine, o, job, progress, p));
        });
    if (!searched.ok()) return searched.error();
    plan = std::move(*searched);
  } else {
    plan = runDecomposition(model, machine, options, job, progress);
  }
  detail::returnFreedMemory();
  job.setProgress(1.0, "search done");
  return plan;
}

Result<Decomposition> planFromClippingPlanes(const TriangleMesh& model, const MachineSpec& machine,
                                             const SearchOptions& options, const std::vector<Plane>& clippingPlanes) {
  if (Status s = checkSearchInputs(model, machine, options); !s) return s.error();
  const auto start = std::chrono::steady_clock::now();
  SearchOptions evaluation = options;
  evaluation.candidates.normalSamples = 1;  // the engine's own candidates are not used here
  JobContext job;
  SearchEngine engine(model, machine, evaluation, job);
  NodePtr node = engine.root();
  for (const Plane& plane : clippingPlanes) {
    auto child = engine.cut(node, plane);
    if (!child.ok()) return child.error();
    node = *child;
  }
  Decomposition plan = engine.planOf(*node);
  plan.rotationAxis = machine.rotationAxis;
  plan.statistics.levels = static_cast<int>(clippingPlanes.size());
  plan.statistics.clipsPerformed = engine.clipsPerformed();
  plan.statistics.threads = 1;
  plan.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return plan;
}

namespace {

// The axis search's second stage: the full beam search on this many axes (the given one and the best-scored).
constexpr int kAxesSearchedInFull = 8;

// The axis search proper, on `model` (the model itself or its proxy) with `platform` as the platform region
// when given.
Result<Decomposition> searchAxes(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                                 int axisCount, JobContext& job, const SearchProgressSink& progress,
                                 const std::optional<PlatformRegion>& platform) {
  const auto start = std::chrono::steady_clock::now();

  const int threads = detail::resolveThreadCount(options.threads);
  SearchOptions perAxis = options;
  perAxis.threads = 1;  // parallel across axes instead
  const Vec3 first = machine.rotationAxis;
  const Vec3 second = machine.up.cross(first);
  auto machineFor = [&](int axis) {
    const double angle = kPi * axis / axisCount;
    MachineSpec spec = machine;
    spec.rotationAxis = (std::cos(angle) * first + std::sin(angle) * second).normalized();
    return spec;
  };
  // Only the best plan so far is kept (each axis's plan holds its regions' meshes, so keeping all would make
  // memory grow with the number of axes). "Best": least J_G, then fewer regions, then the lower axis index,
  // compared exactly, so the winner does not depend on the order the threads finish in.
  std::optional<Decomposition> best;
  int bestAxis = -1;
  SearchStatistics total;
  std::mutex resultMutex;
  const auto key = [](double jg, std::size_t regions, int axis) { return std::make_tuple(jg, regions, axis); };
  auto account = [&](const Decomposition& result) {
    total.candidatesScored += result.statistics.candidatesScored;
    total.clipsPerformed += result.statistics.clipsPerformed;
    total.levels = std::max(total.levels, result.statistics.levels);
    total.candidatesPerLevel = std::max(total.candidatesPerLevel, result.statistics.candidatesPerLevel);
    total.normals = result.statistics.normals;
  };
  auto offer = [&](Decomposition result, int axis) {
    if (!best || key(result.jgAfterMm2, result.regions.size(), axis) <
                     key(best->jgAfterMm2, best->regions.size(), bestAxis)) {
      best = std::move(result);
      bestAxis = axis;
    }
  };
  auto report = [&](int axis, const Decomposition& result) {
    if (!progress) return;
    SearchProgress p;
    p.axisIndex = axis;
    p.axisCount = axisCount;
    p.bestJgMm2 = result.jgAfterMm2;
    p.candidatesScored = result.statistics.candidatesScored;
    progress(p);
  };

  // 1. Every axis scored by a beam of width 1 without refinement (about a fifth of the full search's time);
  // 2. the full beam search on the given axis and the best-scored others. Greedy schemes (cheaper than the
  // screening) run once per axis. Measured on 180 axes (bench, idle): kitten 15.8 s and the same plan as the full
  // search on every axis (66 s); bunny 31.6 s for 809 mm^2 against 757 mm^2 in 104 s; the greedy schemes as
  // screens missed the bunny's best axes (977 mm^2 with 36 axes searched in full).
  const bool twoStages = options.scheme == SearchScheme::Beam && axisCount > kAxesSearchedInFull;
  SearchOptions screening = perAxis;
  if (twoStages) {
    screening.beamWidth = 1;
    screening.refinementRounds = 0;
  }
  std::vector<std::tuple<double, std::size_t, int>> scores(static_cast<std::size_t>(axisCount),
                                                           {INFINITY, std::size_t{0}, 0});
  const double steps = axisCount + (twoStages ? 5.0 * kAxesSearchedInFull : 0.0);
  int finished = 0;
  detail::parallelFor(axisCount, threads, [&](int a) {
    if (job.isCancelled()) return;
    Decomposition result = runDecomposition(model, machineFor(a), screening, job, {}, platform);
    std::lock_guard<std::mutex> lock(resultMutex);
    account(result);
    job.setProgress(++finished / steps, "axis search");
    report(a, result);
    scores[static_cast<std::size_t>(a)] = key(result.jgAfterMm2, result.regions.size(), a);
    offer(std::move(result), a);
  });
  if (twoStages && !job.isCancelled()) {
    std::vector<std::tuple<double, std::size_t, int>> ranked(scores.begin() + 1, scores.end());
    std::sort(ranked.begin(), ranked.end());
    std::vector<int> chosen{0};
    for (const auto& score : ranked)
      if (static_cast<int>(chosen.size()) < kAxesSearchedInFull && std::isfinite(std::get<0>(score)))
        chosen.push_back(std::get<2>(score));
    detail::parallelFor(static_cast<int>(chosen.size()), threads, [&](int k) {
      if (job.isCancelled()) return;
      Decomposition result = runDecomposition(model, machineFor(chosen[k]), perAxis, job, {}, platform);
      if (result.cancelled) return;  // the finished greedy plan stands
      std::lock_guard<std::mutex> lock(resultMutex);
      account(result);
      finished += 5;
      job.setProgress(finished / steps, "axis search");
      report(chosen[k], result);
      offer(std::move(result), chosen[k]);
    });
  }

  if (!best) {
    if (job.isCancelled()) return Error{ErrorCode::Cancelled, "the axis search was cancelled before any axis finished", "axis search"};
    return Error{ErrorCode::Internal, "no axis gave a plan", "axis search"};
  }
  detail::returnFreedMemory();
  best->cancelled = job.isCancelled();
  total.threads = threads;
  total.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  best->statistics = total;
  return std::move(*best);
}

}  // namespace

Result<Decomposition> decomposeWithAxisSearch(const TriangleMesh& model, const MachineSpec& machine,
                                              const SearchOptions& options, int axisCount, JobContext& job,
                                              const SearchProgressSink& progress) {
  if (machine.kind != MachineKind::RotaryPlatform)
    return Error{ErrorCode::InvalidParameter, "the axis search needs a 4-DOF machine (--machine 4dof)", "axis search"};
  if (axisCount < 1 || axisCount > 3600)
    return Error{ErrorCode::InvalidParameter, "the number of axes must be between 1 and 3600", "axis search"};
  if (Status s = checkSearchInputs(model, machine, options); !s) return s.error();
  if (!detail::needsProxy(model, options)) return searchAxes(model, machine, options, axisCount, job, progress, std::nullopt);
  // The platform region depends on up alone, so one serves every axis.
  auto plan = detail::runProxyDecomposition(
      model, machine, options, job, [&](const TriangleMesh& mesh, const SearchOptions& o, const PlatformRegion& p) {
        return searchAxes(mesh, machine, o, axisCount, job, progress, p);
      });
  detail::returnFreedMemory();
  return plan;
}

}  // namespace multidir::core

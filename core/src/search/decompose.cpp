#include "multidir/core/search/decompose.h"
#include "multidir/core/search/plan_from_planes.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <cmath>

#include "detail/freed_memory.h"
#include "detail/parallel.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "search/apart_search.h"
#include "search/cut_face_area.h"
#include "search/run_decomposition.h"
#include "search/search_engine.h"
#include "search/search_schemes.h"

namespace multidir::core {
namespace {

using detail::BeamWork;
using detail::BestPlan;
using detail::NodePtr;
using detail::SearchEngine;
using detail::SearchNode;
using detail::chainOf;
using detail::runBeamScheme;
using detail::runGreedy;
using detail::takeIfNew;

// The planes of a node's chain, in clipping order.
std::vector<Plane> planesOf(const NodePtr& node) {
  std::vector<Plane> planes;
  for (const SearchNode* n = node.get(); n && n->parent; n = n->parent.get()) planes.push_back(n->plane);
  std::reverse(planes.begin(), planes.end());
  return planes;
}

// The same planes, bit for bit, in the same order.
bool samePlanes(const std::vector<Plane>& a, const std::vector<Plane>& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const Plane& p, const Plane& q) {
           return p.normal == q.normal && p.offset == q.offset;
         });
}

}  // namespace

bool detail::takeIfNew(std::vector<std::vector<Plane>>& taken, std::vector<Plane> planes) {
  const bool seen = std::any_of(taken.begin(), taken.end(),
                                [&](const std::vector<Plane>& other) { return samePlanes(other, planes); });
  if (!seen) taken.push_back(std::move(planes));
  return !seen;
}

// A plane is kept only if it pays for itself: each region costs a platform move and a seam, and apart a part
// with its cut face (docs/apart.md, "The price of a part").
NodePtr detail::withoutUnpaidPlanes(SearchEngine& engine, NodePtr node, const SearchOptions& o) {
  const double minGain = std::max(o.minPlaneGainMm2, o.minPlaneGainPercent / 100.0 * engine.root()->riskyUpAreaMm2);
  auto partsPrice = [&](const NodePtr& n) {
    return engine.sequenceFree() ? o.partCostMm2 * n->level + o.cutFaceCost * detail::cutFaceAreaMm2(*n) : 0.0;
  };
  std::vector<Plane> planes = planesOf(node);
  while (!planes.empty()) {
    // Without plane k, the first k cuts are unchanged: start from the node they made.
    const std::vector<NodePtr> chain = chainOf(node);
    std::vector<NodePtr> without(planes.size());
    detail::parallelFor(static_cast<int>(planes.size()), engine.threads(), [&](int k) {
      const std::vector<Plane> later(planes.begin() + k + 1, planes.end());
      const Result<NodePtr> rebuilt = detail::cutInTurn(engine, chain[k], later);
      without[k] = rebuilt.ok() ? *rebuilt : nullptr;  // null: some later plane is refused without plane k
    });
    NodePtr bestNode;
    const double price = partsPrice(node);
    for (const NodePtr& candidate : without) {
      if (!candidate || candidate->jg() - node->jg() >= std::max(minGain, price - partsPrice(candidate))) continue;
      if (!bestNode || candidate->jg() < bestNode->jg()) bestNode = candidate;
    }
    if (!bestNode) break;
    node = bestNode;
    planes = planesOf(node);  // as cut: each kept off the vertices of what it cuts now
  }
  return node;
}

// The plan a search that ran to its end delivers: the least J_G, then the fewer planes, among the best plan and
// every side-by-side search's best, each once its unpaid planes are removed (docs/search.md, "Planes that do not
// pay"). The searches' plans are compared as found, but removing a plane raises J_G by up to the plane-gain
// threshold, so the best as found need not be the best that pays: on the bunny the constrained greedy chain's
// plan pays with 223.46 mm^2, the overall best as found with 233.39 mm^2. A plan whose J_G as found is already
// above the choice's cannot win (removing planes never lowers J_G) and is not cut again.
NodePtr detail::paidChoice(SearchEngine& engine, const NodePtr& best, const std::vector<NodePtr>& searchBests,
                           const SearchOptions& o, bool compareSearches, std::vector<PaidPlan>* paidPlans) {
  const auto paidOf = [&](const NodePtr& found) {
    NodePtr paid = withoutUnpaidPlanes(engine, found, o);
    if (paidPlans) paidPlans->push_back({found, paid});
    return paid;
  };
  NodePtr chosen = paidOf(best);
  if (!compareSearches) return chosen;
  const double tie = 1e-9 * std::max(1.0, engine.root()->riskyUpAreaMm2);
  for (const NodePtr& other : searchBests) {
    if (!other || other == best || !(other->jg() < chosen->jg() - tie)) continue;
    const NodePtr paid = paidOf(other);
    const bool tied = std::abs(paid->jg() - chosen->jg()) <= tie;
    if (paid->jg() < chosen->jg() - tie || (tied && paid->level < chosen->level)) chosen = paid;
  }
  return chosen;
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
                               const std::optional<PlatformRegion>& platform, std::vector<Decomposition>* finalists,
                               std::vector<Decomposition>* polishStarts) {
  const auto start = std::chrono::steady_clock::now();
  SearchEngine engine(model, machine, options, job, platform);
  BestPlan best(finalists != nullptr || polishStarts != nullptr);
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
  // A cancelled search delivers the best plan it has, the one its progress reported: removing the planes that
  // do not pay for themselves may raise J_G (by less than the plane-gain threshold), so it is left to a search
  // that ran to its end (docs/search.md, "Progress and Cancel"). The apart machine's own search (`finalists`)
  // keeps its best as found: its priced choice among the finalists follows (docs/apart.md).
  const bool compareSearches = finalists == nullptr;
  std::vector<PaidPlan> paidPlans;  // the plans paidChoice removed unpaid planes from: not done again below
  const NodePtr chosen = cancelled ? best.node()
                                   : paidChoice(engine, best.node(), scaleWork.searchBests, options, compareSearches,
                                                &paidPlans);
  const auto knownPaid = [&](const NodePtr& found) -> NodePtr {
    for (const PaidPlan& p : paidPlans)
      if (p.found == found) return p.paid;
    return nullptr;
  };
  Decomposition plan = engine.planOf(*chosen);
  const std::vector<Plane> chosenPlanes = planesOf(chosen);
  if (finalists && !cancelled) {
    std::vector<std::vector<Plane>> taken{chosenPlanes};
    // Each as found and without its unpaid planes: removing them lowers the price, but may raise J_G apart
    // above the bound the choice keeps.
    for (const NodePtr& finalist : best.finalists()) {
      if (!finalist || job.isCancelled()) continue;
      const NodePtr known = knownPaid(finalist);
      for (const NodePtr& node : {finalist, known ? known : withoutUnpaidPlanes(engine, finalist, options)})
        if (takeIfNew(taken, planesOf(node))) finalists->push_back(engine.planOf(*node));
    }
  }
  if (polishStarts && !cancelled) {
    // As found: polishedChoice removes their unpaid planes only from those it may polish (most it screens
    // out, and the removal re-cuts a plan's later planes once per plane tried). A finalist that pays with the
    // plan returned (the best as found is one: paidChoice made the plan from it) would only be found to be it
    // again there, after that removal: it is left out.
    std::vector<std::vector<Plane>> taken{chosenPlanes};
    for (const NodePtr& finalist : best.finalists()) {
      if (!finalist) continue;
      const NodePtr known = knownPaid(finalist);
      if (known && samePlanes(planesOf(known), chosenPlanes)) continue;
      if (takeIfNew(taken, planesOf(finalist))) polishStarts->push_back(engine.planOf(*finalist));
    }
  }
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
  // The apart machine adds its bound: never more J_G apart than the default 5-DOF plan (docs/apart.md), a
  // second search about as long as its own ("Measured"), so one progress runs over both.
  const bool apart = machine.kind == MachineKind::Apart;
  const detail::StagedProgress staged(progress, apart ? std::vector<double>{1.0, 1.0} : std::vector<double>{1.0},
                                      maxSearchLevels(options));
  Result<Decomposition> plan = apart ? detail::decomposeApart(model, machine, options, job, staged)
                                     : detail::searchedAndPolished(model, machine, options, job, staged.stage(0));
  if (!plan.ok()) return plan.error();
  detail::returnFreedMemory();
  // What the search reported last may be older than the plan a cancel delivers (searches running side by side
  // offer plans until they notice the cancel): the last report is the delivered plan's.
  if (plan->cancelled && progress) {
    SearchProgress last;
    last.level = plan->statistics.levels;
    last.bestJgMm2 = plan->jgAfterMm2;
    last.candidatesScored = plan->statistics.candidatesScored;
    staged.stage(apart ? 1 : 0)(last);  // the fraction stays where the search left it
  }
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
  const Result<NodePtr> node = detail::cutInTurn(engine, engine.root(), clippingPlanes);
  if (!node.ok()) return node.error();
  Decomposition plan = engine.planOf(**node);
  plan.rotationAxis = machine.rotationAxis;
  plan.statistics.levels = static_cast<int>(clippingPlanes.size());
  plan.statistics.clipsPerformed = engine.clipsPerformed();
  plan.statistics.threads = 1;
  plan.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return plan;
}

}  // namespace multidir::core

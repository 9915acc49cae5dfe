// Searching a polished plan's later planes again (docs/search.md, "Searching the tails again").
//
// Why: polishing turns each plane by a few degrees, but issue 30's diagnosis (multidir_jg_diagnosis_bench)
// found the fertility statue's J_G in which region a face lands, not in the planes' last degrees: every risky
// face of its plan is safe along another region's direction of the same plan. Changing the regions takes other
// planes, not moved ones: a large-neighbourhood search. From each state of the polished plan (its first k
// planes kept), the rest of the plan is dropped and searched again, by a narrow beam, from that polished
// state, which no search saw; each result pays for itself, and the best is polished and
// kept when it ends lower than the plan it started from.
#include "search/tail_search.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "search/run_decomposition.h"
#include "search/search_engine.h"
#include "search/search_schemes.h"

namespace multidir::core::detail {
namespace {

// The beam that searches each tail: two beams found the fertility statue's 10-region plan (2.19 %) from its
// first polished plane; one beam did not (its tails ended at 755 mm^2 or more, against 602 polished). The
// greedy chains that searched each tail beside it found nothing the beam did not on the nine shared models
// (the knight's 64.45 mm^2 and the statue's 289.68 both come from the beam) and cost a quarter of the tails.
constexpr int kTailBeamWidth = 2;

// The best plan, without its unpaid planes, that a beam of two finds from `start` (null when none cuts), its
// states abandoned once their regions hold `mustBeatMm2` (no plan through them can be lower). Deterministic.
NodePtr searchedFrom(SearchEngine& engine, const SearchOptions& o, const NodePtr& start, double mustBeatMm2) {
  BestPlan found;
  int levels = 0;
  BeamScale scale;
  scale.minRegionVolume = engine.minRegionVolume(o.minVolumeDivisor);
  scale.beamWidth = kTailBeamWidth;
  scale.maxLevels = static_cast<int>(std::ceil(o.minVolumeDivisor)) + 1;
  scale.abandonAtMm2 = mustBeatMm2;
  SearchOptions beam = o;
  beam.beamWidth = kTailBeamWidth;
  runBeamSearch(engine, beam, scale, found, {}, levels, start);
  if (!found.node() || found.node()->level <= start->level || !(found.node()->jg() < mustBeatMm2)) return nullptr;
  return withoutUnpaidPlanes(engine, found.node(), o);
}

}  // namespace

Decomposition withTailsSearchedAgain(const TriangleMesh& model, const MachineSpec& machine,
                                     const SearchOptions& options, Decomposition plan, JobContext& job,
                                     const std::optional<PlatformRegion>& platform) {
  if (plan.cancelled || plan.clippingPlanes.empty() || job.isCancelled()) return plan;
  const auto start = std::chrono::steady_clock::now();
  MachineSpec axis = machine;
  axis.rotationAxis = plan.rotationAxis;  // an axis search's choice
  SearchEngine engine(model, axis, options, job, platform);
  const Result<NodePtr> node = cutInTurn(engine, engine.root(), plan.clippingPlanes);
  if (!node.ok()) {
    plan.statistics.notes.push_back("tails not searched again: " + node.error().describe());
    return plan;
  }
  const std::vector<NodePtr> chain = chainOf(*node);
  // The searches from every state, in order, the first of equal J_G kept: the same for any thread count.
  NodePtr best;
  std::size_t bestStart = 0;
  for (std::size_t k = 0; k + 1 < chain.size() && !job.isCancelled(); ++k) {
    // A tail counts only below the polished plan and below the best tail so far (the first of equal J_G
    // kept), so its search abandons the states that already hold as much.
    const double mustBeat = best ? std::min(best->jg(), plan.jgAfterMm2) : plan.jgAfterMm2;
    const NodePtr tail = searchedFrom(engine, options, chain[k], mustBeat);
    if (tail && (!best || tail->jg() < best->jg())) {
      best = tail;
      bestStart = k;
    }
  }
  if (job.isCancelled()) return plan;
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // A tail as found is compared with the polished plan: polishing lowers a plan by 10 to 40 % (docs/search.md),
  // so one above the polished plan rarely polishes below it, and each polish costs about a search's time.
  if (!best || !(best->jg() < plan.jgAfterMm2)) {
    plan.statistics.seconds += seconds;
    plan.statistics.notes.push_back("the tails searched again: none lower than the polished plan");
    return plan;
  }
  Decomposition candidate = engine.planOf(*best);
  candidate.rotationAxis = plan.rotationAxis;
  candidate.statistics = plan.statistics;
  candidate.statistics.notes.clear();
  Decomposition polished = polishedIfAsked(model, machine, options, std::move(candidate), job, {}, platform);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double tie = 1e-9 * std::max(1.0, plan.jgBeforeMm2);
  if (job.isCancelled() || !(polished.jgAfterMm2 < plan.jgAfterMm2 - tie)) {
    plan.statistics.seconds += seconds;
    if (!job.isCancelled())
      plan.statistics.notes.push_back("the tails searched again: the lowest did not polish below the plan");
    return plan;
  }
  std::vector<std::string> notes = plan.statistics.notes;
  char note[240];
  std::snprintf(note, sizeof note,
                "the tails searched again: the planes after plane %zu, from the polished plan: %.2f mm^2 as "
                "found, %.2f polished, against %.2f (%.2f s)",
                bestStart, best->jg(), polished.jgAfterMm2, plan.jgAfterMm2, seconds);
  notes.push_back(note);
  polished.statistics.notes = std::move(notes);
  polished.statistics.jgBeforePolishMm2 = plan.statistics.jgBeforePolishMm2;
  polished.statistics.polishEvaluations += plan.statistics.polishEvaluations;
  polished.statistics.polishSeconds += plan.statistics.polishSeconds;
  polished.statistics.seconds = plan.statistics.seconds + seconds;
  polished.cancelled = false;
  return polished;
}

}  // namespace multidir::core::detail

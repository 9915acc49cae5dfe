// The plan a search delivers after polishing: its own plan polished, or with SearchOptions::polishFinalists the
// best polished of it and those of its finalists that may beat it (docs/search.md, "Polishing the finalists");
// then, with SearchOptions::searchTails, its tails searched again (tail_search.h).
//
// Why more than one: which plan polishes best is not the plan that was best before polishing. On the bunny's
// 254-normal lattice the search's plan (5 regions, 240.09 mm^2 as found) polishes to 177.58 mm^2, a 15-region
// finalist (194.29 mm^2) to 82.27; the delivered J_G then swings with the lattice, the spread issue 30 names.
//
// Why not all of them: a finalist far above the plan already polished would have to lose most of its J_G to
// polishing to win, and polishing one costs about as much as polishing the search's plan. So the finalists are
// polished from the lowest J_G up, and the first one that could win only by losing more of its J_G than any
// plan has lost to polishing in this search, and more than kLeastCreditedGain, ends the list (every later one
// starts higher still).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "search/run_decomposition.h"
#include "search/search_engine.h"
#include "search/search_schemes.h"
#include "search/tail_search.h"

namespace multidir::core::detail {
namespace {

// The share of its J_G polishing is credited with taking off any finalist, at least. The finalists that won on
// the bunny's seven lattices (244 to 256 normals) had to lose 53 and 59 % of their J_G to win, and lost 76 and
// 61 %; a finalist on the fertility statue had to lose 30 % and lost 5 % (docs/search.md, "Polishing the
// finalists").
constexpr double kLeastCreditedGain = 0.6;

// The share of its J_G polishing took off a plan, 0 when it took nothing.
double polishGain(double before, double after) { return before > 0 ? std::max(0.0, 1.0 - after / before) : 0.0; }

// `plan` (a finalist as found) without the planes that do not pay for themselves, as the search removes them
// from its own plan; the plan as it is when its planes are not cut again (the search cut them: not expected).
Decomposition paidPlanOf(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                          const Decomposition& plan, JobContext& job,
                          const std::optional<PlatformRegion>& platform) {
  SearchOptions evaluation = options;
  evaluation.candidates.normalSamples = 1;  // the engine only cuts given planes here
  MachineSpec axis = machine;
  axis.rotationAxis = plan.rotationAxis;
  SearchEngine engine(model, axis, evaluation, job, platform);
  const Result<NodePtr> cut = cutInTurn(engine, engine.root(), plan.clippingPlanes);
  if (!cut.ok()) return plan;
  Decomposition paid = engine.planOf(*detail::withoutUnpaidPlanes(engine, *cut, options));
  paid.rotationAxis = plan.rotationAxis;
  paid.statistics = plan.statistics;
  return paid;
}

}  // namespace

Decomposition searchedPolishedChoice(const TriangleMesh& model, const MachineSpec& machine,
                                     const SearchOptions& options, JobContext& job,
                                     const SearchProgressSink& progress,
                                     const std::optional<PlatformRegion>& platform, double mustBeatMm2) {
  std::vector<Decomposition> others;
  Decomposition plan = runDecomposition(model, machine, options, job, progress, platform, nullptr,
                                        options.polish && options.polishFinalists ? &others : nullptr);
  return polishedChoice(model, machine, options, std::move(plan), std::move(others), job, progress, platform,
                        mustBeatMm2);
}

Decomposition polishedChoice(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                             Decomposition plan, std::vector<Decomposition> others, JobContext& job,
                             const SearchProgressSink& progress, const std::optional<PlatformRegion>& platform,
                             double mustBeatMm2) {
  const bool finalists = options.polish && options.polishFinalists;
  // Competing with another plan (another pose's): a polish that cannot get below it is given up part-way.
  PolishRace ownRace{mustBeatMm2};
  Decomposition best = polishedIfAsked(model, machine, options, plan, job, progress, platform,
                                       std::isfinite(mustBeatMm2) ? &ownRace : nullptr);
  if (ownRace.gaveUp) {
    char note[200];
    std::snprintf(note, sizeof note,
                  "polishing given up part-way: its J_G fell too slowly to get below %.2f mm^2 (the plan it competes "
                  "with)",
                  mustBeatMm2);
    best.statistics.notes.push_back(note);
  }
  // Last, with SearchOptions::searchTails, the regions chosen again after the chosen plan's first planes.
  const auto withTails = [&](Decomposition chosen) {
    if (!options.searchTails || chosen.cancelled) return chosen;
    return withTailsSearchedAgain(model, machine, options, std::move(chosen), job, platform);
  };
  if (!finalists || best.cancelled) return withTails(std::move(best));
  // A gain below rounding is not one: the earlier plan stays (the search's own first).
  const double tie = 1e-9 * std::max(1.0, plan.jgBeforeMm2);
  double credited = std::max(kLeastCreditedGain, polishGain(plan.jgAfterMm2, best.jgAfterMm2));
  // The lowest as found first; equal ones in the search's order, so the order, and the plan, is the same for any
  // threads.
  std::vector<std::size_t> order(others.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return others[a].jgAfterMm2 < others[b].jgAfterMm2; });
  int evaluations = best.statistics.polishEvaluations, polished = 0, gaveUp = 0;
  double seconds = best.statistics.polishSeconds;
  bool chosen = false;
  std::vector<std::vector<Plane>> started{plan.clippingPlanes};
  for (const std::size_t i : order) {
    if (job.isCancelled()) break;
    // What a finalist must beat: the plan polished so far, and the plan competed with.
    const double target = std::min(best.jgAfterMm2, mustBeatMm2);
    // It, and every later one, could win only by losing more than polishing is credited with: without its
    // unpaid planes its J_G is no lower than as found.
    if (others[i].jgAfterMm2 * (1 - credited) >= target - tie) break;
    others[i].statistics = plan.statistics;  // the search's, as for its own plan
    others[i].rotationAxis = plan.rotationAxis;
    const auto paying = std::chrono::steady_clock::now();
    Decomposition other = paidPlanOf(model, machine, options, others[i], job, platform);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - paying).count();
    if (job.isCancelled()) break;
    const double asFound = other.jgAfterMm2;
    if (asFound * (1 - credited) >= target - tie) continue;
    // Two finalists may pay with the same planes, or with the search's own.
    if (!takeIfNew(started, other.clippingPlanes)) continue;
    const std::size_t regions = other.regions.size();
    PolishRace race{target};
    Decomposition result = polishedIfAsked(model, machine, options, std::move(other), job, {}, platform, &race);
    if (job.isCancelled()) break;  // a polish cut short is not compared: Cancel keeps the best finished one
    ++polished;
    if (race.gaveUp) ++gaveUp;
    evaluations += result.statistics.polishEvaluations;
    seconds += result.statistics.polishSeconds;
    if (!race.gaveUp) credited = std::max(credited, polishGain(asFound, result.jgAfterMm2));
    if (result.jgAfterMm2 < best.jgAfterMm2 - tie) {
      best = std::move(result);
      chosen = true;
      char note[200];
      std::snprintf(note, sizeof note, "a finalist of the search (%zu regions, %.2f mm^2 as found) polished best",
                    regions, asFound);
      best.statistics.notes.push_back(note);
    }
  }
  best.statistics.polishEvaluations = evaluations;
  best.statistics.seconds += seconds - best.statistics.polishSeconds;
  best.statistics.polishSeconds = seconds;
  char note[320];
  std::snprintf(note, sizeof note,
                "polished %d of %zu finalists of the search too (%d given up part-way, their J_G falling too slowly "
                "to win; the others would have had to lose more than %.0f %% of their J_G); %s",
                polished, others.size(), gaveUp, 100 * credited,
                chosen ? "a finalist polished best" : "the search's own plan polished best");
  best.statistics.notes.push_back(note);
  return withTails(std::move(best));
}

}  // namespace multidir::core::detail

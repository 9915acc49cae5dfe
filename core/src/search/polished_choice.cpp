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
#include <cstdio>
#include <numeric>

#include "search/run_decomposition.h"
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

}  // namespace

Decomposition searchedPolishedChoice(const TriangleMesh& model, const MachineSpec& machine,
                                     const SearchOptions& options, JobContext& job,
                                     const SearchProgressSink& progress,
                                     const std::optional<PlatformRegion>& platform) {
  std::vector<Decomposition> others;
  Decomposition plan = runDecomposition(model, machine, options, job, progress, platform, nullptr,
                                        options.polish && options.polishFinalists ? &others : nullptr);
  return polishedChoice(model, machine, options, std::move(plan), std::move(others), job, progress, platform);
}

Decomposition polishedChoice(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                             Decomposition plan, std::vector<Decomposition> others, JobContext& job,
                             const SearchProgressSink& progress, const std::optional<PlatformRegion>& platform) {
  const bool finalists = options.polish && options.polishFinalists;
  Decomposition best = polishedIfAsked(model, machine, options, plan, job, progress, platform);
  // Last, with SearchOptions::searchTails, the regions chosen again after the chosen plan's first planes.
  const auto withTails = [&](Decomposition chosen) {
    if (!options.searchTails || chosen.cancelled) return chosen;
    return withTailsSearchedAgain(model, machine, options, std::move(chosen), job, platform);
  };
  if (!finalists || best.cancelled) return withTails(std::move(best));
  // A gain below rounding is not one: the earlier plan stays (the search's own first).
  const double tie = 1e-9 * std::max(1.0, plan.jgBeforeMm2);
  double credited = std::max(kLeastCreditedGain, polishGain(plan.jgAfterMm2, best.jgAfterMm2));
  // The lowest first; equal ones in the search's order, so the order, and the plan, is the same for any threads.
  std::vector<std::size_t> order(others.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return others[a].jgAfterMm2 < others[b].jgAfterMm2; });
  int evaluations = best.statistics.polishEvaluations, polished = 0;
  double seconds = best.statistics.polishSeconds;
  bool chosen = false;
  for (const std::size_t i : order) {
    if (job.isCancelled()) break;
    Decomposition other = std::move(others[i]);
    const double asFound = other.jgAfterMm2;
    // It, and every later one, could win only by losing more than polishing is credited with.
    if (asFound * (1 - credited) >= best.jgAfterMm2 - tie) break;
    const std::size_t regions = other.regions.size();
    other.statistics = plan.statistics;  // the search's, as for its own plan
    other.rotationAxis = plan.rotationAxis;
    Decomposition result = polishedIfAsked(model, machine, options, std::move(other), job, {}, platform);
    if (job.isCancelled()) break;  // a polish cut short is not compared: Cancel keeps the best finished one
    ++polished;
    evaluations += result.statistics.polishEvaluations;
    seconds += result.statistics.polishSeconds;
    credited = std::max(credited, polishGain(asFound, result.jgAfterMm2));
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
  char note[256];
  std::snprintf(note, sizeof note,
                "polished %d of %zu finalists of the search too (the others would have had to lose more than %.0f %% "
                "of their J_G); %s",
                polished, others.size(), 100 * credited,
                chosen ? "a finalist polished best" : "the search's own plan polished best");
  best.statistics.notes.push_back(note);
  return withTails(std::move(best));
}

}  // namespace multidir::core::detail

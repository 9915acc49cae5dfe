// The plan a search delivers after polishing: its own plan polished, or with SearchOptions::polishFinalists the
// best polished of it and its finalists (docs/search.md, "Polishing the finalists").
//
// Why more than one: which plan polishes best is not the plan that was best before polishing. On the bunny's
// 254-normal lattice the search's plan (5 regions, 240.09 mm^2 as found) polishes to 177.58 mm^2, a 15-region
// finalist (194.29 mm^2) to 82.27; the delivered J_G then swings with the lattice, the spread issue 30 names.
#include <algorithm>
#include <cstdio>

#include "search/run_decomposition.h"

namespace multidir::core::detail {

Decomposition searchedPolishedChoice(const TriangleMesh& model, const MachineSpec& machine,
                                     const SearchOptions& options, JobContext& job,
                                     const SearchProgressSink& progress,
                                     const std::optional<PlatformRegion>& platform) {
  const bool finalists = options.polish && options.polishFinalists;
  std::vector<Decomposition> others;
  Decomposition plan = runDecomposition(model, machine, options, job, progress, platform, nullptr,
                                        finalists ? &others : nullptr);
  Decomposition best = polishedIfAsked(model, machine, options, plan, job, progress, platform);
  if (!finalists || best.cancelled || others.empty()) return best;
  // A gain below rounding is not one: the earlier plan stays (the search's own first).
  const double tie = 1e-9 * std::max(1.0, plan.jgBeforeMm2);
  int evaluations = best.statistics.polishEvaluations, polished = 0;
  double seconds = best.statistics.polishSeconds;
  std::size_t chosen = 0;
  for (std::size_t i = 0; i < others.size() && !job.isCancelled(); ++i) {
    Decomposition other = std::move(others[i]);
    const double asFound = other.jgAfterMm2;
    const std::size_t regions = other.regions.size();
    other.statistics = plan.statistics;  // the search's, as for its own plan
    other.rotationAxis = plan.rotationAxis;
    Decomposition result = polishedIfAsked(model, machine, options, std::move(other), job, {}, platform);
    if (job.isCancelled()) break;  // a polish cut short is not compared: Cancel keeps the best finished one
    ++polished;
    evaluations += result.statistics.polishEvaluations;
    seconds += result.statistics.polishSeconds;
    if (result.jgAfterMm2 < best.jgAfterMm2 - tie) {
      best = std::move(result);
      chosen = i + 1;
      char note[200];
      std::snprintf(note, sizeof note, "finalist %zu of the search (%zu regions, %.2f mm^2 as found) polished best",
                    chosen, regions, asFound);
      best.statistics.notes.push_back(note);
    }
  }
  best.statistics.polishEvaluations = evaluations;
  best.statistics.seconds += seconds - best.statistics.polishSeconds;
  best.statistics.polishSeconds = seconds;
  char note[200];
  std::snprintf(note, sizeof note, "polished %d finalists of the search too; %s", polished,
                chosen == 0 ? "the search's own plan polished best" : "a finalist polished best");
  best.statistics.notes.push_back(note);
  return best;
}

}  // namespace multidir::core::detail

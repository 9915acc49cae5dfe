// The beam scheme: greedy chains and the beam at every region scale, side by side.
#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

#include "detail/parallel.h"
#include "search/search_schemes.h"

namespace multidir::core::detail {

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

  // Progress (issue 29): the best J_G is the least of the complete plans that any of the searches holds, the
  // greedy chains included, since their plans are offered to `best` like the beams' and Cancel delivers the
  // least of them; so it never rises. The level is the deepest any beam scale reached (the greedy chains only
  // seed the result, as in the plan's statistics), never their sum: the scales run side by side.
  std::mutex progressMutex;
  std::vector<int> scaleLevels(static_cast<std::size_t>(scales), 0), scaleBeams(static_cast<std::size_t>(scales), 0);
  double bestJg = engine.root()->jg();
  const long long scoredBefore = engine.candidatesScored();
  std::vector<long long> searchScored(static_cast<std::size_t>(searches), 0);
  // What search `task` reported, and the whole reported on (the caller's sink runs under the lock).
  auto reportOf = [&](int task, const SearchProgress& p) {
    if (!sink) return;
    std::lock_guard<std::mutex> lock(progressMutex);
    // Another search may have reported while the sink was cancelling the job: nothing is reported after a
    // cancel (checked under the lock, so a sink that cancels is the last one called here).
    if (engine.job().isCancelled()) return;
    searchScored[static_cast<std::size_t>(task)] = p.candidatesScored;
    if (task >= kGreedyChains) {
      scaleLevels[static_cast<std::size_t>(task - kGreedyChains)] = p.level;
      scaleBeams[static_cast<std::size_t>(task - kGreedyChains)] = p.beamsAlive;
    }
    bestJg = std::min(bestJg, p.bestJgMm2);
    SearchProgress total = p;
    total.level = *std::max_element(scaleLevels.begin(), scaleLevels.end());
    total.beamsAlive = 0;
    for (int beams : scaleBeams) total.beamsAlive += beams;
    total.candidatesScored = scoredBefore;
    for (long long scored : searchScored) total.candidatesScored += scored;
    total.bestJgMm2 = bestJg;
    sink(total);
  };

  std::vector<BestPlan> found(static_cast<std::size_t>(searches), BestPlan(engine.sequenceFree()));
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
      done[static_cast<std::size_t>(task)] = {own.candidatesScored(), own.clipsPerformed(), {}};
      std::lock_guard<std::mutex> lock(progressMutex);
      state[static_cast<std::size_t>(task)] = Finished;
      if (std::find(state.begin(), state.end(), Waiting) != state.end()) return;
      for (int k = searches - 1; k >= 0; --k)
        if (state[static_cast<std::size_t>(k)] == Running) {
          engines[static_cast<std::size_t>(k)]->addThreads(own.threads());
          break;
        }
    };
    const SearchProgressSink searchSink = [&, task](const SearchProgress& p) { reportOf(task, p); };
    if (task < kGreedyChains) {
      stopped[static_cast<std::size_t>(task)] =
          runGreedy(own, task == 1, own.minRegionVolume(o.minVolumeDivisor), found[static_cast<std::size_t>(task)],
                    searchSink, reached[static_cast<std::size_t>(task)]);
      reached[static_cast<std::size_t>(task)] = 0;  // the levels reported are the beam's
      finished();
      return;
    }
    const int s = task - kGreedyChains;
    const double divisor = volumeDivisorOfScale(o, s);
    BeamScale scale;
    scale.minRegionVolume = own.minRegionVolume(divisor);
    scale.maxLevels = static_cast<int>(std::ceil(divisor)) + 1;
    scale.beamWidth = perScale.beamWidth;
    stopped[static_cast<std::size_t>(task)] = runBeamSearch(own, perScale, scale, found[static_cast<std::size_t>(task)],
                                                            searchSink, reached[static_cast<std::size_t>(task)]);
    finished();
  });
  bool cancelled = false;
  for (int task = 0; task < searches; ++task) {
    const auto k = static_cast<std::size_t>(task);
    if (found[k].node()) best.offer(found[k].node());
    if (found[k].node()) work.searchBests.push_back(found[k].node());
    best.offerFinalistsOf(found[k]);
    levels = std::max(levels, reached[k]);
    cancelled = cancelled || stopped[k];
    work.candidatesScored += done[k].candidatesScored;
    work.clipsPerformed += done[k].clipsPerformed;
  }
  return cancelled;
}

}  // namespace multidir::core::detail

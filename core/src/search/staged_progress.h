#pragma once
// One progress for a search made of stages run one after the other (the apart machine's own search, then the
// 5-DOF search for its bound; docs/apart.md): each stage has a weight, and SearchProgress::fraction is the
// share of the whole done, never decreasing, although each stage's level and best J_G start again. Internal
// to core.
#include <memory>
#include <mutex>
#include <vector>

#include "multidir/core/search/search_options.h"

namespace multidir::core::detail {

// A stage's own share done, in [0, 1]: the deepest level reached of `maxLevels` while it searches (80 %;
// most searches stop well before the bound, so this part is a floor), then polishing (the last 20 %).
double stageFraction(const SearchProgress& progress, int maxLevels);

class StagedProgress {
 public:
  // `weights`: one per stage, positive; they are scaled to add up to 1. A null `sink` reports nowhere.
  StagedProgress(SearchProgressSink sink, std::vector<double> weights, int maxLevels);

  // The sink stage `index` (0-based) reports through: stage, stageCount and fraction set, the fraction never
  // below one reported before by any stage. Null when the sink is. Safe from several threads.
  SearchProgressSink stage(int index) const;

 private:
  struct Shared {
    std::mutex mutex;
    double fraction = 0.0;
  };
  SearchProgressSink m_sink;
  std::vector<double> m_starts;  // the share done when each stage starts; one more: 1
  int m_maxLevels = 1;
  std::shared_ptr<Shared> m_shared;
};

}  // namespace multidir::core::detail

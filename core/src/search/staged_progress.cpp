#include "search/staged_progress.h"

#include <algorithm>
#include <numeric>

namespace multidir::core::detail {

namespace {
// The share of a stage its search takes before polishing; polishing took 0.1 to 0.95 of the search's time on
// the shared models at effort 1 (docs/search.md, "Polishing"), so a fifth is its share.
constexpr double kSearchingShare = 0.8;
}  // namespace

double stageFraction(const SearchProgress& progress, int maxLevels) {
  if (progress.polishing) return kSearchingShare + (1.0 - kSearchingShare) * std::clamp(progress.polishFraction, 0.0, 1.0);
  const double levels = static_cast<double>(std::max(1, maxLevels));
  return kSearchingShare * std::clamp(static_cast<double>(progress.level) / levels, 0.0, 1.0);
}

StagedProgress::StagedProgress(SearchProgressSink sink, std::vector<double> weights, int maxLevels)
    : m_sink(std::move(sink)), m_maxLevels(std::max(1, maxLevels)), m_shared(std::make_shared<Shared>()) {
  if (weights.empty()) weights.push_back(1.0);
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  double start = 0.0;
  for (const double weight : weights) {
    m_starts.push_back(start);
    start += total > 0 ? weight / total : 1.0 / static_cast<double>(weights.size());
  }
  m_starts.push_back(1.0);
}

SearchProgressSink StagedProgress::stage(int index) const {
  if (!m_sink) return {};
  const int count = static_cast<int>(m_starts.size()) - 1;
  const auto i = static_cast<std::size_t>(std::clamp(index, 0, count - 1));
  const double start = m_starts[i], width = m_starts[i + 1] - m_starts[i];
  return [sink = m_sink, shared = m_shared, start, width, stage = static_cast<int>(i) + 1, count,
          maxLevels = m_maxLevels](const SearchProgress& progress) {
    SearchProgress staged = progress;
    staged.stage = stage;
    staged.stageCount = count;
    // The lock is held while reporting so that two threads' reports arrive in the order of their fractions.
    std::lock_guard<std::mutex> lock(shared->mutex);
    shared->fraction = std::max(shared->fraction, std::min(1.0, start + width * stageFraction(progress, maxLevels)));
    staged.fraction = shared->fraction;
    sink(staged);
  };
}

}  // namespace multidir::core::detail

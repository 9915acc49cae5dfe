#pragma once
// One progress and cancellation contract for every long core function.
// A default-constructed JobContext reports nowhere and is never cancelled.
// cancel() may be called from any thread and is sticky; progress is clamped to [0,1] and never decreases.
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

namespace multidir::core {

class JobContext {
 public:
  using ProgressSink = std::function<void(double fraction, const std::string& phase)>;

  JobContext() : m_shared(std::make_shared<Shared>()) {}
  explicit JobContext(ProgressSink sink) : JobContext() { m_shared->sink = std::move(sink); }

  // Copies share state: cancelling one cancels all.
  void cancel() { m_shared->cancelled.store(true, std::memory_order_release); }
  bool isCancelled() const { return m_shared->cancelled.load(std::memory_order_acquire); }

  void setProgress(double fraction, const std::string& phase) {
    std::lock_guard<std::mutex> lock(m_shared->mutex);
    if (fraction < m_shared->progress) fraction = m_shared->progress;
    if (fraction > 1.0) fraction = 1.0;
    m_shared->progress = fraction;
    if (m_shared->sink) m_shared->sink(fraction, phase);
  }
  double progress() const {
    std::lock_guard<std::mutex> lock(m_shared->mutex);
    return m_shared->progress;
  }

 private:
  struct Shared {
    std::atomic<bool> cancelled{false};
    mutable std::mutex mutex;
    double progress = 0.0;
    ProgressSink sink;
  };
  std::shared_ptr<Shared> m_shared;
};

}  // namespace multidir::core

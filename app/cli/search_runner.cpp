#include "search_runner.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <future>
#include <mutex>

#include "number_text.h"

namespace multidir::cli {
namespace {

namespace core = multidir::core;

volatile std::sig_atomic_t gInterrupted = 0;

extern "C" void onInterrupt(int) { gInterrupted = 1; }

// Installs the Ctrl-C handler for its lifetime. SA_RESETHAND restores the default action once the handler
// has run, so a second Ctrl-C ends the program even if the search were slow to notice the first.
class InterruptGuard {
 public:
  InterruptGuard() {
    gInterrupted = 0;
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    m_installed = sigaction(SIGINT, &action, &m_previous) == 0;
  }
  ~InterruptGuard() {
    if (m_installed) sigaction(SIGINT, &m_previous, nullptr);
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  struct sigaction m_previous {};
  bool m_installed = false;
};

// The latest report of the search, handed from the search's threads to the drawing thread.
class LatestProgress {
 public:
  void store(const core::SearchProgress& p) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_latest = p;
    if (p.axisCount > 0) {
      // Each axis reports its own search once it ends: the line shows the best and the total over axes.
      m_bestAxisJg = m_axesFinished == 0 ? p.bestJgMm2 : std::min(m_bestAxisJg, p.bestJgMm2);
      m_axisCandidates += p.candidatesScored;
      ++m_axesFinished;
      m_latest.bestJgMm2 = m_bestAxisJg;
      m_latest.candidatesScored = m_axisCandidates;
    }
    ++m_version;
  }
  // The line to draw; the search reports only when a level (or an axis) ends, so before the first report
  // the line says it is preparing (candidate planes, greedy seeds of the beams).
  std::string text() {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_version == 0) return "preparing the search";
    return progressText(m_latest, m_axesFinished);
  }

 private:
  std::mutex m_mutex;
  core::SearchProgress m_latest;
  int m_axesFinished = 0;
  double m_bestAxisJg = 0.0;
  long long m_axisCandidates = 0;
  long long m_version = 0;
};

}  // namespace

std::string progressText(const core::SearchProgress& p, int axesFinished) {
  char jg[64];
  std::snprintf(jg, sizeof jg, "%.2f", p.bestJgMm2);
  if (p.axisCount > 0)
    return "axis " + std::to_string(axesFinished) + "/" + std::to_string(p.axisCount) + " | best J_G " + jg +
           " mm^2 | " + withThousands(p.candidatesScored) + " candidates";
  return "level " + std::to_string(p.level) + " | beams " + std::to_string(p.beamsAlive) + " | best J_G " + jg +
         " mm^2 | " + withThousands(p.candidatesScored) + " candidates";
}

SearchOutcome runInterruptibleSearch(const SearchCall& search, const std::string& startLine, bool progressLine,
                                     std::ostream& err) {
  InterruptGuard guard;
  err << startLine << std::endl;
  core::JobContext job;
  LatestProgress latest;
  const core::SearchProgressSink sink = [&latest](const core::SearchProgress& p) { latest.store(p); };
  std::future<core::Result<core::Decomposition>> running =
      std::async(std::launch::async, [&search, &job, &sink] { return search(job, sink); });

  bool interrupted = false;
  bool drawn = false;
  const auto start = std::chrono::steady_clock::now();
  while (running.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
    if (gInterrupted && !interrupted) {
      interrupted = true;
      job.cancel();
      if (drawn) err << "\r\033[K";
      err << "multidir decompose: interrupted; stopping the search and keeping the best plan found so far "
             "(Ctrl-C again quits without saving)"
          << std::endl;
      drawn = false;
    }
    if (!progressLine || interrupted) continue;
    char elapsed[32];
    std::snprintf(elapsed, sizeof elapsed, " | %.1f s",
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    err << "\r\033[K" << latest.text() << elapsed << std::flush;
    drawn = true;
  }
  if (drawn) err << "\r\033[K" << std::flush;
  return SearchOutcome{running.get(), interrupted};
}

}  // namespace multidir::cli

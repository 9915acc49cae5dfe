#include "multidir/slicing/side_by_side.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "multidir/slicing/child_process.h"

namespace multidir::slicing {

using core::Error;
using core::ErrorCode;

core::Status runSideBySide(const SlicerEngine& engine, std::vector<SliceTask>& tasks, std::size_t stepCount,
                           double shares, core::JobContext& context) {
  const std::vector<int> cpus = usableCpus();
  const std::size_t workers = std::max<std::size_t>(1, std::min(tasks.size(), cpus.size()));
  core::JobContext stop;  // the workers' own: cancelled on the caller's cancel or a failure
  std::vector<std::atomic<double>> fractions(tasks.size());
  std::vector<std::atomic<int>> states(tasks.size());  // 0 waiting, 1 running, 2 done
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    fractions[i] = 0.0;
    states[i] = 0;
  }
  std::vector<std::optional<Error>> errors(tasks.size());
  // The order the workers take the tasks in: the comparison first (the whole model, the longest run), then the
  // steps. A one-thread slicer cannot share its CPU with the others once they are done, so the longest run
  // started last would leave the other CPUs idle while it ends alone.
  std::vector<std::size_t> startOrder;
  for (std::size_t i = stepCount; i < tasks.size(); ++i) startOrder.push_back(i);
  for (std::size_t i = 0; i < std::min(stepCount, tasks.size()); ++i) startOrder.push_back(i);
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> finished{0};
  std::vector<std::thread> threads;
  for (std::size_t w = 0; w < workers; ++w)
    threads.emplace_back([&, cpu = cpus[w % cpus.size()]] {
      for (std::size_t taken = next++; taken < tasks.size(); taken = next++) {
        const std::size_t i = startOrder[taken];
        if (stop.isCancelled()) {
          ++finished;
          continue;
        }
        states[i] = 1;
        SliceRequest request = tasks[i].request;
        request.progress = [&fractions, i](double f) { fractions[i] = f; };
        request.cpu = cpu;
        core::Result<SliceRun> run = engine.slice(request, stop);
        if (run) {
          tasks[i].run = std::move(run).value();
        } else {
          errors[i] = run.error();
          stop.cancel();
        }
        fractions[i] = 1.0;
        states[i] = 2;
        ++finished;
      }
    });
  while (finished.load() < tasks.size()) {
    if (context.isCancelled()) stop.cancel();
    double done = 0.0;
    double comparison = 0.0;
    std::string running;
    int doneSteps = 0;
    for (std::size_t i = 0; i < tasks.size(); ++i) {
      (i < stepCount ? done : comparison) += fractions[i];
      if (i < stepCount && states[i] == 2) ++doneSteps;
      if (states[i] != 1) continue;
      char percent[16];
      std::snprintf(percent, sizeof percent, " (%d %%)", static_cast<int>(fractions[i] * 100.0));
      running += std::string(running.empty() ? "" : ", ") +
                 (i < stepCount ? "step " + std::to_string(i + 1) : std::string("the comparison")) + percent;
    }
    // The comparison's share counts once every step is done, so that the steps' shares read as the steps'
    // progress (sliceStageAt: "step k" while k - 1 steps' worth are done).
    if (doneSteps == static_cast<int>(stepCount)) done += comparison;
    if (!stop.isCancelled())
      context.setProgress(done / shares, "slicing " + (running.empty() ? std::string("") : running + "; ") +
                                             std::to_string(doneSteps) + " of " + std::to_string(stepCount) +
                                             " steps done");
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  for (std::thread& t : threads) t.join();
  if (context.isCancelled()) return Error{ErrorCode::Cancelled, "slicing was cancelled", "slicing"};
  for (std::size_t i = 0; i < tasks.size(); ++i)
    if (errors[i] && errors[i]->code != ErrorCode::Cancelled) return *errors[i];
  for (std::size_t i = 0; i < tasks.size(); ++i)
    if (errors[i]) return *errors[i];
  return core::Done{};
}

}  // namespace multidir::slicing

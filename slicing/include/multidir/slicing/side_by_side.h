#pragma once
// Slicer runs side by side, each on a CPU of its own. PrusaSlicer spreads its work over as many threads as
// the CPUs it may use (TBB), and the order in which they finish changes its G-code from run to run (docs/
// slicing.md, "The same G-code on every run"); confined to one CPU it gives the same G-code for the same
// input every time. So each run is pinned to one of the CPUs the caller may use, and the runs go side by side,
// one per such CPU, so that a job's slicing takes no longer than with the slicer's own threads.
#include <cstddef>
#include <optional>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/common/result.h"
#include "multidir/slicing/slicer_engine.h"

namespace multidir::slicing {

// One slicing run and, once it ran, what it gave.
struct SliceTask {
  SliceRequest request;  // its cpu is set by runSideBySide
  std::optional<SliceRun> run;
};

// Runs the tasks side by side, one slicer per CPU the calling thread may use (usableCpus(), at most one per
// task), each pinned to its worker's CPU (SliceRequest::cpu); their results in their slots, in the tasks'
// order whatever order they finish in. A thread allowed a single CPU runs them one after the other on it. The
// comparison (tasks from stepCount on: the whole model, the longest) starts first, then the steps in order, so
// that no long run is left to end alone on one CPU while the others idle.
// Progress: tasks [0, stepCount) are the steps, a further one the comparison; each reports its own fraction
// (the slicer's own stages), the job's progress is the steps' sum over `shares`, plus the comparison's once
// every step is done. The caller's cancel reaches every running slicer within about 50 ms (each polls the
// workers' context, which this thread cancels); the first failure cancels the others and is returned (a
// cancel, when the caller cancelled).
core::Status runSideBySide(const SlicerEngine& engine, std::vector<SliceTask>& tasks, std::size_t stepCount,
                           double shares, core::JobContext& context);

}  // namespace multidir::slicing

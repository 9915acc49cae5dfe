// Preloaded into PrusaSlicer (LD_PRELOAD, by PrusaSlicerEngine) so that it slices on one thread: then the same
// mesh and settings give the same G-code on every run (docs/slicing.md, "The same G-code on every run").
// PrusaSlicer 2.5 has no option for its thread count; its TBB work done by several threads ends in an order
// that changes from run to run, and TBB's workers still take turns on a process confined to one CPU. A
// global_control caps the whole process' TBB parallelism, PrusaSlicer's own global_control included (TBB
// keeps the smallest of them).
#include <sched.h>

#include <memory>
#include <oneapi/tbb/global_control.h>

namespace {

// Only in a process confined to one CPU (PrusaSlicerEngine pins it before it starts): there TBB's arenas have
// one slot, so PrusaSlicer's start-up barrier over its pool's threads (it waits until as many threads as the
// arena's slots run at once) waits for the main thread alone. Capped in a process allowed more CPUs, that
// barrier would wait forever for threads the cap never lets come.
std::unique_ptr<oneapi::tbb::global_control> oneThreadWhenOnOneCpu() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (::sched_getaffinity(0, sizeof mask, &mask) != 0 || CPU_COUNT(&mask) != 1) return nullptr;
  return std::make_unique<oneapi::tbb::global_control>(oneapi::tbb::global_control::max_allowed_parallelism, 1);
}

// Constructed when the library is loaded, before PrusaSlicer's main; kept until the process ends.
const std::unique_ptr<oneapi::tbb::global_control> oneThread = oneThreadWhenOnOneCpu();

}  // namespace

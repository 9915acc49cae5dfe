#pragma once
// A step no single orientation can print split into runs, each on its own rotation about the nozzle axis and
// arm configuration, re-oriented only at travel moves (docs/robot-cell.md, "Re-orientation within a step").
#include <optional>
#include <vector>

#include "step_run.h"

namespace multidir::robot::detail {

// Moves [first, end) printed on one orientation. A run after the first starts with a re-orientation in place of
// its first move (a travel): the part lifted off the nozzle on the run before, one joint move to the new
// orientation above the travel's end, and down there.
struct PlannedRun {
  Orientation orientation;
  std::size_t first = 0;
  std::size_t end = 0;
};

struct RunPlan {
  std::vector<PlannedRun> runs;       // covering every move, in order (not to be used when refused)
  std::optional<RunFailure> failure;  // refused: `wholeStep` (below), saying where no run got further
};

// The fewest runs, greedily: each run, from where the last one ended, on the orientation that gets furthest (to
// the last travel move before its first failure whose lift off the nozzle is clear, or to the step's end); of
// those that get equally far, the one today's choice (scoreOrientations over the run's own moves) ranks first.
// `wholeStep` is the failure of the step's own choice over all its moves: the refusal (as without splitting) when
// from some travel move on no run gets to a later one.
RunPlan planRuns(const StepPath& path, const RunFailure& wholeStep, const core::JobContext& context);

}  // namespace multidir::robot::detail

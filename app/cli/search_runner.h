#pragma once
// Runs a decomposition search on a worker thread while the calling thread watches for Ctrl-C and, on a
// terminal, redraws one progress line. The first Ctrl-C cancels the search through JobContext::cancel()
// (the search then returns its best plan so far); a second one ends the program at once.
#include <functional>
#include <ostream>
#include <string>

#include "multidir/core/common/job_context.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/core/search/search_options.h"

namespace multidir::cli {

using SearchCall =
    std::function<core::Result<core::Decomposition>(core::JobContext& job, const core::SearchProgressSink& progress)>;

struct SearchOutcome {
  core::Result<core::Decomposition> result;
  bool interrupted = false;  // Ctrl-C was pressed
};

// `startLine` is written to `err` once Ctrl-C is handled, just before the search starts. `progressLine`:
// redraw a status line on `err` (only when it is a terminal). Exceptions of `search` are rethrown on the
// calling thread.
SearchOutcome runInterruptibleSearch(const SearchCall& search, const std::string& startLine, bool progressLine,
                                     std::ostream& err);

// One status line for a progress report: "level 3 | beams 10 | best J_G 12.5 mm^2 | 104,250 candidates".
std::string progressText(const core::SearchProgress& progress, int axesFinished);

}  // namespace multidir::cli

#pragma once
// The paper's comparison (Table "Computational Statistic"): support needed to print a model along one fixed
// direction against the multi-directional plan, with the same support generator.
#include <string>

#include "multidir/core/search/decompose.h"
#include "multidir/core/supports/projected_supports.h"

namespace multidir::core {

struct SupportReport {
  std::size_t triangles = 0;
  double searchSeconds = 0.0;
  int regions = 0;                    // parts of the multi-directional plan
  double jgBeforeMm2 = 0.0;           // risky area printing the whole model along up
  double jgAfterMm2 = 0.0;            // the plan's J_G
  double fixedVolumeMm3 = 0.0;        // supports printing the whole model along up
  double fixedContactAreaMm2 = 0.0;
  double multiVolumeMm3 = 0.0;        // projected supports of the plan
  double multiContactAreaMm2 = 0.0;
  SupportStatistics fixedStatistics;
  SupportStatistics multiStatistics;
  double supportSeconds = 0.0;        // both generations together
  bool cancelled = false;             // the search was cancelled: the plan is the best found until then
};

// Decomposes `model` for `machine` (see decompose), then generates supports for the plan and for the whole
// model printed along machine.up. Progress is the search's (supports take a fraction of its time). Errors: those of decompose
// and generateSupports; Cancelled when cancelled during support generation.
Result<SupportReport> supportReport(const TriangleMesh& model, const MachineSpec& machine,
                                    const SearchOptions& searchOptions, const SupportOptions& supportOptions,
                                    JobContext& job);

}  // namespace multidir::core

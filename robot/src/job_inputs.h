#pragma once
// A sliced job read and laid out as the step converter's inputs: shared by planRobotJob (the programs) and
// robotJobMotion (the studio's view of the same motion), so both convert the very same steps.
#include <filesystem>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/robot/cell.h"
#include "step_converter.h"

namespace multidir::robot::detail {

struct JobInputs {
  std::vector<StepInput> steps;
  // Each step's region and supports in the platform frame (what the arm carries), in step order.
  std::vector<core::TriangleMesh> regions;
  std::vector<core::TriangleMesh> supports;
};

// Errors: those of reading the job (FileNotFound, MalformedFile), InvalidParameter for a job sliced for a
// printer with platform axes in its firmware.
core::Result<JobInputs> readJobInputs(const std::filesystem::path& jobDirectory, const Cell& cell);

}  // namespace multidir::robot::detail

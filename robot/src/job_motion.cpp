// The programs' motion as poses: the job read and converted exactly as planRobotJob does (job_inputs.h,
// step_converter.h), the converter asked to keep each move's pose.
#include "multidir/robot/job_motion.h"

#include "job_inputs.h"
#include "step_converter.h"

namespace multidir::robot {

Eigen::Isometry3d platformPoseAt(const StepMotion& step, const MotionSample& sample) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = step.platformRotations.empty() ? Eigen::Matrix3d::Identity()
                                                 : step.platformRotations[static_cast<std::size_t>(sample.run)];
  pose.translation() = sample.platformMm;
  return pose;
}

core::Result<std::vector<StepMotion>> robotJobMotion(const std::filesystem::path& jobDirectory, const Cell& cell,
                                                     const RobotProgramOptions& options, core::JobContext context) {
  auto inputs = detail::readJobInputs(jobDirectory, cell);
  if (!inputs) return inputs.error();
  std::vector<StepMotion> motion;
  const std::size_t stepCount = inputs->steps.size();
  for (std::size_t k = 0; k < stepCount; ++k) {
    detail::StepInput& input = inputs->steps[k];
    context.setProgress(static_cast<double>(k) / static_cast<double>(stepCount), "step " + std::to_string(input.step));
    input.recordMotion = true;
    detail::StepOutput converted = detail::convertStep(input, cell, options, context);
    if (context.isCancelled()) return core::Error{core::ErrorCode::Cancelled, "cancelled", jobDirectory.string()};
    StepMotion step;
    step.step = input.step;
    step.gcodeFile = input.gcodeFile;
    step.platformToFile = input.platformToFile;
    step.platformRotations = std::move(converted.platformRotations);
    step.region = std::move(inputs->regions[k]);
    step.supports = std::move(inputs->supports[k]);
    step.samples = std::move(converted.motion);
    if (!converted.refusals.empty())
      step.warning = MotionWarning{input.step, converted.refusalLine, converted.refusals.front()};
    motion.push_back(std::move(step));
  }
  context.setProgress(1.0, "done");
  return motion;
}

}  // namespace multidir::robot

// The pose convention on a firmware axis (docs/hardware.md, "Pose convention"), checked by replaying the
// stitched program: the firmware turns the platform about the printer's X by the A the program commands
// (positive A lifts the top towards +Y), and while each step prints, that turn must point the step's printing
// direction straight up and equal the frame the step was sliced in.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>

#include "multidir/slicing/gcode_program.h"
#include "multidir/slicing/slice_job.h"
#include "slicing_fixtures.h"
#include "support/test_models.h"

using namespace multidir;
using namespace multidir::slicing;
using core::Vec3;

namespace {

// The firmware's rotary axis as docs/slicing.md describes it, written out here: a turn about +X by -A.
Eigen::Matrix3d firmwareAxisTurn(double aDegrees) {
  return Eigen::AngleAxisd(-aDegrees * M_PI / 180.0, Vec3::UnitX()).toRotationMatrix();
}

}  // namespace

TEST(PoseConvention, FirmwareAxisPointsEveryKittenStepsPrintingDirectionUpWhileItPrints) {
  core::MachineSpec machine;
  machine.kind = core::MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitY();
  machine.rotationAxis = Vec3::UnitX();
  const core::LoadedPlan plan = test::plannedInMemory(test::loadSharedModel("kitten.off"), machine, "kitten", 0.4);
  const core::PrintJob job = test::machineJob(plan);
  ASSERT_GE(job.steps.size(), 2u);
  core::Result<PrinterProfile> profile = loadPrinterProfile("klipper-rotary");
  ASSERT_TRUE(profile.ok()) << profile.error().describe();
  SliceJobOptions options;
  options.settings = test::coarseSettings(0.3);
  options.fixedDirection = false;
  const std::string dir = test::scratchDirectory("pose_convention.firmware_axis");
  core::JobContext context;
  const core::Result<SlicedJob> sliced = sliceJob(job, *profile, options, dir, context);
  ASSERT_TRUE(sliced.ok()) << sliced.error().describe();
  ASSERT_EQ(sliced->stitchedFile, "job.gcode");

  const core::Result<GcodeProgram> program =
      parseGcode(test::readFile(dir + "/job.gcode"), profile->rotaryAxis, "job.gcode");
  ASSERT_TRUE(program.ok()) << program.error().describe();
  // The A axis' position at every extrusion of each step, as the program leaves it.
  std::map<int, std::vector<double>> anglesWhilePrinting;
  for (const GcodeMove& move : program->moves)
    if (move.extrudes() && move.step >= 1 && !move.inTransition) anglesWhilePrinting[move.step].push_back(move.rotaryToDegrees);

  const Eigen::Matrix3d frame = job.steps.front().modelToFile.linear();  // step 1 stands at rest
  double largestTurn = 0.0;
  for (const core::PrintJobStep& step : job.steps) {
    const std::vector<double>& angles = anglesWhilePrinting[step.index];
    ASSERT_FALSE(angles.empty()) << "step " << step.index << " extrudes nothing in job.gcode";
    for (double a : angles) ASSERT_EQ(a, angles.front()) << "the platform turned while step " << step.index << " printed";
    const Eigen::Matrix3d turn = firmwareAxisTurn(angles.front());
    // The program writes A with three decimals; the plan's angles are whole stepper steps.
    EXPECT_LT((turn * frame * step.printingDirection - Vec3::UnitZ()).norm(), 1e-9)
        << "step " << step.index << " at A " << angles.front();
    EXPECT_LT((turn * frame - step.modelToFile.linear()).norm(), 1e-9) << "step " << step.index;
    largestTurn = std::max(largestTurn, std::abs(angles.front()));
  }
  EXPECT_GT(largestTurn, 10.0) << "the kitten's plan should turn the platform at least once";
}

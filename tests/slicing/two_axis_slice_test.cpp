// A printer with two firmware axes (multidir.platform = firmware-2axis) has its profile and angles but not yet
// the program that turns the axes between steps: a multi-step job is refused before anything is sliced, rather
// than written as step programs nothing would turn the platform between.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/slice_job.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir;
using namespace multidir::slicing;

TEST(SliceJob, AMultiStepJobForTwoFirmwareAxesIsRefusedBeforeTheSlicerRuns) {
  const core::Result<PrinterProfile> profile = loadPrinterProfile("open5x-rrf");
  ASSERT_TRUE(profile.ok()) << profile.error().describe();
  core::PrintJob job;
  job.machine.kind = core::MachineKind::TiltRotate;
  for (int k = 0; k < 2; ++k) {
    core::PrintJobStep step;
    step.region = test::makeBox(core::Vec3(-5, -5, 10.0 * k), core::Vec3(5, 5, 10.0 * (k + 1)));
    step.regionFile = "step-0" + std::to_string(k + 1) + "-region.stl";
    job.steps.push_back(step);
  }
  SliceJobOptions options;
  options.slicerExecutable = "/nonexistent/prusa-slicer";  // reached only if the refusal were missing
  options.fixedDirection = false;
  const std::string dir = test::scratchDirectory("two_axis_slice.refused") + "/out";
  core::JobContext context;
  const core::Result<SlicedJob> sliced = sliceJob(job, *profile, options, dir, context);
  ASSERT_FALSE(sliced.ok());
  EXPECT_EQ(sliced.error().code, core::ErrorCode::InvalidParameter) << sliced.error().describe();
  EXPECT_NE(sliced.error().message.find("firmware-2axis"), std::string::npos) << sliced.error().message;
  EXPECT_NE(sliced.error().message.find("2 steps"), std::string::npos) << sliced.error().message;
  EXPECT_FALSE(std::filesystem::exists(dir + "/step-01.gcode"));
}

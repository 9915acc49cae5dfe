// Runs `multidir export` on a plan of the kitten written by `multidir decompose`: the table of steps, the files
// it writes, print-job.json, and its errors and exit codes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/plan/plan_file.h"
#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

namespace fs = std::filesystem;
using multidir::test::CliRun;
using multidir::test::readAll;
using multidir::test::runCli;

// The kitten's plan (beam width 2, about a second), decomposed once per test process: ctest may run these
// tests in parallel, each in its own process and folder.
const std::string& kittenPlan() {
  static const std::string plan = [] {
    const std::string dir = multidir::test::scratchDirectory(
        std::string("CliExport.Plan.") + testing::UnitTest::GetInstance()->current_test_info()->name());
    const CliRun run = runCli(
        "decompose '" + multidir::test::sharedModelPath("kitten.off") + "' --up y --beam-width 2 -o '" + dir + "/plan'",
        dir);
    if (run.exitCode != 0) throw std::runtime_error("decompose failed: " + run.err);
    return dir + "/plan";
  }();
  return plan;
}

std::string quoted(const std::string& path) { return "'" + path + "'"; }

}  // namespace

TEST(CliExport, WritesOneFilePerStepAndTheJobDescription) {
  const std::string dir = multidir::test::scratchDirectory("CliExport.Default");
  const CliRun run = runCli("export " + quoted(kittenPlan()) + " -o " + quoted(dir + "/job"), dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto plan = multidir::core::loadPlan(kittenPlan());
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  const std::size_t regions = plan->decomposition.regions.size();

  EXPECT_NE(run.out.find("Print job steps (" + std::to_string(regions) + " regions; 5dof, machine frame)"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("machine angles (degrees)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("    1  step-01-region.stl"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("tilt   0.0  azimuth"), std::string::npos) << "step 1 is printed at rest\n" << run.out;
  EXPECT_NE(
      run.out.find("Print job saved   " + dir + "/job/print-job.json, " + std::to_string(regions) + " region files"),
      std::string::npos)
      << run.out;

  const nlohmann::json job = nlohmann::json::parse(readAll(dir + "/job/print-job.json"));
  EXPECT_EQ(job["schema"], "multidir-print-job");
  EXPECT_EQ(job["model"]["checksum"], plan->metadata.modelChecksum);
  ASSERT_EQ(job["steps"].size(), regions);
  for (std::size_t i = 0; i < regions; ++i) {
    const nlohmann::json& files = job["steps"][i]["files"];
    EXPECT_TRUE(fs::exists(dir + "/job/" + files["region"].get<std::string>())) << files;
    EXPECT_EQ(files["supports"].is_null(), plan->supports[i].empty()) << "step " << i + 1;
    if (!files["supports"].is_null()) {
      EXPECT_TRUE(fs::exists(dir + "/job/" + files["supports"].get<std::string>())) << files;
    }
  }
}

TEST(CliExport, ModelFrameTextFormatWithoutSupports) {
  const std::string dir = multidir::test::scratchDirectory("CliExport.ModelOff");
  const CliRun run = runCli(
      "export " + quoted(kittenPlan()) + " -o " + quoted(dir + "/job") + " --frame model --format off --no-supports",
      dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("model frame"), std::string::npos) << run.out;
  const auto plan = multidir::core::loadPlan(kittenPlan());
  ASSERT_TRUE(plan.ok());
  for (std::size_t i = 0; i < plan->decomposition.regions.size(); ++i) {
    const std::string stem = dir + "/job/step-0" + std::to_string(i + 1);
    EXPECT_FALSE(fs::exists(stem + "-supports.off"));
    multidir::core::LoadOptions exact;
    exact.weldToleranceMm = 0.0;
    exact.degenerateAreaMm2 = 0.0;
    const auto region = multidir::core::loadMesh(stem + "-region.off", exact);
    ASSERT_TRUE(region.ok()) << region.error().describe();
    EXPECT_NEAR(multidir::core::signedVolume(region->mesh),
                multidir::core::signedVolume(plan->decomposition.regions[i].mesh),
                1e-6 * plan->decomposition.regions[i].volumeMm3);
  }
}

TEST(CliExport, HelpListsEveryOption) {
  const std::string dir = multidir::test::scratchDirectory("CliExport.Help");
  for (const std::string& arguments : {std::string("export --help"), std::string("help export")}) {
    const CliRun run = runCli(arguments, dir);
    EXPECT_EQ(run.exitCode, 0) << arguments;
    for (const char* option : {"PLAN_DIR -o OUTDIR", "--format", "--frame", "--no-supports", "Exit codes"})
      EXPECT_NE(run.out.find(option), std::string::npos) << arguments << ": " << option;
  }
}

TEST(CliExport, MissingPlanFolderExitsWithOneNamingIt) {
  const std::string dir = multidir::test::scratchDirectory("CliExport.Missing");
  const CliRun run = runCli("export " + quoted(dir + "/no-such-plan") + " -o " + quoted(dir + "/job"), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find(dir + "/no-such-plan"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir + "/job"));
}

TEST(CliExport, FolderWithoutPlanExitsWithOne) {
  const std::string dir = multidir::test::scratchDirectory("CliExport.NotAPlan");
  const CliRun run = runCli("export " + quoted(dir) + " -o " + quoted(dir + "/job"), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("plan.json"), std::string::npos) << run.err;
}

TEST(CliExport, UsageErrorsExitWithTwoBeforeThePlanIsRead) {
  const std::string dir = multidir::test::scratchDirectory("CliExport.Usage");
  // The plan folder does not exist: a usage error is reported first, without reading it.
  const std::string plan = quoted(dir + "/plan");
  const CliRun format = runCli("export " + plan + " -o job --format 3mf", dir);
  EXPECT_EQ(format.exitCode, 2);
  EXPECT_NE(format.err.find("--format: '3mf' is not a mesh format"), std::string::npos) << format.err;
  const CliRun frame = runCli("export " + plan + " -o job --frame printer", dir);
  EXPECT_EQ(frame.exitCode, 2);
  EXPECT_NE(frame.err.find("--frame: 'printer' is not a frame"), std::string::npos) << frame.err;
  const CliRun noOut = runCli("export " + plan, dir);
  EXPECT_EQ(noOut.exitCode, 2);
  EXPECT_NE(noOut.err.find("-o OUTDIR is missing"), std::string::npos) << noOut.err;
  EXPECT_EQ(runCli("export -o job", dir).exitCode, 2);
  EXPECT_EQ(runCli("export a b -o job", dir).exitCode, 2);
  EXPECT_EQ(runCli("export " + plan + " -o job --colour red", dir).exitCode, 2);
}

TEST(CliExport, UnwritableOutputExitsWithOne) {
  const std::string dir = multidir::test::scratchDirectory("CliExport.Unwritable");
  std::ofstream(dir + "/taken") << "a file, not a folder";
  const CliRun run = runCli("export " + quoted(kittenPlan()) + " -o " + quoted(dir + "/taken"), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("cannot write the print job"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("taken"), std::string::npos) << run.err;
}

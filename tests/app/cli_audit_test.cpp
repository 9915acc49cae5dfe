// Runs `multidir audit` on a job sliced by `multidir slice`: the table per program, the JSON, the exit codes
// and the errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::readAll;
using multidir::test::runCli;

std::string quoted(const std::string& path) { return "'" + path + "'"; }

// The kitten on a rotary platform (greedy search), sliced coarsely for the Klipper printer whose firmware turns
// the platform (so the job has job.gcode), once per test process.
const std::string& slicedKitten(const std::string& dir) {
  static const std::string job = [&dir] {
    const CliRun plan = runCli("decompose " + quoted(multidir::test::sharedModelPath("kitten.off")) +
                                   " --up y --machine 4dof --scheme greedy -o " + quoted(dir + "/plan"),
                               dir);
    if (plan.exitCode != 0) throw std::runtime_error("decompose failed: " + plan.err);
    const CliRun slice = runCli("slice " + quoted(dir + "/plan") +
                                    " --printer klipper-rotary --no-comparison --set 'layer_height=0.3 "
                                    "first_layer_height=0.3 perimeters=1 top_solid_layers=1 bottom_solid_layers=1 "
                                    "fill_density=0%' -o " +
                                    quoted(dir + "/job"),
                                dir);
    if (slice.exitCode != 0) throw std::runtime_error("slice failed: " + slice.err);
    return dir + "/job";
  }();
  return job;
}

}  // namespace

TEST(CliAudit, HelpNamesTheFiveChecks) {
  const std::string dir = multidir::test::scratchDirectory("CliAudit.Help");
  for (const std::string command : {"audit --help", "help audit"}) {
    const CliRun run = runCli(command, dir);
    EXPECT_EQ(run.exitCode, 0) << command;
    for (const char* check : {"(a)", "(b)", "(c)", "(d)", "(e)", "--json", "--strict"})
      EXPECT_NE(run.out.find(check), std::string::npos) << command << " lacks " << check;
  }
}

TEST(CliAudit, AFolderWithoutAJobIsABadInputNamingPrintJobJson) {
  const std::string dir = multidir::test::scratchDirectory("CliAudit.NoJob");
  const CliRun run = runCli("audit " + quoted(dir), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("print-job.json"), std::string::npos) << run.err;
}

TEST(CliAudit, APrintableAngleOutOfRangeIsAUsageError) {
  const std::string dir = multidir::test::scratchDirectory("CliAudit.Alpha");
  const CliRun run = runCli("audit job --alpha 95", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("--alpha"), std::string::npos) << run.err;
}

TEST(CliAudit, AStitchedJobIsAuditedAsStepProgramsAndAsJobGcodeWithTheSameNumbersInJson) {
  const std::string dir = multidir::test::scratchDirectory("CliAudit.Stitched");
  const std::string job = slicedKitten(dir);
  const CliRun run = runCli("audit " + quoted(job) + " --json " + quoted(dir + "/audit.json"), dir);
  ASSERT_TRUE(run.exitCode == 0 || run.exitCode == 5) << run.err;
  EXPECT_NE(run.out.find("step programs"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("job.gcode (stitched"), std::string::npos) << run.out;
  const nlohmann::json audit = nlohmann::json::parse(readAll(dir + "/audit.json"));
  const nlohmann::json printJob = nlohmann::json::parse(readAll(job + "/print-job.json"));
  EXPECT_EQ(audit["schema"], "multidir-audit");
  EXPECT_EQ(audit["passed"].get<bool>(), run.exitCode == 0);
  EXPECT_EQ(audit["poseMismatches"], 0) << audit["findings"].dump();
  ASSERT_EQ(audit["programs"].size(), 2u);
  const nlohmann::json& parts = audit["programs"][0];
  const nlohmann::json& stitched = audit["programs"][1];
  EXPECT_EQ(stitched["name"], "job.gcode");
  ASSERT_EQ(stitched["steps"].size(), printJob["steps"].size());
  for (std::size_t k = 0; k < stitched["steps"].size(); ++k) {
    // job.gcode holds the step programs' bodies: the same extrusion, in the same places.
    EXPECT_NEAR(stitched["steps"][k]["extrusionMm"].get<double>(), parts["steps"][k]["extrusionMm"].get<double>(),
                1e-6);
    EXPECT_NEAR(stitched["steps"][k]["unsupportedMm"].get<double>(), parts["steps"][k]["unsupportedMm"].get<double>(),
                1e-6);
    EXPECT_EQ(stitched["steps"][k]["outsideMm"].get<double>(), 0.0);
    if (k + 1 < stitched["steps"].size()) {
      // The turn's clearance as measured over the arc: above the part (the slicer planned the same arc).
      EXPECT_GT(stitched["steps"][k]["turnClearanceMm"].get<double>(), 0.0);
    } else {
      EXPECT_TRUE(stitched["steps"][k]["turnClearanceMm"].is_null());
    }
  }
  const bool unsupported = stitched["total"]["unsupportedMm"].get<double>() > 0.0;
  const CliRun strict = runCli("audit " + quoted(job) + " --strict", dir);
  EXPECT_EQ(strict.exitCode, unsupported || run.exitCode == 5 ? 5 : 0) << strict.out;
}

// `multidir report` (the paper's table: support volume fixed against multi-directional) and the supports
// `multidir decompose` saves with its plan.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "multidir/core/plan/plan_file.h"
#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::readAll;
using multidir::test::runCli;

std::string model(const std::string& name) { return "'" + multidir::test::sharedModelPath(name) + "'"; }

bool exists(const std::string& path) { return std::ifstream(path).good(); }

}  // namespace

TEST(CliReport, KittenRowShowsLessSupportForTheMultiDirectionalPlan) {
  const std::string dir = multidir::test::scratchDirectory("CliReport.Kitten");
  const CliRun run = runCli("report " + model("kitten.off") + " --up y --beam-width 2 --json '" + dir + "/report.json'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("support fixed"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("support multi"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("kitten.off            10,000"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("1507.21"), std::string::npos) << "J_G before along +Y\n" << run.out;
  const nlohmann::json rows = nlohmann::json::parse(readAll(dir + "/report.json"));
  ASSERT_EQ(rows.size(), 1u);
  const nlohmann::json& row = rows[0];
  EXPECT_EQ(row["triangles"], 10000);
  EXPECT_GE(row["parts"].get<int>(), 2);
  EXPECT_GT(row["support_volume_fixed"].get<double>(), 0.0);
  EXPECT_LT(row["support_volume_multi"].get<double>(), row["support_volume_fixed"].get<double>());
  EXPECT_LT(row["contact_area_multi"].get<double>(), row["contact_area_fixed"].get<double>());
  EXPECT_EQ(row["fixed"]["projections"], 0) << "one direction has nothing to project across";
}

TEST(CliReport, HelpNamesTheOptions) {
  const std::string dir = multidir::test::scratchDirectory("CliReport.Help");
  const CliRun run = runCli("help report", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("--support-spacing"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("--json"), std::string::npos) << run.out;
  const CliRun usage = runCli("--help", dir);
  EXPECT_NE(usage.out.find("report MODEL..."), std::string::npos) << usage.out;
}

TEST(CliReport, WithoutModelsIsAUsageError) {
  const std::string dir = multidir::test::scratchDirectory("CliReport.NoModel");
  const CliRun run = runCli("report --up y", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("which models?"), std::string::npos) << run.err;
}

TEST(CliReport, MissingModelExitsWithOne) {
  const std::string dir = multidir::test::scratchDirectory("CliReport.Missing");
  const CliRun run = runCli("report '" + dir + "/nothing.off'", dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("nothing.off"), std::string::npos) << run.err;
}

TEST(CliDecomposeSupports, PlanHoldsSupportFilesThatLoadBack) {
  const std::string dir = multidir::test::scratchDirectory("CliDecomposeSupports.Kitten");
  const CliRun run = runCli("decompose " + model("kitten.off") + " --up y --beam-width 2 -o '" + dir + "/plan'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("Supports     "), std::string::npos) << run.out;
  const auto plan = multidir::core::loadPlan(dir + "/plan");
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  ASSERT_EQ(plan->supports.size(), plan->decomposition.regions.size());
  std::size_t struts = 0;
  for (std::size_t r = 0; r < plan->supports.size(); ++r) {
    struts += plan->supports[r].struts.size();
    EXPECT_EQ(exists(dir + "/plan/region-0" + std::to_string(r + 1) + "-supports.stl"), !plan->supports[r].empty());
  }
  EXPECT_GT(struts, 0u);
}

TEST(CliDecomposeSupports, NoSupportsOptionWritesNone) {
  const std::string dir = multidir::test::scratchDirectory("CliDecomposeSupports.None");
  const CliRun run =
      runCli("decompose " + model("kitten.off") + " --up y --beam-width 2 --no-supports -o '" + dir + "/plan'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(run.out.find("Supports     "), std::string::npos) << run.out;
  EXPECT_FALSE(exists(dir + "/plan/region-01-supports.stl"));
}

TEST(CliDecomposeSupports, BadSupportSpacingIsAUsageError) {
  const std::string dir = multidir::test::scratchDirectory("CliDecomposeSupports.Spacing");
  const CliRun run = runCli("decompose " + model("kitten.off") + " --support-spacing 0 -o '" + dir + "/plan'", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("--support-spacing"), std::string::npos) << run.err;
}

TEST(CliReport, JsonReplacesALinkAtItsPathInsteadOfWritingThroughIt) {
  const std::string dir = multidir::test::scratchDirectory("CliReport.JsonOverALink");
  std::ofstream(dir + "/victim.txt") << "not MultiDir's\n";
  std::filesystem::create_symlink(dir + "/victim.txt", dir + "/report.json");
  const CliRun run = runCli("report " + model("kitten.off") + " --up y --beam-width 1 --normals 40 --json '" + dir +
                                "/report.json'",
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(readAll(dir + "/victim.txt"), "not MultiDir's\n");
  EXPECT_FALSE(std::filesystem::is_symlink(dir + "/report.json"));
  EXPECT_EQ(nlohmann::json::parse(readAll(dir + "/report.json")).size(), 1u);
}

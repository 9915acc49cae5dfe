// Runs the built `multidir` command line and checks its output, JSON and exit codes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::readAll;
using multidir::test::runCli;

}  // namespace

TEST(CliInfo, KittenAlongYReportsStatisticsChecksAndRiskyArea) {
  const std::string dir = multidir::test::scratchDirectory("CliInfo.Kitten");
  const std::string json = dir + "/kitten.json";
  const CliRun run = runCli("info '" + multidir::test::sharedModelPath("kitten.off") + "' --up y --json '" + json + "'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("triangles    10000"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("genus        1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("closed       yes"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("no defects found"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("risky area"), std::string::npos) << run.out;

  const nlohmann::json doc = nlohmann::json::parse(readAll(json));
  EXPECT_EQ(doc["statistics"]["triangles"], 10000);
  EXPECT_EQ(doc["statistics"]["genus"], 1);
  EXPECT_EQ(doc["statistics"]["closed"], true);
  EXPECT_TRUE(doc["checks"]["defects"].empty());
  EXPECT_EQ(doc["overhang"]["up"], nlohmann::json::array({0.0, 1.0, 0.0}));
  EXPECT_GT(doc["overhang"]["riskyAreaMm2"].get<double>(), 0.0);
  EXPECT_LT(doc["overhang"]["riskyAreaMm2"].get<double>(), doc["statistics"]["areaMm2"].get<double>());
}

TEST(CliInfo, DefectiveModelExitsWithOneAndNamesTheDefect) {
  const std::string dir = multidir::test::scratchDirectory("CliInfo.Defective");
  const CliRun run = runCli("info '" + multidir::test::sharedModelPath("defective/halftunnel-open.off") + "'", dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("halftunnel-open.off: not a solid: 96 open boundary edges"), std::string::npos) << run.err;
}

TEST(CliInfo, MissingModelExitsWithOne) {
  const std::string dir = multidir::test::scratchDirectory("CliInfo.Missing");
  EXPECT_EQ(runCli("info /nonexistent/ghost.stl", dir).exitCode, 1);
}

TEST(CliInfo, UsageErrorsExitWithTwoAndSayWhatIsWrong) {
  const std::string dir = multidir::test::scratchDirectory("CliInfo.Usage");
  const std::string kitten = "'" + multidir::test::sharedModelPath("kitten.off") + "'";
  const CliRun unknownOption = runCli("info " + kitten + " --colour red", dir);
  EXPECT_EQ(unknownOption.exitCode, 2);
  EXPECT_NE(unknownOption.err.find("unknown option '--colour'"), std::string::npos) << unknownOption.err;
  const CliRun badNumber = runCli("info " + kitten + " --alpha steep", dir);
  EXPECT_EQ(badNumber.exitCode, 2);
  EXPECT_NE(badNumber.err.find("--alpha expects a number, got 'steep'"), std::string::npos) << badNumber.err;
  EXPECT_EQ(runCli("info " + kitten + " --alpha 95", dir).exitCode, 2);
  EXPECT_EQ(runCli("info " + kitten + " --up sideways", dir).exitCode, 2);
  EXPECT_EQ(runCli("info " + kitten + " --up", dir).exitCode, 2);
  EXPECT_EQ(runCli("info", dir).exitCode, 2);
  EXPECT_EQ(runCli("frobnicate", dir).exitCode, 2);
  EXPECT_EQ(runCli("", dir).exitCode, 2);
}

TEST(CliInfo, HelpListsEveryCommand) {
  const std::string dir = multidir::test::scratchDirectory("CliInfo.Help");
  const CliRun run = runCli("--help", dir);
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_NE(run.out.find("info MODEL"), std::string::npos);
  EXPECT_NE(run.out.find("decompose MODEL"), std::string::npos);
  EXPECT_NE(run.out.find("export PLAN_DIR -o OUTDIR"), std::string::npos);
  EXPECT_NE(run.out.find("report MODEL"), std::string::npos);
  EXPECT_NE(run.out.find("simulate"), std::string::npos);
  EXPECT_NE(run.out.find("cell check CELL"), std::string::npos);
  EXPECT_NE(run.out.find("cell reach PLAN --cell CELL"), std::string::npos);
  EXPECT_NE(run.out.find("robot-program JOB --cell CELL -o OUT"), std::string::npos);
  const CliRun info = runCli("help info", dir);
  EXPECT_EQ(info.exitCode, 0);
  EXPECT_NE(info.out.find("--alpha DEGREES"), std::string::npos);
}

TEST(CliInfo, JsonReplacesALinkAtItsPathInsteadOfWritingThroughIt) {
  // A link planted where the JSON goes: the file it points to stays as it was.
  const std::string dir = multidir::test::scratchDirectory("CliInfo.JsonOverALink");
  std::ofstream(dir + "/victim.txt") << "not MultiDir's\n";
  std::filesystem::create_symlink(dir + "/victim.txt", dir + "/kitten.json");
  const CliRun run =
      runCli("info '" + multidir::test::sharedModelPath("kitten.off") + "' --up y --json '" + dir + "/kitten.json'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(readAll(dir + "/victim.txt"), "not MultiDir's\n");
  EXPECT_FALSE(std::filesystem::is_symlink(dir + "/kitten.json"));
  EXPECT_TRUE(nlohmann::json::parse(readAll(dir + "/kitten.json")).contains("overhang"));
}

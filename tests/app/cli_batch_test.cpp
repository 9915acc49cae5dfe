// `multidir batch`: a folder or list file in, one plan folder per model and one table row per model out,
// shards, resuming, failures recorded (docs/batch.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "multidir/core/plan/plan_file.h"
#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

namespace fs = std::filesystem;
using multidir::test::CliRun;
using multidir::test::readAll;
using multidir::test::runCli;

// A small search keeps each model to a fraction of a second.
const std::string kSmall = " --up y --beam-width 1 --normals 30 --refine 0 --no-supports";

std::string shared(const std::string& name) { return multidir::test::sharedModelPath(name); }

// A folder holding links to the given shared models (the models themselves stay where they are).
std::string folderOf(const std::string& dir, const std::vector<std::string>& names) {
  const fs::path folder = fs::path(dir) / "models";
  fs::create_directories(folder);
  for (const std::string& name : names) fs::create_symlink(shared(name), folder / fs::path(name).filename());
  return folder.string();
}

nlohmann::json jsonTable(const std::string& path) { return nlohmann::json::parse(readAll(path), nullptr, false); }

CliRun batch(const std::string& dir, const std::string& input, const std::string& options) {
  return runCli("batch '" + input + "' -o '" + dir + "/out'" + kSmall + " " + options, dir);
}

}  // namespace

TEST(CliBatch, AFolderGivesEachModelAPlanFolderAndATableRow) {
  const std::string dir = multidir::test::scratchDirectory("CliBatch.Folder");
  const CliRun run = batch(dir, folderOf(dir, {"knight.off", "bumpy.off"}), "--table '" + dir + "/results.json'");
  ASSERT_EQ(run.exitCode, 0) << run.err << run.out;
  const nlohmann::json table = jsonTable(dir + "/results.json");
  ASSERT_EQ(table.size(), 2u) << table.dump();
  EXPECT_NE(table[0]["model"].get<std::string>().find("bumpy.off"), std::string::npos);  // sorted
  EXPECT_NE(table[1]["model"].get<std::string>().find("knight.off"), std::string::npos);
  for (const auto& row : table) {
    const std::string name = fs::path(row["model"].get<std::string>()).filename().string();
    auto plan = multidir::core::loadPlan(dir + "/out/" + name);
    ASSERT_TRUE(plan.ok()) << name << ": " << plan.error().describe();
    EXPECT_EQ(row["status"], "done");
    EXPECT_EQ(row["error"], "");
    EXPECT_EQ(row["regions"].get<std::size_t>(), plan->decomposition.regions.size());
    EXPECT_DOUBLE_EQ(row["jg_after_mm2"].get<double>(), plan->decomposition.jgAfterMm2);
    EXPECT_DOUBLE_EQ(row["jg_before_mm2"].get<double>(), plan->decomposition.jgBeforeMm2);
    EXPECT_GT(row["seconds"].get<double>(), 0.0);
    EXPECT_GT(row["peak_memory_mib"].get<double>(), 0.0);
  }
  EXPECT_EQ(table[1]["faces"], 1000);
}

TEST(CliBatch, ABrokenMeshIsRecordedWithItsErrorAndTheBatchGoesOn) {
  const std::string dir = multidir::test::scratchDirectory("CliBatch.Broken");
  // The broken mesh sorts first: the good one after it must still get its plan.
  const CliRun run = batch(dir, folderOf(dir, {"defective/halftunnel-open.off", "knight.off"}), "");
  EXPECT_EQ(run.exitCode, 1) << run.err << run.out;
  const std::string csv = readAll(dir + "/out/batch-results.csv");
  EXPECT_EQ(csv.rfind("model,status,faces,jg_before_mm2,jg_after_mm2,regions,seconds,peak_memory_mib,error\n", 0), 0u)
      << csv;
  EXPECT_NE(csv.find("halftunnel-open.off,failed,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("96 open boundary edges"), std::string::npos) << csv;
  EXPECT_NE(csv.find("knight.off,done,1000,"), std::string::npos) << csv;
  EXPECT_TRUE(fs::exists(dir + "/out/knight.off/plan.json"));
  EXPECT_FALSE(fs::exists(dir + "/out/halftunnel-open.off/plan.json"));
  EXPECT_NE(run.err.find("1 of 2 models failed"), std::string::npos) << run.err;
}

TEST(CliBatch, ShardITakesTheModelsWhoseSortedIndexIsIModuloN) {
  const std::string dir = multidir::test::scratchDirectory("CliBatch.Shards");
  // A list file, out of order, with a comment and a blank line; paths relative to the list's folder.
  fs::create_directories(dir + "/lists");
  folderOf(dir + "/lists", {"knight.off", "bumpy.off", "screwdriver.off"});
  std::ofstream(dir + "/lists/models.txt") << "# three models\nmodels/screwdriver.off\n\nmodels/knight.off\nmodels/bumpy.off\n";
  const CliRun first = batch(dir, dir + "/lists/models.txt", "--shard 0/2 --table '" + dir + "/shard0.json'");
  const CliRun second = batch(dir, dir + "/lists/models.txt", "--shard 1/2 --table '" + dir + "/shard1.json'");
  ASSERT_EQ(first.exitCode, 0) << first.err;
  ASSERT_EQ(second.exitCode, 0) << second.err;
  const nlohmann::json zero = jsonTable(dir + "/shard0.json");
  const nlohmann::json one = jsonTable(dir + "/shard1.json");
  // Sorted: bumpy (0), knight (1), screwdriver (2).
  ASSERT_EQ(zero.size(), 2u);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NE(zero[0]["model"].get<std::string>().find("bumpy.off"), std::string::npos);
  EXPECT_NE(zero[1]["model"].get<std::string>().find("screwdriver.off"), std::string::npos);
  EXPECT_NE(one[0]["model"].get<std::string>().find("knight.off"), std::string::npos);
  for (const char* name : {"bumpy.off", "knight.off", "screwdriver.off"})
    EXPECT_TRUE(fs::exists(dir + "/out/" + name + "/plan.json")) << name;
}

TEST(CliBatch, AModelWhosePlanFolderIsCompleteIsSkippedOnTheNextRun) {
  const std::string dir = multidir::test::scratchDirectory("CliBatch.Resume");
  const std::string input = folderOf(dir, {"knight.off"});
  ASSERT_EQ(batch(dir, input, "").exitCode, 0);
  const auto written = fs::last_write_time(dir + "/out/knight.off/plan.json");
  const CliRun again = batch(dir, input, "");
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_EQ(fs::last_write_time(dir + "/out/knight.off/plan.json"), written) << "the plan was written again";
  EXPECT_NE(readAll(dir + "/out/batch-results.csv").find("knight.off,done before,1000,"), std::string::npos);
}

TEST(CliBatch, APlanFolderWithoutItsBatchRecordIsRunAgain) {
  // A crash after plan.json but before batch-row.json leaves a folder that does not count as complete.
  const std::string dir = multidir::test::scratchDirectory("CliBatch.Incomplete");
  const std::string input = folderOf(dir, {"knight.off"});
  ASSERT_EQ(batch(dir, input, "").exitCode, 0);
  fs::remove(dir + "/out/knight.off/batch-row.json");
  const CliRun again = batch(dir, input, "");
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(readAll(dir + "/out/batch-results.csv").find("knight.off,done,1000,"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir + "/out/knight.off/batch-row.json"));
}

TEST(CliBatch, IsolateRunsEachModelInAChildProcessWithTheSameResults) {
  const std::string dir = multidir::test::scratchDirectory("CliBatch.Isolate");
  const std::string input = folderOf(dir, {"defective/halftunnel-open.off", "knight.off"});
  const CliRun run = batch(dir, input, "--isolate --table '" + dir + "/isolated.json'");
  EXPECT_EQ(run.exitCode, 1) << run.err;
  const nlohmann::json table = jsonTable(dir + "/isolated.json");
  ASSERT_EQ(table.size(), 2u);
  EXPECT_EQ(table[0]["status"], "failed");
  EXPECT_NE(table[0]["error"].get<std::string>().find("96 open boundary edges"), std::string::npos);
  EXPECT_TRUE(table[0]["faces"].is_null());
  EXPECT_EQ(table[1]["status"], "done");
  EXPECT_GT(table[1]["peak_memory_mib"].get<double>(), 0.0);
  EXPECT_TRUE(multidir::core::loadPlan(dir + "/out/knight.off").ok());
}

TEST(CliBatch, MistakesAreUsageErrorsBeforeAnyModelRuns) {
  const std::string dir = multidir::test::scratchDirectory("CliBatch.Usage");
  const std::string input = folderOf(dir, {"knight.off"});
  for (const std::string& options : {std::string("--shard 2/2"), std::string("--shard 1"), std::string("--shard -1/2"),
                                     std::string("--summary s.json"), std::string("--alpha 95")}) {
    const CliRun run = batch(dir, input, options);
    EXPECT_EQ(run.exitCode, 2) << options << "\n" << run.err;
    EXPECT_FALSE(fs::exists(dir + "/out/knight.off")) << options;
  }
  const CliRun missing = runCli("batch '" + dir + "/nothing' -o '" + dir + "/out'", dir);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("does not exist"), std::string::npos) << missing.err;
}

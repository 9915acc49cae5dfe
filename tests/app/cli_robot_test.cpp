// The robot cell's commands: `multidir cell check`, `multidir robot-program` on a kitten job sliced with the
// cell's profile, `multidir cell reach`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::runCli;

const std::string kShippedCell = std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json";

std::string quoted(const std::string& path) { return "'" + path + "'"; }

// The kitten at half size, 5-DOF greedy, sliced coarse with the cell's profile into `dir`/job.
void sliceKitten(const std::string& dir) {
  const CliRun decomposed = runCli("decompose " + quoted(multidir::test::sharedModelPath("kitten.off")) +
                                       " --up y --machine 5dof --scheme greedy --scale 0.5 -o " + quoted(dir + "/plan"),
                                   dir);
  ASSERT_EQ(decomposed.exitCode, 0) << decomposed.err;
  const CliRun sliced = runCli("slice " + quoted(dir + "/plan") +
                                   " --printer ur5-cell-0.8 --no-comparison --set 'layer_height=0.6 "
                                   "first_layer_height=0.6 perimeters=1 top_solid_layers=1 bottom_solid_layers=1 "
                                   "fill_density=0%' -o " + quoted(dir + "/job"),
                               dir);
  ASSERT_EQ(sliced.exitCode, 0) << sliced.err;
}

TEST(CliRobot, CellCheckFindsThePaperCellSound) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.CellCheckSound");
  const CliRun run = runCli("cell check " + quoted(kShippedCell), dir);
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("sound"), std::string::npos);
  EXPECT_NE(run.out.find("ur5"), std::string::npos);
}

TEST(CliRobot, CellCheckNamesEveryProblemsKey) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.CellCheckProblems");
  std::ifstream in(kShippedCell);
  nlohmann::json cell = nlohmann::json::parse(in);
  cell["nozzleAxis"] = {0, 0.5, 0};
  cell["homeDegrees"][2] = 270;
  std::ofstream(dir + "/cell.json") << cell.dump();
  const CliRun run = runCli("cell check " + quoted(dir + "/cell.json"), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("2 problem(s)"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("nozzleAxis: has length 0.5"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("homeDegrees[2]: is 270.0 deg"), std::string::npos) << run.err;
}

// With the cell's platform as large as the plan's platform region (docs/robot-cell.md, "The platform").
TEST(CliRobot, RobotProgramWritesTheContractsFolder) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.RobotProgramWrites");
  sliceKitten(dir);
  std::ifstream jobIn(dir + "/job/print-job.json");
  const nlohmann::json job = nlohmann::json::parse(jobIn);
  std::ifstream cellIn(kShippedCell);
  nlohmann::json cell = nlohmann::json::parse(cellIn);
  cell["platformRadiusMm"] = job["pivot"]["platformRadiusMm"];
  std::ofstream(dir + "/cell.json") << cell.dump(2);
  const CliRun run = runCli("robot-program " + quoted(dir + "/job") + " --cell " + quoted(dir + "/cell.json") + " -o " +
                                quoted(dir + "/robot"),
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::ifstream robotIn(dir + "/robot/robot-job.json");
  const nlohmann::json robot = nlohmann::json::parse(robotIn);
  EXPECT_EQ(robot["format"], "multidir-robot-job");
  EXPECT_EQ(robot["version"], 1);
  EXPECT_EQ(robot["robot"], "ur5");
  EXPECT_EQ(robot["cell"], "cell.json");
  ASSERT_EQ(robot["steps"].size(), job["steps"].size());
  for (const auto& step : robot["steps"]) {
    for (const char* key : {"step", "program", "seconds", "filamentMm", "moves", "reachMarginMm", "slowestJoint", "slowdowns"})
      EXPECT_TRUE(step.contains(key)) << key;
    EXPECT_TRUE(std::filesystem::exists(dir + "/robot/" + step["program"].get<std::string>()));
  }
  EXPECT_TRUE(std::filesystem::exists(dir + "/robot/cell.json"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/robot/summary.txt"));
  EXPECT_NE(run.out.find("robot time"), std::string::npos);
}

// The paper cell's 30 mm platform swings into the extruder on the kitten's steeply tilted step: refused with the
// step and line, nothing written.
TEST(CliRobot, RobotProgramRefusesAJobTheCellCannotRunNamingStepAndLine) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.RobotProgramRefuses");
  sliceKitten(dir);
  const CliRun run = runCli("robot-program " + quoted(dir + "/job") + " --cell " + quoted(kShippedCell) + " -o " +
                                quoted(dir + "/robot"),
                            dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("the job cannot run on the cell"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(", line "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("the platform would hit the extruder's body"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/robot"));
}

TEST(CliRobot, CellReachReportsTheBestNozzlePositionAndWritesTheMap) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.CellReach");
  const CliRun decomposed = runCli("decompose " + quoted(multidir::test::sharedModelPath("kitten.off")) +
                                       " --up y --machine 5dof --scheme greedy --scale 0.5 -o " + quoted(dir + "/plan"),
                                   dir);
  ASSERT_EQ(decomposed.exitCode, 0) << decomposed.err;
  const CliRun run = runCli("cell reach " + quoted(dir + "/plan") + " --cell " + quoted(kShippedCell) +
                                " --grid 150 -o " + quoted(dir + "/reach.ply"),
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("best position"), std::string::npos);
  EXPECT_NE(run.out.find("100.0 % of the needed poses reachable"), std::string::npos) << run.out;
  std::ifstream ply(dir + "/reach.ply");
  std::string first;
  std::getline(ply, first);
  EXPECT_EQ(first, "ply");
}

}  // namespace

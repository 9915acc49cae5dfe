// `multidir decompose --pose auto`: the chosen pose in plan.json and the summary, usage errors, and the export
// of such a plan along the chosen up.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "multidir/core/plan/plan_file.h"
#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::readAll;
using multidir::test::runCli;

std::string knight() { return "'" + multidir::test::sharedModelPath("knight.off") + "'"; }

// A small search (few normals, one beam, four poses) keeps the run short.
const std::string kSmall = " --up y --beam-width 1 --normals 30 --refine 0 --no-supports --pose auto --poses 4 --pose-searches 2";

struct PoseRun {
  std::string dir;
  CliRun run;
  nlohmann::json summary;
  nlohmann::json plan;
};

const PoseRun& poseRun() {
  static const PoseRun result = [] {
    PoseRun p;
    p.dir = multidir::test::scratchDirectory(std::string("CliPose.") +
                                             testing::UnitTest::GetInstance()->current_test_info()->name());
    p.run = runCli("decompose " + knight() + kSmall + " -o '" + p.dir + "/plan' --summary '" + p.dir + "/summary.json'",
                   p.dir);
    p.summary = nlohmann::json::parse(readAll(p.dir + "/summary.json"), nullptr, false);
    p.plan = nlohmann::json::parse(readAll(p.dir + "/plan/plan.json"), nullptr, false);
    return p;
  }();
  return result;
}

double dot(const nlohmann::json& a, const nlohmann::json& b) {
  return a[0].get<double>() * b[0].get<double>() + a[1].get<double>() * b[1].get<double>() +
         a[2].get<double>() * b[2].get<double>();
}

// How many poses the plan's notes say were ruled out (neither scored nor searched), 0 when none.
std::size_t ruledOutPoses(const nlohmann::json& plan) {
  for (const auto& note : plan["result"]["statistics"]["notes"]) {
    const std::string text = note.get<std::string>();
    if (text.find("neither scored nor searched") != std::string::npos) return std::stoul(text);
  }
  return 0;
}

void expectUsageError(const std::string& arguments, const std::string& message) {
  const std::string dir = multidir::test::scratchDirectory("CliPose.Usage");
  const CliRun run = runCli("decompose " + arguments, dir);
  EXPECT_EQ(run.exitCode, 2) << arguments << "\n" << run.err;
  EXPECT_NE(run.err.find(message), std::string::npos) << arguments << "\n" << run.err;
}

}  // namespace

TEST(CliPose, AutoWritesTheChosenPoseIntoPlanJsonAndSummary) {
  const PoseRun& p = poseRun();
  ASSERT_EQ(p.run.exitCode, 0) << p.run.err;
  ASSERT_TRUE(p.plan.contains("pose")) << "plan.json records the pose";
  ASSERT_TRUE(p.summary.contains("pose"));
  EXPECT_EQ(p.summary["pose_mode"], "auto");
  const nlohmann::json& pose = p.plan["pose"];
  // machine.up is the chosen up; the rotation turns it onto the given up (y).
  EXPECT_NEAR(dot(pose["up"], p.plan["machine"]["up"]), 1.0, 1e-9);
  EXPECT_NEAR(dot(pose["up"], p.summary["pose"]["up"]), 1.0, 1e-9);
  const nlohmann::json& r = pose["rotation"];
  const nlohmann::json turned = {dot(r[0], pose["up"]), dot(r[1], pose["up"]), dot(r[2], pose["up"])};
  EXPECT_NEAR(turned[1].get<double>(), 1.0, 1e-9);
  // Four poses: the other three are runners-up unless ruled out (no plan of theirs could beat the given up's, the
  // notes say how many; the knight's two largest patches are); the given up among the fully searched ones, none
  // better than the choice.
  const std::size_t ruledOut = ruledOutPoses(p.plan);
  EXPECT_GT(ruledOut, 0u);
  ASSERT_EQ(pose["runnersUp"].size(), 3u - ruledOut);
  EXPECT_EQ(p.summary["pose"]["runners_up"].size(), 3u - ruledOut);
  const double chosen = p.plan["result"]["jgAfterMm2"].get<double>();
  bool givenSearched = pose["source"] == "given";
  for (const auto& t : pose["runnersUp"]) {
    if (t["searched"].get<bool>()) {
      EXPECT_GE(t["jgAfterMm2"].get<double>(), chosen - 1e-6);
    }
    givenSearched = givenSearched || (t["source"] == "given" && t["searched"].get<bool>());
  }
  EXPECT_TRUE(givenSearched);
  EXPECT_NE(p.run.out.find("Pose         up"), std::string::npos) << p.run.out;
}

TEST(CliPose, PlanJsonRecordsTheContactAndMarginOfEveryPoseTried) {
  const PoseRun& p = poseRun();
  ASSERT_EQ(p.run.exitCode, 0) << p.run.err;
  const nlohmann::json& pose = p.plan["pose"];
  EXPECT_GT(pose["contactAreaMm2"].get<double>(), 0.0);
  EXPECT_GT(pose["stabilityMarginMm"].get<double>(), 0.0);
  EXPECT_EQ(p.summary["pose"]["stability_margin"], pose["stabilityMarginMm"]);
  for (const auto& t : pose["runnersUp"]) {
    EXPECT_GT(t["contactAreaMm2"].get<double>(), 0.0) << t.dump();
    EXPECT_GT(t["stabilityMarginMm"].get<double>(), 0.0) << t.dump();
  }
  EXPECT_NE(p.run.out.find("mm inside its edge"), std::string::npos) << p.run.out;
}

TEST(CliPose, PlanWithAPoseLoadsBack) {
  const PoseRun& p = poseRun();
  ASSERT_EQ(p.run.exitCode, 0) << p.run.err;
  auto loaded = multidir::core::loadPlan(p.dir + "/plan");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  ASSERT_TRUE(loaded->metadata.pose.has_value());
  EXPECT_EQ(loaded->metadata.pose->runnersUp.size(), 3u - ruledOutPoses(p.plan));
  EXPECT_NEAR(loaded->metadata.pose->up.dot(loaded->metadata.machine.up), 1.0, 1e-9);
}

TEST(CliPose, ExportPosesTheRegionsFromTheChosenUp) {
  const PoseRun& p = poseRun();
  ASSERT_EQ(p.run.exitCode, 0) << p.run.err;
  const CliRun exported = runCli("export '" + p.dir + "/plan' -o '" + p.dir + "/job'", p.dir);
  ASSERT_EQ(exported.exitCode, 0) << exported.err;
  const nlohmann::json job = nlohmann::json::parse(readAll(p.dir + "/job/print-job.json"), nullptr, false);
  const nlohmann::json& up = p.plan["pose"]["up"];
  EXPECT_NEAR(dot(job["machine"]["up"], up), 1.0, 1e-9);
  const nlohmann::json& first = job["steps"][0];
  EXPECT_NEAR(dot(first["printingDirection"], up), 1.0, 1e-9);
  // The machine frame turns the chosen up to +Z: the third row of modelToFile is that up.
  const nlohmann::json& m = first["modelToFile"];
  EXPECT_NEAR(dot(nlohmann::json{m[2][0], m[2][1], m[2][2]}, up), 1.0, 1e-9);
}

TEST(CliPose, CountsOutOfRangeOrWithoutAutoAreUsageErrors) {
  expectUsageError(knight() + " -o out --pose auto --poses 0", "--poses: the number of poses must be between 1 and 200");
  expectUsageError(knight() + " -o out --pose auto --poses 201", "between 1 and 200");
  expectUsageError(knight() + " -o out --pose auto --poses 3 --pose-searches 4", "--pose-searches: must be between 1 and the number of poses (3)");
  expectUsageError(knight() + " -o out --poses 5", "add --pose auto");
  expectUsageError(knight() + " -o out --pose best", "use auto or up");
}

TEST(CliPose, InfoListsCandidatePosesGivenUpFirst) {
  const std::string dir = multidir::test::scratchDirectory("CliPose.Info");
  const CliRun run = runCli("info " + knight() + " --up y --poses --json '" + dir + "/info.json'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("Candidate poses"), std::string::npos) << run.out;
  const nlohmann::json info = nlohmann::json::parse(readAll(dir + "/info.json"), nullptr, false);
  ASSERT_GE(info["poses"].size(), 2u);
  EXPECT_LE(info["poses"].size(), 24u);
  EXPECT_EQ(info["poses"][0]["source"], "given");
  EXPECT_NEAR(info["poses"][0]["riskyAreaMm2"].get<double>(), info["overhang"]["riskyAreaMm2"].get<double>(), 1e-6);
  EXPECT_EQ(info["poses"][1]["source"], "resting");
  // The knight stands on its base as given; every other candidate stands too.
  for (const auto& pose : info["poses"]) {
    EXPECT_GT(pose["contactAreaMm2"].get<double>(), 0.0) << pose.dump();
    EXPECT_GT(pose["stabilityMarginMm"].get<double>(), 0.0) << pose.dump();
  }
}

TEST(CliPose, InfoSaysWhenTheGivenUpWouldTipOver) {
  const std::string dir = multidir::test::scratchDirectory("CliPose.InfoTips");
  // The bunny as scanned touches the bed with one point of its hull along +Y.
  const CliRun run = runCli("info '" + multidir::test::sharedModelPath("bunny.off") + "' --up y --poses", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("the given up does not stand"), std::string::npos) << run.out;
}

// Runs `multidir decompose` on the kitten and checks its table, plan folder, summary, Ctrl-C and usage errors.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "multidir/core/plan/checksum.h"
#include "multidir/core/plan/plan_file.h"
#include "support/cli_runner.h"
#include "support/test_models.h"

extern char** environ;

namespace {

using multidir::test::CliRun;
using multidir::test::readAll;
using multidir::test::runCli;

std::string kitten() { return "'" + multidir::test::sharedModelPath("kitten.off") + "'"; }

// The quick kitten run most tests share: beam width 2 keeps it to about a second.
struct KittenRun {
  std::string dir;
  CliRun run;
  nlohmann::json summary;
};

const KittenRun& kittenRun() {
  static const KittenRun result = [] {
    KittenRun k;
    // One folder per test process: ctest may run these tests in parallel, each running the command itself.
    k.dir = multidir::test::scratchDirectory(std::string("CliDecompose.Kitten.") +
                                             testing::UnitTest::GetInstance()->current_test_info()->name());
    k.run = runCli("decompose " + kitten() + " --up y --beam-width 2 -o '" + k.dir + "/plan' --summary '" + k.dir +
                       "/summary.json'",
                   k.dir);
    const std::string text = readAll(k.dir + "/summary.json");
    k.summary = nlohmann::json::parse(text, nullptr, false);
    return k;
  }();
  return result;
}

void expectUsageError(const std::string& arguments, const std::string& message) {
  // A folder per test: ctest runs the tests that call this in parallel.
  const std::string dir = multidir::test::scratchDirectory(
      std::string("CliDecompose.Usage.") + testing::UnitTest::GetInstance()->current_test_info()->name());
  const CliRun run = runCli("decompose " + arguments, dir);
  EXPECT_EQ(run.exitCode, 2) << arguments << "\n" << run.err;
  EXPECT_NE(run.err.find(message), std::string::npos) << arguments << "\n" << run.err;
  EXPECT_FALSE(std::ifstream(dir + "/plan/plan.json").good()) << "no plan for a usage error";
}

}  // namespace

TEST(CliDecompose, KittenPrintsTheRegionTableAndJg) {
  const KittenRun& k = kittenRun();
  ASSERT_EQ(k.run.exitCode, 0) << k.run.err;
  EXPECT_NE(k.run.out.find("Regions in printing order"), std::string::npos) << k.run.out;
  EXPECT_NE(k.run.out.find("direction (x, y, z)"), std::string::npos) << k.run.out;
  EXPECT_NE(k.run.out.find("volume mm^3"), std::string::npos) << k.run.out;
  EXPECT_NE(k.run.out.find("risky mm^2"), std::string::npos) << k.run.out;
  EXPECT_NE(k.run.out.find("    1   0.000,  1.000,  0.000    tilt   0.0"), std::string::npos)
      << "the first region stands on the platform, printed along up\n"
      << k.run.out;
  EXPECT_NE(k.run.out.find("J_G before   1507.21 mm^2"), std::string::npos) << k.run.out;
  EXPECT_NE(k.run.out.find("J_G after"), std::string::npos) << k.run.out;
  EXPECT_EQ(k.run.out.find("Note:"), std::string::npos) << "a full search has no cancellation note";
}

TEST(CliDecompose, KittenSummaryHasTheSearchNumbers) {
  const KittenRun& k = kittenRun();
  ASSERT_EQ(k.run.exitCode, 0) << k.run.err;
  const nlohmann::json& s = k.summary;
  ASSERT_TRUE(s.is_object()) << readAll(k.dir + "/summary.json");
  EXPECT_EQ(s["triangles"], 10000);
  EXPECT_GT(s["candidates"].get<long long>(), 0);
  EXPECT_GE(s["levels"].get<int>(), 1);
  EXPECT_GE(s["regions"].get<int>(), 2);
  EXPECT_EQ(s["planes"].get<int>(), s["regions"].get<int>() - 1);
  EXPECT_NEAR(s["jg_before"].get<double>(), 1507.21, 0.01);
  EXPECT_LT(s["jg_after"].get<double>(), 0.1 * s["jg_before"].get<double>());
  EXPECT_GE(s["seconds"].get<double>(), 0.0);
  EXPECT_GE(s["threads"].get<int>(), 1);
  EXPECT_EQ(s["machine"], "5dof");
  EXPECT_EQ(s["scheme"], "beam");
  EXPECT_EQ(s["beam_width"], 2);
  EXPECT_EQ(s["cancelled"], false);
  EXPECT_NE(s["model"].get<std::string>().find("kitten.off"), std::string::npos);
}

TEST(CliDecompose, PlanJsonSummaryAndReportAgreeOnJg) {
  // One definition of J_G (docs/jg-definition.md): every output of the same search shows the same number.
  const KittenRun& k = kittenRun();
  ASSERT_EQ(k.run.exitCode, 0) << k.run.err;
  const nlohmann::json plan = nlohmann::json::parse(readAll(k.dir + "/plan/plan.json"));
  const double planJg = plan["result"]["jgAfterMm2"].get<double>();
  EXPECT_NEAR(k.summary["jg_after"].get<double>(), planJg, 1e-9 * std::max(1.0, planJg));
  double regions = 0;
  for (const nlohmann::json& region : plan["regions"]) regions += region["riskyAreaMm2"].get<double>();
  EXPECT_NEAR(regions, planJg, 1e-6 * std::max(1.0, planJg));
  const CliRun report =
      runCli("report " + kitten() + " --up y --beam-width 2 --json '" + k.dir + "/report.json'", k.dir);
  ASSERT_EQ(report.exitCode, 0) << report.err;
  const nlohmann::json rows = nlohmann::json::parse(readAll(k.dir + "/report.json"));
  EXPECT_NEAR(rows[0]["jg_after"].get<double>(), planJg, 1e-9 * std::max(1.0, planJg));
  EXPECT_NEAR(rows[0]["jg_before"].get<double>(), k.summary["jg_before"].get<double>(), 1e-9);
}

TEST(CliDecompose, KittenPlanLoadsBackWithTheModelChecksum) {
  const KittenRun& k = kittenRun();
  ASSERT_EQ(k.run.exitCode, 0) << k.run.err;
  const auto plan = multidir::core::loadPlan(k.dir + "/plan");
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  EXPECT_EQ(static_cast<int>(plan->decomposition.regions.size()), k.summary["regions"].get<int>());
  EXPECT_EQ(plan->decomposition.jgAfterMm2, k.summary["jg_after"].get<double>());
  EXPECT_EQ(plan->metadata.modelChecksum, *multidir::core::fileChecksum(multidir::test::sharedModelPath("kitten.off")));
  EXPECT_EQ(plan->metadata.up, multidir::core::Vec3(0, 1, 0));
  EXPECT_EQ(plan->metadata.options.beamWidth, 2);
  for (const auto& region : plan->decomposition.regions) EXPECT_GT(region.mesh.faceCount(), 0u);
}

TEST(CliDecompose, WithoutATerminalThereAreNoRedraws) {
  const KittenRun& k = kittenRun();
  EXPECT_EQ(k.run.err.find('\r'), std::string::npos) << k.run.err;
  EXPECT_NE(k.run.err.find("searching"), std::string::npos) << k.run.err;
}

TEST(CliDecompose, MachineProfileChoosesTheMachine) {
  const std::string dir = multidir::test::scratchDirectory("CliDecompose.Profile");
  multidir::core::MachineSpec printer;
  printer.kind = multidir::core::MachineKind::ThreeAxis;
  printer.up = multidir::core::Vec3(0, 1, 0);
  ASSERT_TRUE(multidir::core::saveMachineProfile(printer, dir + "/printer.json").ok());
  const CliRun run = runCli("decompose " + kitten() + " --profile '" + dir + "/printer.json' -o '" + dir +
                                "/plan' --summary '" + dir + "/summary.json'",
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json summary = nlohmann::json::parse(readAll(dir + "/summary.json"));
  EXPECT_EQ(summary["machine"], "3dof");
  EXPECT_NEAR(summary["jg_before"].get<double>(), 1507.21, 0.01) << "the profile's up (+Y) was used";
}

TEST(CliDecompose, UnreadableProfileExitsWithOne) {
  const std::string dir = multidir::test::scratchDirectory("CliDecompose.BadProfile");
  std::ofstream(dir + "/bad.json")
      << R"({"schema": "multidir-machine", "version": 1, "kind": "5dof", "maxTiltDegrees": 200})";
  const CliRun run = runCli("decompose " + kitten() + " --profile '" + dir + "/bad.json' -o '" + dir + "/plan'", dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("bad.json: maximal tilt must be between 0 and 180 degrees"), std::string::npos) << run.err;
}

TEST(CliDecompose, MissingModelExitsWithOne) {
  const std::string dir = multidir::test::scratchDirectory("CliDecompose.Missing");
  const CliRun run = runCli("decompose /nonexistent/ghost.stl -o '" + dir + "/plan'", dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("ghost.stl"), std::string::npos) << run.err;
}

TEST(CliDecompose, PolishOptionsThatContradictOrAreOutOfRangeAreUsageErrors) {
  const std::string k = kitten() + " -o out ";
  expectUsageError(k + "--polish --no-polish", "--polish and --no-polish contradict each other");
  expectUsageError(k + "--no-polish --polish-effort 2", "--polish-effort and --no-polish contradict each other");
  expectUsageError(k + "--polish-effort 7", "--polish-effort: polish effort must be between 1 and 6");
  expectUsageError(k + "--no-polish --polish-finalists", "--polish-finalists and --no-polish contradict each other");
  expectUsageError(k + "--polish-finalists --no-polish-finalists",
                   "--polish-finalists and --no-polish-finalists contradict each other");
  expectUsageError(k + "--search-tails --no-search-tails",
                   "--search-tails and --no-search-tails contradict each other");
}

// --search-tails and --no-search-tails each reach the search (its note on the tails, or none) and plan.json's
// search.searchTails.
TEST(CliDecompose, SearchTailsFlagsReachTheSearchAndPlanJsonKeepsThem) {
  const std::string dir = multidir::test::scratchDirectory("CliDecompose.SearchTails");
  for (const bool tails : {true, false}) {
    const std::string flag = tails ? "--search-tails" : "--no-search-tails";
    const std::string out = dir + "/plan" + flag;
    const CliRun run =
        runCli("decompose " + kitten() + " --up y --beam-width 2 --no-supports " + flag + " -o '" + out + "'", dir);
    ASSERT_EQ(run.exitCode, 0) << flag << ": " << run.err;
    const nlohmann::json plan = nlohmann::json::parse(readAll(out + "/plan.json"));
    EXPECT_EQ(plan["search"]["searchTails"], tails) << flag;
    const std::string notes = plan["result"]["statistics"]["notes"].dump();
    EXPECT_EQ(notes.find("tails searched again") != std::string::npos, tails) << flag << ": " << notes;
  }
}

// --polish-finalists and --no-polish-finalists each reach the search (its note on the finalists, or none) and
// plan.json's search.polishFinalists; --no-polish polishes no finalists either, and plan.json says so.
TEST(CliDecompose, PolishFinalistsFlagsReachTheSearchAndPlanJsonKeepsThem) {
  const std::string dir = multidir::test::scratchDirectory("CliDecompose.PolishFinalists");
  struct Case {
    std::string flag;
    bool finalists;
  };
  for (const Case& c : {Case{"--polish-finalists", true}, Case{"--no-polish-finalists", false},
                        Case{"--no-polish", false}}) {
    const std::string out = dir + "/plan" + c.flag;
    const CliRun run =
        runCli("decompose " + kitten() + " --up y --beam-width 2 --no-supports " + c.flag + " -o '" + out + "'", dir);
    ASSERT_EQ(run.exitCode, 0) << c.flag << ": " << run.err;
    const nlohmann::json plan = nlohmann::json::parse(readAll(out + "/plan.json"));
    EXPECT_EQ(plan["search"]["polishFinalists"], c.finalists) << c.flag;
    const std::string notes = plan["result"]["statistics"]["notes"].dump();
    EXPECT_EQ(notes.find("finalists of the search") != std::string::npos, c.finalists) << c.flag << ": " << notes;
  }
}

TEST(CliDecompose, NoPolishKeepsTheSearchsPlanAndPlanJsonSaysSo) {
  const std::string dir = multidir::test::scratchDirectory("CliDecompose.NoPolish");
  const CliRun run = runCli("decompose " + kitten() + " --up y --beam-width 2 --no-supports --no-polish -o '" + dir +
                                "/plan'",
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json plan = nlohmann::json::parse(readAll(dir + "/plan/plan.json"));
  EXPECT_EQ(plan["search"]["polish"], false);
  EXPECT_EQ(plan["result"]["statistics"]["jgBeforePolishMm2"].get<double>(), -1.0);
  EXPECT_EQ(plan["result"]["statistics"]["polishEvaluations"].get<int>(), 0);
}

TEST(CliDecompose, UsageErrorsExitWithTwoAndNameTheOption) {
  const std::string k = kitten() + " ";
  expectUsageError(k + "-o out --beam-width 0", "--beam-width: beam width must be between 1 and 1000");
  expectUsageError(k + "-o out --beam-width 2.5", "--beam-width expects a whole number, got '2.5'");
  expectUsageError(k + "-o out --machine 7dof", "--machine: '7dof' is not a machine");
  expectUsageError(k + "--beam-width 2", "-o OUTDIR is missing");
  expectUsageError(k + "-o", "-o needs a value");
  expectUsageError(k + "-o out --scheme random", "--scheme: 'random' is not a scheme");
  expectUsageError(k + "-o out --alpha 90", "--alpha: alpha must be at least 0 and below 90 degrees");
  expectUsageError(k + "-o out --normals 0", "--normals: the number of normals must be between 1 and 100000");
  expectUsageError(k + "-o out --offset-step 0", "--offset-step: the offset step must be between 0.01 and 1000 mm");
  expectUsageError(k + "-o out --w 0.5", "--w: w (the minimal region volume is V/w) must be between 1 and 1000");
  expectUsageError(k + "-o out --threads -1", "--threads: threads must be between 0 (all) and 256");
  expectUsageError(k + "-o out --axis 1,0,0", "--axis is the rotation axis of a 4dof machine");
  expectUsageError(k + "-o out --machine 4dof --up y --axis 0,1,0", "--axis: rotation axis must be a unit vector");
  expectUsageError(k + "-o out --axis-search 4", "--axis-search turns the rotation axis of a 4dof machine");
  expectUsageError(k + "-o out --machine 4dof --axis-search 0", "--axis-search: the number of axes must be between");
  expectUsageError(k + "-o out --up sideways", "--up:");
  expectUsageError(k + "-o out --colour red", "unknown option '--colour'");
  expectUsageError("-o out", "which model?");
}

TEST(CliDecompose, ScalesOutsideOneToFourIsAUsageErrorNamingTheOption) {
  const std::string k = kitten() + " ";
  expectUsageError(k + "-o out --scales 0", "--scales: volume scales must be between 1 and 4");
  expectUsageError(k + "-o out --scales 5", "--scales: volume scales must be between 1 and 4");
  expectUsageError(k + "-o out --scales 1.5", "--scales expects a whole number, got '1.5'");
}

TEST(CliDecompose, OneScaleRunsAndIsRecordedInThePlan) {
  const std::string dir = multidir::test::scratchDirectory("CliDecompose.OneScale");
  const CliRun run =
      runCli("decompose " + kitten() + " --up y --beam-width 2 --scales 1 -o '" + dir + "/plan'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto loaded = multidir::core::loadPlan(dir + "/plan");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->metadata.options.volumeScales, 1);
  EXPECT_EQ(nlohmann::json::parse(readAll(dir + "/plan/plan.json"))["search"]["volumeScales"], 1);
}

TEST(CliDecompose, HelpListsEveryOption) {
  const std::string dir = multidir::test::scratchDirectory("CliDecompose.Help");
  const CliRun run = runCli("help decompose", dir);
  EXPECT_EQ(run.exitCode, 0);
  for (const char* option :
       {"-o OUTDIR", "--up", "--machine", "--axis X,Y,Z", "--axis-search", "--profile", "--scheme", "--beam-width",
        "--alpha", "--normals", "--offset-step", "--w W", "--scales S", "--threads", "--summary"})
    EXPECT_NE(run.out.find(option), std::string::npos) << option;
}

// Ctrl-C: the search stops at once and the best plan found until then is saved, marked as cancelled.
TEST(CliDecompose, InterruptSavesTheBestPlanSoFarWithANote) {
  const std::string dir = multidir::test::scratchDirectory("CliDecompose.Interrupt");
  const std::string outPath = dir + "/stdout.txt", errPath = dir + "/stderr.txt";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  // A search far longer than the test waits: thousands of normals, fine offsets, wide beams.
  const std::string model = multidir::test::sharedModelPath("kitten.off"), plan = dir + "/plan";
  std::vector<std::string> args = {
      MULTIDIR_CLI_PATH, "decompose", model, "--up", "y",         "--normals",          "20000", "--beam-width", "100",
      "--offset-step",   "0.1",       "-o",  plan,   "--summary", dir + "/summary.json"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, MULTIDIR_CLI_PATH, &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);

  // The start line is written once Ctrl-C is handled; interrupt as soon as it appears.
  for (int i = 0; i < 3000 && readAll(errPath).find("searching") == std::string::npos; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_NE(readAll(errPath).find("searching"), std::string::npos) << readAll(errPath);
  ASSERT_EQ(kill(pid, SIGINT), 0);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);

  const std::string out = readAll(outPath), err = readAll(errPath);
  ASSERT_TRUE(WIFEXITED(status)) << err;
  EXPECT_EQ(WEXITSTATUS(status), 0) << err;
  EXPECT_NE(err.find("interrupted; stopping the search"), std::string::npos) << err;
  EXPECT_NE(out.find("Note: the search was cancelled; this is the best plan found until then"), std::string::npos)
      << out;
  const auto loaded = multidir::core::loadPlan(plan);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_TRUE(loaded->decomposition.cancelled);
  const nlohmann::json summary = nlohmann::json::parse(readAll(dir + "/summary.json"));
  EXPECT_EQ(summary["cancelled"], true);
}

TEST(CliDecompose, SummaryReplacesALinkAtItsPathInsteadOfWritingThroughIt) {
  const std::string dir = multidir::test::scratchDirectory("CliDecompose.SummaryOverALink");
  std::ofstream(dir + "/victim.txt") << "not MultiDir's\n";
  std::filesystem::create_symlink(dir + "/victim.txt", dir + "/summary.json");
  const CliRun run = runCli("decompose " + kitten() + " --up y --scheme greedy -o '" + dir + "/plan' --summary '" + dir +
                                "/summary.json'",
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(readAll(dir + "/victim.txt"), "not MultiDir's\n");
  EXPECT_FALSE(std::filesystem::is_symlink(dir + "/summary.json"));
  EXPECT_TRUE(nlohmann::json::parse(readAll(dir + "/summary.json")).contains("regions"));
}

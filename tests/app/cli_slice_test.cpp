// Runs `multidir slice` on a plan written by `multidir decompose`: the table, the G-code and estimates it
// writes, and its errors and exit codes.
#include <gtest/gtest.h>

#include <signal.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

namespace fs = std::filesystem;
using multidir::test::CliRun;
using multidir::test::readAll;
using multidir::test::runCli;

std::string quoted(const std::string& path) { return "'" + path + "'"; }

// The kitten on a rotary platform (greedy search: quick), decomposed once per test process.
const std::string& smallKittenPlan(const std::string& dir) {
  static const std::string plan = [&dir] {
    const CliRun run = runCli("decompose " + quoted(multidir::test::sharedModelPath("kitten.off")) +
                                  " --up y --machine 4dof --scheme greedy -o " + quoted(dir + "/plan"),
                              dir);
    if (run.exitCode != 0) throw std::runtime_error("decompose failed: " + run.err);
    return dir + "/plan";
  }();
  return plan;
}

const char* const kCoarse =
    "--set 'layer_height=0.6 first_layer_height=0.6 perimeters=1 top_solid_layers=1 bottom_solid_layers=1 "
    "fill_density=0%'";

}  // namespace

TEST(CliSlice, WritesStepGcodeAndEstimatesIntoTheJobFile) {
  const std::string dir = multidir::test::scratchDirectory("CliSlice.Writes");
  const CliRun run = runCli("slice " + quoted(smallKittenPlan(dir)) + " --printer robot-0.8 --no-comparison " +
                                kCoarse + " -o " + quoted(dir + "/gcode"),
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("Sliced with PrusaSlicer"), std::string::npos) << run.out;
  EXPECT_TRUE(fs::exists(dir + "/gcode/step-01.gcode"));
  EXPECT_FALSE(fs::exists(dir + "/gcode/job.gcode"));  // the robot's platform turns over Modbus
  const nlohmann::json job = nlohmann::json::parse(readAll(dir + "/gcode/print-job.json"));
  ASSERT_TRUE(job.contains("slicing"));
  EXPECT_EQ(job["slicing"]["steps"].size(), job["steps"].size());
  EXPECT_GT(job["slicing"]["total"]["printSeconds"].get<double>(), 0.0);
  EXPECT_TRUE(job["slicing"]["fixedDirection"].is_null());
}

TEST(CliSlice, UnknownPrinterIsABadInputNamingTheShippedProfiles) {
  const std::string dir = multidir::test::scratchDirectory("CliSlice.UnknownPrinter");
  const CliRun run =
      runCli("slice " + quoted(smallKittenPlan(dir)) + " --printer no-such-printer -o " + quoted(dir + "/out"), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("marlin-220"), std::string::npos) << run.err;
}

TEST(CliSlice, MissingPrinterOptionIsAUsageError) {
  const std::string dir = multidir::test::scratchDirectory("CliSlice.NoPrinter");
  const CliRun run = runCli("slice plan -o out", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("--printer is required"), std::string::npos) << run.err;
}

TEST(CliSlice, MissingSlicerExitsWithTheCommandNamed) {
  const std::string dir = multidir::test::scratchDirectory("CliSlice.NoSlicer");
  const CliRun run = runCli("slice " + quoted(smallKittenPlan(dir)) + " --printer robot-0.8 --slicer no-such-slicer -o " +
                                quoted(dir + "/out"),
                            dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("no-such-slicer --loglevel 1 --export-gcode"), std::string::npos) << run.err;
}

TEST(CliSlice, ProgressWrittenToAFileHasNoTerminalEscapes) {
  // stderr is a file here, not a terminal: plain lines, no carriage returns or ANSI escapes.
  const std::string dir = multidir::test::scratchDirectory("CliSlice.PlainProgress");
  const CliRun run = runCli("slice " + quoted(smallKittenPlan(dir)) + " --printer robot-0.8 --no-comparison " +
                                kCoarse + " -o " + quoted(dir + "/gcode"),
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(run.err.find('\r'), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find('\033'), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("% slicing"), std::string::npos) << run.err;
}

TEST(CliSlice, InterruptStopsEverySlicerAndLeavesNoWorkFolder) {
  const std::string dir = multidir::test::scratchDirectory("CliSlice.Interrupt");
  // A slicer that never ends on its own; each writes its process id.
  const std::string fake = dir + "/slow-slicer.sh";
  std::ofstream(fake) << "#!/bin/sh\necho $$ >> '" << dir << "/pids'\nexec sleep 60\n";
  fs::permissions(fake, fs::perms::owner_all);
  const CliRun run = runCli("slice " + quoted(smallKittenPlan(dir)) + " --printer robot-0.8 --slicer " + quoted(fake) +
                                " -o " + quoted(dir + "/out"),
                            dir, "timeout --preserve-status -s INT 4");
  EXPECT_EQ(run.exitCode, 130) << run.err;
  EXPECT_NE(run.err.find("interrupted"), std::string::npos) << run.err;
  ASSERT_TRUE(fs::exists(dir + "/pids")) << "no slicer started before the interrupt";
  for (const auto& entry : fs::directory_iterator(dir + "/out"))
    EXPECT_NE(entry.path().filename().string().rfind(".slicing-", 0), 0u) << entry.path();
  EXPECT_FALSE(fs::exists(dir + "/out/step-01.gcode"));
  std::istringstream pids(readAll(dir + "/pids"));
  for (long pid = 0; pids >> pid;) EXPECT_NE(::kill(static_cast<pid_t>(pid), 0), 0) << "slicer " << pid << " still runs";
}

TEST(CliSlice, AnOutputFolderHoldingOtherFilesIsRefusedNamingItAndForce) {
  const std::string dir = multidir::test::scratchDirectory("CliSlice.OtherFiles");
  fs::create_directories(dir + "/out");
  std::ofstream(dir + "/out/notes.txt") << "the user's own notes\n";
  const CliRun run = runCli("slice " + quoted(smallKittenPlan(dir)) + " --printer robot-0.8 --slicer no-such-slicer -o " +
                                quoted(dir + "/out"),
                            dir);
  EXPECT_EQ(run.exitCode, 1) << run.err;
  EXPECT_NE(run.err.find(dir + "/out: "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--force"), std::string::npos) << run.err;
  EXPECT_EQ(readAll(dir + "/out/notes.txt"), "the user's own notes\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir + "/out"), fs::directory_iterator()), 1);
}

TEST(CliSlice, HelpNamesForce) {
  const std::string dir = multidir::test::scratchDirectory("CliSlice.Help");
  const CliRun run = runCli("slice --help", dir);
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_NE(run.out.find("--force"), std::string::npos) << run.out;
}

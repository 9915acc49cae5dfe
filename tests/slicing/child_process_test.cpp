// Child processes: a missing program names itself, a failing one gives its exit code and output, a cancelled
// one is stopped.
#include "multidir/slicing/child_process.h"

#include <gtest/gtest.h>

#include <thread>

using namespace multidir;
using slicing::runChildProcess;

TEST(ChildProcess, MissingProgramIsFileNotFoundNamingTheCommand) {
  core::JobContext context;
  const auto run = runChildProcess({"no-such-slicer-xyz", "--export-gcode"}, context);
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.error().code, core::ErrorCode::FileNotFound);
  EXPECT_NE(run.error().message.find("no-such-slicer-xyz --export-gcode"), std::string::npos) << run.error().message;
}

TEST(ChildProcess, ExitCodeAndInterleavedOutputAreCaptured) {
  core::JobContext context;
  const auto run = runChildProcess({"sh", "-c", "echo one; echo two >&2; exit 3"}, context);
  ASSERT_TRUE(run.ok()) << run.error().describe();
  EXPECT_EQ(run->exitCode, 3);
  EXPECT_EQ(slicing::lastLines(run->output, 5), "one\ntwo");
  EXPECT_EQ(slicing::lastLines(run->output, 1), "two");
}

TEST(ChildProcess, CancellingStopsTheChildWithCancelled) {
  core::JobContext context;
  std::thread canceller([context]() mutable {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    context.cancel();
  });
  const auto run = runChildProcess({"sleep", "30"}, context);
  canceller.join();
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.error().code, core::ErrorCode::Cancelled);
}

TEST(ChildProcess, CommandTextQuotesArgumentsWithSpaces) {
  EXPECT_EQ(slicing::commandText({"prusa-slicer", "-o", "my file.gcode"}), "prusa-slicer -o 'my file.gcode'");
}

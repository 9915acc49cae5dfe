// The job timeline's rows follow the sequencer's log; the job's time left follows the slicer's estimates.
#include <gtest/gtest.h>

#include <chrono>

#include "ui/device/job_eta.h"
#include "ui/device/job_timeline.h"

namespace multidir::ui {
namespace {

using hardware::PrintRunState;

hardware::PrintRunLogEntry entry(std::size_t step, PrintRunState state, int second) {
  hardware::PrintRunLogEntry e;
  e.step = step;
  e.state = state;
  e.wallTime = std::chrono::system_clock::time_point(std::chrono::seconds(1'800'000'000 + second));
  return e;
}

std::vector<TimelineRow> threeSteps() { return std::vector<TimelineRow>(3); }

TEST(JobTimelineRows, AStepTheRunWentPastIsDoneWhenTheNextOneStarts) {
  auto rows = threeSteps();
  applyRunEvent(rows, entry(0, PrintRunState::Moving, 0), {});
  applyRunEvent(rows, entry(0, PrintRunState::Settling, 2), {});
  applyRunEvent(rows, entry(0, PrintRunState::Printing, 3), {});
  EXPECT_EQ(rows[0].phase, StepPhase::Printing);
  applyRunEvent(rows, entry(1, PrintRunState::Moving, 40), {});
  EXPECT_EQ(rows[0].phase, StepPhase::Done);
  EXPECT_EQ(rows[0].started->toSecsSinceEpoch(), 1'800'000'000);
  EXPECT_EQ(rows[0].ended->toSecsSinceEpoch(), 1'800'000'040);
  EXPECT_EQ(rows[1].phase, StepPhase::Moving);
  EXPECT_FALSE(rows[1].ended);
  EXPECT_EQ(rows[2].phase, StepPhase::Waiting);
  EXPECT_FALSE(rows[2].started);
}

TEST(JobTimelineRows, APauseKeepsTheReasonItPausedForAndResumeClearsIt) {
  auto rows = threeSteps();
  applyRunEvent(rows, entry(0, PrintRunState::Printing, 0), {});
  applyRunEvent(rows, entry(0, PrintRunState::Paused, 5), QStringLiteral("temperature fault"));
  applyRunEvent(rows, entry(0, PrintRunState::Paused, 6), QStringLiteral("motion stopped"));
  EXPECT_EQ(rows[0].phase, StepPhase::Paused);
  EXPECT_EQ(rows[0].reason, QStringLiteral("temperature fault"));
  applyRunEvent(rows, entry(0, PrintRunState::Printing, 9), {});
  EXPECT_EQ(rows[0].phase, StepPhase::Printing);
  EXPECT_TRUE(rows[0].reason.isEmpty());
  EXPECT_EQ(rows[0].started->toSecsSinceEpoch(), 1'800'000'000);  // when it first started
}

TEST(JobTimelineRows, AFaultFailsTheStepWithTheReasonAndTheLastStepIsDoneWhenTheRunCompletes) {
  auto rows = threeSteps();
  applyRunEvent(rows, entry(1, PrintRunState::Moving, 10), {});
  applyRunEvent(rows, entry(1, PrintRunState::Faulted, 12), QStringLiteral("stall"));
  EXPECT_EQ(rows[1].phase, StepPhase::Failed);
  EXPECT_EQ(rows[1].reason, QStringLiteral("stall"));
  EXPECT_EQ(rows[1].ended->toSecsSinceEpoch(), 1'800'000'012);
  applyRunEvent(rows, entry(1, PrintRunState::Moving, 20), {});  // resumed: the step is retried
  EXPECT_EQ(rows[1].phase, StepPhase::Moving);
  EXPECT_FALSE(rows[1].ended);
  applyRunEvent(rows, entry(2, PrintRunState::Completed, 90), {});
  for (const TimelineRow& row : rows) EXPECT_EQ(row.phase, StepPhase::Done);
  EXPECT_EQ(rows[2].ended->toSecsSinceEpoch(), 1'800'000'090);
}

TEST(JobTimelineRows, AnEmergencyStopAbortsTheCurrentStepOnceAndKeepsItsTime) {
  auto rows = threeSteps();
  applyRunEvent(rows, entry(0, PrintRunState::Printing, 0), {});
  applyRunEvent(rows, entry(0, PrintRunState::Aborted, 4), QStringLiteral("EMERGENCY STOP"));
  applyRunEvent(rows, entry(0, PrintRunState::Aborted, 5), QStringLiteral("printer confirmed the emergency stop"));
  EXPECT_EQ(rows[0].phase, StepPhase::Aborted);
  EXPECT_EQ(rows[0].reason, QStringLiteral("EMERGENCY STOP"));
  EXPECT_EQ(rows[0].ended->toSecsSinceEpoch(), 1'800'000'004);
  EXPECT_EQ(rows[1].phase, StepPhase::Waiting);
}

TEST(JobEta, TimeLeftIsTheCurrentStepsRestPlusEveryLaterStep) {
  const std::vector<double> estimates = {100.0, 200.0, 50.0};
  EXPECT_DOUBLE_EQ(*remainingJobSeconds(estimates, 0, 0.0), 350.0);
  EXPECT_DOUBLE_EQ(*remainingJobSeconds(estimates, 1, 0.25), 200.0);
  EXPECT_DOUBLE_EQ(*remainingJobSeconds(estimates, 2, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(*remainingJobSeconds(estimates, 2, 7.0), 0.0);  // progress clamped
}

TEST(JobEta, NoTimeLeftWithoutAnEstimateForEveryStep) {
  EXPECT_FALSE(remainingJobSeconds({}, 0, 0.0));
  EXPECT_FALSE(remainingJobSeconds({100.0, 0.0}, 0, 0.5));
  EXPECT_FALSE(remainingJobSeconds({100.0}, 1, 0.0));
}

}  // namespace
}  // namespace multidir::ui

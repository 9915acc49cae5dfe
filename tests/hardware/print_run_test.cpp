#include "multidir/hardware/print_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace multidir::hardware {
namespace {

using namespace std::chrono_literals;

// A positioner the test moves by hand. Its stop latches like the drivers' (moves refused until clearStop,
// which is refused until the stop is confirmed) and, depending on stopMode, is confirmed at once, waits
// (as during a link outage) until the test calls confirmStop(), or is refused.
class FakePositioner : public Positioner {
 public:
  enum class StopMode { ConfirmedAtOnce, WaitsForTheLink, Refused };

  core::Status startMove(const PlatformOrientation& target) override {
    moves.push_back(target);
    if (state.stopLatched) return core::Error{core::ErrorCode::InvalidParameter, "a stop is latched", "fake"};
    if (refuseNext) {
      refuseNext = false;
      return core::Error{core::ErrorCode::InvalidParameter, "not homed", "fake"};
    }
    state.reached = false;
    state.moving = true;
    return core::Done{};
  }
  core::Status stopMotion() override {
    ++stops;
    if (stopMode == StopMode::Refused)
      return core::Error{core::ErrorCode::InvalidParameter, "not connected: the stop was not sent", "fake"};
    state.stopLatched = true;
    state.stopConfirmed = false;
    if (stopMode == StopMode::ConfirmedAtOnce) confirmStop();
    return core::Done{};
  }
  core::Status emergencyStop() override {
    ++emergencyStops;
    return stopMotion();
  }
  core::Status clearStop() override {
    if (state.stopLatched && !state.stopConfirmed)
      return core::Error{core::ErrorCode::InvalidParameter, "the stop is not confirmed yet", "fake"};
    state.stopLatched = false;
    state.stopConfirmed = false;
    return core::Done{};
  }
  void confirmStop() {
    state.stopConfirmed = true;
    state.moving = false;
  }
  PositionerSnapshot snapshot() const override { return state; }
  std::string name() const override { return "fake platform"; }

  void arrive() {
    state.moving = false;
    state.reached = true;
  }

  std::vector<PlatformOrientation> moves;
  int stops = 0;
  int emergencyStops = 0;
  bool refuseNext = false;
  StopMode stopMode = StopMode::ConfirmedAtOnce;
  PositionerSnapshot state = [] {
    PositionerSnapshot s;
    s.linkUp = true;
    return s;
  }();
};

bool logMentions(const PrintRun& run, const std::string& text) {
  return std::any_of(run.log().begin(), run.log().end(),
                     [&](const PrintRunLogEntry& e) { return e.message.find(text) != std::string::npos; });
}

class PrintRunTest : public ::testing::Test {
 protected:
  PrintRunOptions options() {
    PrintRunOptions o;
    o.settleTime = 500ms;
    o.moveTimeout = 10s;
    o.steadyNow = [this] { return now; };
    o.wallNow = [this] { return wall; };
    return o;
  }
  std::vector<PrintStep> threeSteps() const {
    return {{PlatformOrientation::rotary(0.0), "region_1.stl"},
            {PlatformOrientation::rotary(30.0), "region_2.stl"},
            {PlatformOrientation::rotary(-45.0), "region_3.stl"}};
  }
  void advance(std::chrono::milliseconds by, PrintRun& run) {
    now += by;
    wall += by;
    run.tick();
  }
  // Moves through reaching and settling into Printing.
  void settle(PrintRun& run) {
    device.arrive();
    advance(10ms, run);
    advance(500ms, run);
  }

  FakePositioner device;
  std::chrono::steady_clock::time_point now{std::chrono::hours(1)};
  std::chrono::system_clock::time_point wall{std::chrono::hours(24 * 365 * 50)};
};

TEST_F(PrintRunTest, RunsEachStepMoveSettlePrintInOrderAndCompletes) {
  PrintRun run(device, threeSteps(), options());
  std::vector<std::size_t> printed;
  run.setPrintRequestCallback([&](std::size_t step, const PrintStep&) { printed.push_back(step); });
  ASSERT_TRUE(run.start().ok());
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(run.state(), PrintRunState::Moving);
    EXPECT_EQ(device.moves.size(), i + 1);
    settle(run);
    ASSERT_EQ(run.state(), PrintRunState::Printing);
    ASSERT_TRUE(run.regionDone(i).ok());
  }
  EXPECT_EQ(run.state(), PrintRunState::Completed);
  EXPECT_EQ(printed, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_DOUBLE_EQ(device.moves[1].rotaryDegrees, 30.0);
  EXPECT_DOUBLE_EQ(device.moves[2].rotaryDegrees, -45.0);
}

TEST_F(PrintRunTest, StartedFromAStepMovesToThatStepFirstAndPrintsOnlyFromThere) {
  PrintRun run(device, threeSteps(), options());
  std::vector<std::size_t> printed;
  run.setPrintRequestCallback([&](std::size_t step, const PrintStep&) { printed.push_back(step); });
  ASSERT_TRUE(run.start(1).ok());
  EXPECT_EQ(run.currentStep(), 1u);
  ASSERT_EQ(device.moves.size(), 1u);
  EXPECT_DOUBLE_EQ(device.moves[0].rotaryDegrees, 30.0);
  for (std::size_t i = 1; i < 3; ++i) {
    settle(run);
    ASSERT_EQ(run.state(), PrintRunState::Printing);
    ASSERT_TRUE(run.regionDone(i).ok());
  }
  EXPECT_EQ(run.state(), PrintRunState::Completed);
  EXPECT_EQ(printed, (std::vector<std::size_t>{1, 2}));
}

TEST_F(PrintRunTest, StartFromAStepPastTheLastIsRefusedAndNothingMoves) {
  PrintRun run(device, threeSteps(), options());
  const core::Status started = run.start(3);
  ASSERT_FALSE(started.ok());
  EXPECT_NE(started.error().message.find("no step 4"), std::string::npos) << started.error().message;
  EXPECT_EQ(run.state(), PrintRunState::Idle);
  EXPECT_TRUE(device.moves.empty());
}

TEST_F(PrintRunTest, PrintingWaitsUntilTheTargetWasHeldForTheSettleTime) {
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  device.arrive();
  advance(10ms, run);
  EXPECT_EQ(run.state(), PrintRunState::Settling);
  advance(499ms, run);
  EXPECT_EQ(run.state(), PrintRunState::Settling);
  device.state.reached = false;  // a vibration takes it off target
  advance(1ms, run);
  EXPECT_EQ(run.state(), PrintRunState::Moving);
  device.arrive();
  advance(1ms, run);
  advance(499ms, run);
  EXPECT_EQ(run.state(), PrintRunState::Settling);  // the settle time starts again
  advance(1ms, run);
  EXPECT_EQ(run.state(), PrintRunState::Printing);
}

TEST_F(PrintRunTest, NoMoveIsCommandedWhileARegionPrints) {
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  settle(run);
  ASSERT_EQ(run.state(), PrintRunState::Printing);
  device.state.reached = false;  // whatever the device says, the sequencer waits for "region done"
  device.state.faulted = true;
  for (int i = 0; i < 20; ++i) advance(1s, run);
  EXPECT_EQ(run.state(), PrintRunState::Printing);
  EXPECT_EQ(device.moves.size(), 1u);
  EXPECT_EQ(device.stops, 0);
}

TEST_F(PrintRunTest, PauseWhileMovingStopsAndResumeCommandsTheSameStepAgain) {
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(run.pause().ok());
  EXPECT_EQ(run.state(), PrintRunState::Paused);
  EXPECT_EQ(device.stops, 1);
  advance(1s, run);
  EXPECT_EQ(run.state(), PrintRunState::Paused);
  ASSERT_TRUE(run.resume().ok());
  EXPECT_EQ(run.state(), PrintRunState::Moving);
  ASSERT_EQ(device.moves.size(), 2u);
  EXPECT_DOUBLE_EQ(device.moves[1].rotaryDegrees, 0.0);
  EXPECT_EQ(run.currentStep(), 0u);
}

TEST_F(PrintRunTest, PauseWhilePrintingTakesEffectWhenTheRegionIsDone) {
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  settle(run);
  ASSERT_TRUE(run.pause().ok());
  EXPECT_EQ(run.state(), PrintRunState::Printing);
  EXPECT_TRUE(run.pausePending());
  EXPECT_EQ(device.stops, 0);
  ASSERT_TRUE(run.regionDone(0).ok());
  EXPECT_EQ(run.state(), PrintRunState::Paused);
  EXPECT_EQ(run.currentStep(), 1u);
  EXPECT_EQ(device.moves.size(), 1u);  // step 2 not started
  ASSERT_TRUE(run.resume().ok());
  ASSERT_EQ(device.moves.size(), 2u);
  EXPECT_DOUBLE_EQ(device.moves[1].rotaryDegrees, 30.0);
}

TEST_F(PrintRunTest, AbortWhileMovingStopsAndIsFinal) {
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(run.abort().ok());
  EXPECT_EQ(run.state(), PrintRunState::Aborted);
  EXPECT_EQ(device.stops, 1);
  EXPECT_FALSE(run.resume().ok());
  EXPECT_FALSE(run.start().ok());
  EXPECT_FALSE(run.abort().ok());
}

TEST_F(PrintRunTest, AbortWhilePrintingCommandsNoMotionAndTellsToStopThePrinter) {
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  settle(run);
  ASSERT_TRUE(run.abort().ok());
  EXPECT_EQ(run.state(), PrintRunState::Aborted);
  EXPECT_EQ(device.stops, 0);
  EXPECT_NE(run.log().back().message.find("stop the printer"), std::string::npos);
}

TEST_F(PrintRunTest, DeviceFaultWhileMovingFaultsTheRunAndResumeRetriesTheStep) {
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  device.state.faulted = true;
  device.state.problem = "stall at 12.00 degrees";
  advance(10ms, run);
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_EQ(device.stops, 1);
  EXPECT_NE(run.lastProblem().find("stall"), std::string::npos);
  device.state.faulted = false;
  ASSERT_TRUE(run.resume().ok());
  EXPECT_EQ(run.state(), PrintRunState::Moving);
  EXPECT_EQ(device.moves.size(), 2u);
}

TEST_F(PrintRunTest, RefusedMoveFaultsTheRunWithTheDevicesReason) {
  device.refuseNext = true;
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_NE(run.lastProblem().find("not homed"), std::string::npos);
}

TEST_F(PrintRunTest, MoveThatNeverArrivesTimesOut) {
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  advance(9s, run);
  EXPECT_EQ(run.state(), PrintRunState::Moving);
  advance(2s, run);
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
}

TEST_F(PrintRunTest, LinkLossWhileMovingFaultsTheRun) {
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  device.state.linkUp = false;
  advance(10ms, run);
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_NE(run.lastProblem().find("link to fake platform is down"), std::string::npos);
}

TEST_F(PrintRunTest, RegionDoneIsAcceptedOnlyForTheRegionThatPrints) {
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  EXPECT_FALSE(run.regionDone(0).ok());  // still moving
  settle(run);
  EXPECT_FALSE(run.regionDone(1).ok());
  EXPECT_EQ(run.state(), PrintRunState::Printing);
  EXPECT_TRUE(run.regionDone(0).ok());
}

TEST_F(PrintRunTest, EmptyRunCannotStart) {
  PrintRun run(device, {}, options());
  EXPECT_FALSE(run.start().ok());
  EXPECT_EQ(run.state(), PrintRunState::Idle);
}

TEST_F(PrintRunTest, EveryTransitionIsLoggedWithTheClocksTime) {
  PrintRun run(device, threeSteps(), options());
  std::vector<PrintRunLogEntry> seen;
  run.setLogCallback([&](const PrintRunLogEntry& entry) { seen.push_back(entry); });
  const auto wallAtStart = wall;
  ASSERT_TRUE(run.start().ok());
  settle(run);
  ASSERT_EQ(seen.size(), 3u);  // moving, settling, printing
  EXPECT_EQ(seen[0].state, PrintRunState::Moving);
  EXPECT_EQ(seen[0].wallTime, wallAtStart);
  EXPECT_EQ(seen[0].elapsed, 0ms);
  EXPECT_EQ(seen[1].state, PrintRunState::Settling);
  EXPECT_EQ(seen[1].elapsed, 10ms);
  EXPECT_EQ(seen[2].state, PrintRunState::Printing);
  EXPECT_EQ(seen[2].elapsed, 510ms);
  EXPECT_NE(seen[2].message.find("step 1/3 (region_1.stl, rotary 0.00 deg)"), std::string::npos) << seen[2].message;
  EXPECT_EQ(run.log().size(), seen.size());
}

TEST_F(PrintRunTest, PauseLogsMotionStoppedOnlyOnceTheDeviceConfirmsTheStop) {
  device.stopMode = FakePositioner::StopMode::WaitsForTheLink;
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(run.pause().ok());
  EXPECT_EQ(run.state(), PrintRunState::Paused);
  for (int i = 0; i < 5; ++i) advance(100ms, run);
  EXPECT_FALSE(logMentions(run, "motion stopped")) << run.log().back().message;
  EXPECT_TRUE(logMentions(run, "waiting for it to confirm"));
  device.confirmStop();
  advance(10ms, run);
  EXPECT_NE(run.log().back().message.find("motion stopped: fake platform confirmed the stop"), std::string::npos)
      << run.log().back().message;
  EXPECT_EQ(run.state(), PrintRunState::Paused);
}

TEST_F(PrintRunTest, StopStillUnconfirmedAfterASecondIsLoggedOnceAsAWarning) {
  device.stopMode = FakePositioner::StopMode::WaitsForTheLink;
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(run.pause().ok());
  device.state.linkUp = false;
  advance(900ms, run);
  EXPECT_FALSE(logMentions(run, "has not confirmed the stop"));
  advance(200ms, run);
  EXPECT_NE(run.log().back().message.find("fake platform has not confirmed the stop after 1000 ms (the link is down)"),
            std::string::npos)
      << run.log().back().message;
  const std::size_t entries = run.log().size();
  for (int i = 0; i < 5; ++i) advance(1s, run);
  EXPECT_EQ(run.log().size(), entries);
}

TEST_F(PrintRunTest, ResumeIsRefusedUntilTheDeviceConfirmedTheStop) {
  device.stopMode = FakePositioner::StopMode::WaitsForTheLink;
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(run.pause().ok());
  const core::Status early = run.resume();
  ASSERT_FALSE(early.ok());
  EXPECT_NE(early.error().message.find("cannot resume yet"), std::string::npos) << early.error().message;
  EXPECT_EQ(run.state(), PrintRunState::Paused);
  EXPECT_EQ(device.moves.size(), 1u);
  device.confirmStop();
  ASSERT_TRUE(run.resume().ok());
  EXPECT_EQ(run.state(), PrintRunState::Moving);
  EXPECT_EQ(device.moves.size(), 2u);
  EXPECT_FALSE(device.state.stopLatched);
  EXPECT_TRUE(logMentions(run, "motion stopped"));  // told before the retry, not skipped
}

TEST_F(PrintRunTest, RefusedStopOnPauseFaultsTheRunAndSaysToUseTheEStop) {
  device.stopMode = FakePositioner::StopMode::Refused;
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  const core::Status paused = run.pause();
  ASSERT_FALSE(paused.ok());
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_NE(run.log().back().message.find("the stop was refused"), std::string::npos) << run.log().back().message;
  EXPECT_NE(run.log().back().message.find("E-STOP"), std::string::npos);
  EXPECT_NE(run.lastProblem().find("not connected"), std::string::npos) << run.lastProblem();
  advance(100ms, run);
  EXPECT_FALSE(logMentions(run, "motion stopped"));
}

TEST_F(PrintRunTest, AbortWithARefusedStopIsFinalButSaysTheDeviceMayStillMove) {
  device.stopMode = FakePositioner::StopMode::Refused;
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(run.abort().ok());
  EXPECT_EQ(run.state(), PrintRunState::Aborted);
  EXPECT_NE(run.log().back().message.find("may still move"), std::string::npos) << run.log().back().message;
  EXPECT_FALSE(logMentions(run, "motion stopped"));
}

TEST_F(PrintRunTest, LinkLossFaultLogsTheStopOnlyWhenTheDeviceConfirmsItAfterReconnecting) {
  device.stopMode = FakePositioner::StopMode::WaitsForTheLink;
  PrintRun run(device, threeSteps(), options());
  ASSERT_TRUE(run.start().ok());
  device.state.linkUp = false;
  advance(10ms, run);
  ASSERT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_EQ(device.stops, 1);
  EXPECT_TRUE(device.state.stopLatched);
  advance(300ms, run);
  EXPECT_FALSE(logMentions(run, "motion stopped"));
  device.state.linkUp = true;
  device.confirmStop();
  advance(10ms, run);
  EXPECT_TRUE(logMentions(run, "motion stopped"));
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
}

}  // namespace
}  // namespace multidir::hardware

// The print run with a printer: against each printer simulator (Moonraker, OctoPrint) and the Modbus device
// simulator on 127.0.0.1 (both record every command with the clock the test injects), plus interlock cases
// with test doubles.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <thread>

#include "multidir/hardware/device_simulator.h"
#include "multidir/hardware/print_run.h"
#include "multidir/hardware/rotary_platform.h"
#include "printer_test_support.h"

namespace multidir::hardware {
namespace {

using namespace test;
using Clock = std::chrono::steady_clock;

constexpr int kRotaryMove = 4;
constexpr int kRotaryEmergencyStop = 6;

bool logMentions(const PrintRun& run, const std::string& text) {
  return std::any_of(run.log().begin(), run.log().end(),
                     [&](const PrintRunLogEntry& e) { return e.message.find(text) != std::string::npos; });
}

std::string wholeLog(const PrintRun& run) {
  std::string text;
  for (const auto& e : run.log()) text += e.message + "\n";
  return text;
}

class PrintRunWithPrinterTest : public ::testing::TestWithParam<PrinterProtocol> {
 protected:
  // One clock for both simulators' records, the links and the run.
  std::function<Clock::time_point()> clock = [] { return Clock::now(); };

  void SetUp() override {
    SimulatorOptions deviceOptions;
    deviceOptions.robot = false;
    deviceOptions.steadyNow = clock;
    devices = std::make_unique<DeviceSimulator>(deviceOptions);
    ASSERT_TRUE(devices->start().ok());
    RotaryPlatformOptions options;
    options.connection = fastSettings(devices->port(), 1);
    options.machine.kind = core::MachineKind::RotaryPlatform;
    options.machine.minAngleDegrees = -90.0;
    options.machine.maxAngleDegrees = 90.0;
    options.machine.angleStepDegrees = 1.0;
    options.speedDegreesPerSecond = 300.0;
    platform = std::make_unique<RotaryPlatform>(options);
    ASSERT_TRUE(platform->connect().ok());
    ASSERT_TRUE(outcome(platform->enable()).ok());
    ASSERT_TRUE(eventually([&] { return platform->status().enabled; }));
    ASSERT_TRUE(outcome(platform->home()).ok());
    ASSERT_TRUE(eventually([&] { return platform->status().homed && !platform->status().homing; }));
    positioner = makePositioner(*platform);
    const auto dir = std::filesystem::path(testing::TempDir()) / "print-run-printer";
    for (int i = 1; i <= 3; ++i)
      gcodes.push_back(writeFile(dir / ("step-0" + std::to_string(i) + ".gcode"), shortGcode()));
  }

  void startPrinter(double speed) {
    PrinterSimulatorOptions options;
    options.speed = speed;
    options.steadyNow = clock;
    printerSim = printerSimulator(GetParam(), options);
    ASSERT_TRUE(printerSim->start().ok());
    PrinterLinkOptions linkOptions = fastPrinterOptions();
    linkOptions.steadyNow = clock;
    printer = printerLinkTo(GetParam(), printerSim->port(), linkOptions);
    ASSERT_TRUE(printer->connect().ok());
  }

  std::vector<PrintStep> steps() const {
    return {{PlatformOrientation::rotary(0.0), "region 1", gcodes[0]},
            {PlatformOrientation::rotary(30.0), "region 2", gcodes[1]},
            {PlatformOrientation::rotary(-45.0), "region 3", gcodes[2]}};
  }

  PrintRunOptions runOptions() const {
    PrintRunOptions o;
    o.settleTime = 20ms;
    o.moveTimeout = 5000ms;
    o.steadyNow = clock;
    return o;
  }

  // Ticks every 2 ms until `condition` holds; at most `ticks` ticks.
  bool tickUntil(PrintRun& run, const std::function<bool()>& condition, int ticks = 3000) {
    for (int i = 0; i < ticks; ++i) {
      run.tick();
      if (condition()) return true;
      std::this_thread::sleep_for(2ms);
    }
    return condition();
  }

  // Ticks until the printer simulator is printing the run's current step (past its heating).
  bool untilPrinting(PrintRun& run) {
    return tickUntil(run, [&] {
      const SimulatedPrinterState s = printerSim->state();
      return run.state() == PrintRunState::Printing && s.jobState == "printing" && s.progress > 0.1;
    });
  }

  std::vector<SimulatedCommandRecord> platformCommandsSince(Clock::time_point since) const {
    std::vector<SimulatedCommandRecord> out;
    for (const auto& r : devices->commandLog())
      if (r.at >= since) out.push_back(r);
    return out;
  }

  // A fault during printing pauses the run with `message` and nothing moves: no platform command from the
  // moment the printer printed until well after the pause.
  void expectPausedWithoutMotion(PrintRun& run, Clock::time_point printing, const std::string& message) {
    ASSERT_TRUE(tickUntil(run, [&] { return run.state() != PrintRunState::Printing; })) << wholeLog(run);
    EXPECT_EQ(run.state(), PrintRunState::Paused) << wholeLog(run);
    EXPECT_TRUE(run.printInterrupted());
    EXPECT_NE(run.lastProblem().find(message), std::string::npos) << run.lastProblem();
    tickUntil(
        run, [] { return false; }, 50);  // 100 ms more: still nothing may move
    EXPECT_TRUE(platformCommandsSince(printing).empty());
    EXPECT_EQ(run.state(), PrintRunState::Paused);
  }

  std::unique_ptr<DeviceSimulator> devices;
  std::unique_ptr<RotaryPlatform> platform;
  std::unique_ptr<Positioner> positioner;
  std::unique_ptr<PrinterSimulator> printerSim;
  std::unique_ptr<PrinterLink> printer;
  std::vector<std::string> gcodes;
};

INSTANTIATE_TEST_SUITE_P(Protocols, PrintRunWithPrinterTest,
                         ::testing::Values(PrinterProtocol::Moonraker, PrinterProtocol::OctoPrint), protocolName);

TEST_P(PrintRunWithPrinterTest, RunsEveryStepOnThePlatformAndThePrinterToCompletion) {
  startPrinter(400.0);
  PrintRun run(*positioner, steps(), runOptions(), printer.get());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(tickUntil(
      run, [&] { return run.state() == PrintRunState::Completed; }, 4000))
      << wholeLog(run);
  std::vector<std::string> completed;
  for (const auto& e : printerSim->jobEvents())
    if (e.state == "complete") completed.push_back(e.file);
  EXPECT_EQ(completed, (std::vector<std::string>{"step-01.gcode", "step-02.gcode", "step-03.gcode"}));
  EXPECT_EQ(
      countRequests(printerSim->requests(), [&](const PrinterRequestRecord& r) { return isStart(GetParam(), r); }), 3);
  EXPECT_NEAR(devices->rotaryState().angleDegrees, -45.0, 0.05);
}

TEST_P(PrintRunWithPrinterTest, NoPlatformCommandReachesTheDeviceWhileThePrinterPrints) {
  startPrinter(400.0);
  PrintRun run(*positioner, steps(), runOptions(), printer.get());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(tickUntil(
      run, [&] { return run.state() == PrintRunState::Completed; }, 4000))
      << wholeLog(run);
  // Each job from its start to its end, on the clock both simulators share.
  const auto events = printerSim->jobEvents();
  int intervals = 0;
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (events[i].state != "printing") continue;
    const Clock::time_point from = events[i].at;
    const Clock::time_point to = i + 1 < events.size() ? events[i + 1].at : Clock::time_point::max();
    ++intervals;
    for (const auto& command : devices->commandLog())
      EXPECT_FALSE(command.at >= from && command.at <= to)
          << "platform command " << command.command << " while " << events[i].file << " printed";
  }
  EXPECT_EQ(intervals, 3);
  // And every start reached the printer after the platform's move of its step.
  std::vector<Clock::time_point> moves;
  for (const auto& command : devices->commandLog())
    if (command.command == kRotaryMove) moves.push_back(command.at);
  std::vector<Clock::time_point> starts;
  for (const auto& r : printerSim->requests())
    if (isStart(GetParam(), r)) starts.push_back(r.at);
  ASSERT_EQ(moves.size(), 3u);
  ASSERT_EQ(starts.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_GT(starts[k], moves[k]);
  for (std::size_t k = 0; k + 1 < 3; ++k) EXPECT_LT(starts[k], moves[k + 1]);
}

TEST_P(PrintRunWithPrinterTest, ThermalRunawayPausesTheRunWithTheTemperatureAndNothingMoves) {
  startPrinter(20.0);
  PrintRun run(*positioner, steps(), runOptions(), printer.get());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(untilPrinting(run)) << wholeLog(run);
  const Clock::time_point printing = clock();
  printerSim->injectThermalRunaway();
  expectPausedWithoutMotion(run, printing, "temperature fault: the extruder reads");
  EXPECT_EQ(run.currentStep(), 0u);
}

TEST_P(PrintRunWithPrinterTest, ALostLinkPausesTheRunAndResumeFollowsThePrinterAgain) {
  startPrinter(20.0);
  PrintRun run(*positioner, steps(), runOptions(), printer.get());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(untilPrinting(run)) << wholeLog(run);
  const Clock::time_point printing = clock();
  printerSim->dropLink();
  expectPausedWithoutMotion(run, printing, "is lost");
  EXPECT_FALSE(run.resume().ok());  // still lost
  printerSim->restoreLink();
  ASSERT_TRUE(eventually([&] { return !printer->status().linkLost; }));
  ASSERT_TRUE(run.resume().ok()) << wholeLog(run);
  EXPECT_EQ(run.state() == PrintRunState::Printing || run.state() == PrintRunState::Moving, true);
  ASSERT_TRUE(tickUntil(run, [&] { return run.currentStep() == 1; })) << wholeLog(run);
}

TEST_P(PrintRunWithPrinterTest, AJobCancelledOnThePrinterPausesTheRunAndNothingMoves) {
  startPrinter(20.0);
  PrintRun run(*positioner, steps(), runOptions(), printer.get());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(untilPrinting(run)) << wholeLog(run);
  const Clock::time_point printing = clock();
  printerSim->cancelJobOnPrinter();
  expectPausedWithoutMotion(run, printing, "step-01.gcode was cancelled on the printer");
  // The job cannot be resumed; the operator finishes the region by hand and goes on.
  const core::Status resumed = run.resume();
  ASSERT_FALSE(resumed.ok());
  EXPECT_NE(resumed.error().message.find("Region done"), std::string::npos) << resumed.error().message;
  ASSERT_TRUE(run.regionDone(0).ok());
  EXPECT_EQ(run.state(), PrintRunState::Moving);
}

TEST_P(PrintRunWithPrinterTest, RepliesSlowerThanTheLinksTimeoutPauseTheRunAndNothingMoves) {
  startPrinter(20.0);
  PrintRun run(*positioner, steps(), runOptions(), printer.get());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(untilPrinting(run)) << wholeLog(run);
  const Clock::time_point printing = clock();
  printerSim->setReplyDelay(1300ms);  // the link waits 1000 ms
  expectPausedWithoutMotion(run, printing, "is lost");
  printerSim->setReplyDelay(0ms);
}

TEST_P(PrintRunWithPrinterTest, EmergencyStopDuringPrintingReachesBothDevicesWithin200Ms) {
  startPrinter(20.0);
  PrintRun run(*positioner, steps(), runOptions(), printer.get());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(untilPrinting(run)) << wholeLog(run);
  const Clock::time_point called = clock();
  ASSERT_TRUE(run.emergencyStop().ok());
  EXPECT_EQ(run.state(), PrintRunState::Aborted);
  ASSERT_TRUE(tickUntil(run, [&] { return !run.stopUnconfirmed(); })) << wholeLog(run);
  Clock::time_point platformAt = Clock::time_point::max();
  for (const auto& command : devices->commandLog())
    if (command.command == kRotaryEmergencyStop && command.at >= called) platformAt = std::min(platformAt, command.at);
  Clock::time_point printerAt = Clock::time_point::max();
  for (const auto& r : printerSim->requests())
    if (isEmergencyStop(GetParam(), r) && r.at >= called) printerAt = std::min(printerAt, r.at);
  ASSERT_NE(platformAt, Clock::time_point::max());
  ASSERT_NE(printerAt, Clock::time_point::max());
  EXPECT_LE(platformAt - called, 200ms);
  EXPECT_LE(printerAt - called, 200ms);
  const auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
  RecordProperty("platformEmergencyStopMs", std::to_string(ms(platformAt - called)));
  RecordProperty("printerEmergencyStopMs", std::to_string(ms(printerAt - called)));
  std::cout << "[ measured ] e-stop reached the platform after " << ms(platformAt - called) << " ms, the printer after "
            << ms(printerAt - called) << " ms\n";
  EXPECT_EQ(printerSim->state().firmwareState, "shutdown");
  EXPECT_TRUE(logMentions(run, "confirmed the emergency stop"));
}

// Interlocks, with doubles whose state the test sets.

class StillPositioner : public Positioner {
 public:
  core::Status startMove(const PlatformOrientation&) override {
    ++moves;
    return core::Done{};
  }
  core::Status stopMotion() override { return core::Done{}; }
  core::Status emergencyStop() override { return core::Done{}; }
  core::Status clearStop() override { return core::Done{}; }
  PositionerSnapshot snapshot() const override { return state; }
  std::string name() const override { return "test platform"; }
  int moves = 0;
  PositionerSnapshot state = [] {
    PositionerSnapshot s;
    s.linkUp = true;
    s.reached = true;
    return s;
  }();
};

class ScriptedPrinter : public PrinterLink {
 public:
  core::Status connect() override { return core::Done{}; }
  void disconnect() override {}
  std::future<core::Status> upload(const std::string&, const std::string& name) override {
    uploads.push_back(name);
    return done();
  }
  std::future<core::Status> startPrint(const std::string&) override { return done(); }
  std::future<core::Status> pausePrint() override { return done(); }
  std::future<core::Status> resumePrint() override { return done(); }
  std::future<core::Status> cancelPrint() override { return done(); }
  std::future<core::Status> emergencyStop() override { return done(); }
  core::Status clearStop() override { return core::Done{}; }
  PrinterStatus status() const override { return state; }
  std::string name() const override { return "test printer"; }

  static std::future<core::Status> done() {
    std::promise<core::Status> p;
    p.set_value(core::Done{});
    return p.get_future();
  }
  std::vector<std::string> uploads;
  PrinterStatus state = [] {
    PrinterStatus s;
    s.link = LinkState::Connected;
    s.linkLost = false;
    s.state = PrinterJobState::Standby;
    s.polls = 1;
    return s;
  }();
};

PrintRunOptions immediate() {
  PrintRunOptions o;
  o.settleTime = 0ms;
  return o;
}

TEST(PrintRunInterlock, ThePlatformIsNotCommandedWhileThePrinterReportsAJobPrinting) {
  StillPositioner platform;
  ScriptedPrinter printer;
  printer.state.state = PrinterJobState::Printing;
  printer.state.currentFile = "someone-elses.gcode";
  PrintRun run(platform, {{PlatformOrientation::rotary(0.0), "r1", "/tmp/step-01.gcode"}}, immediate(), &printer);
  ASSERT_TRUE(run.start().ok());
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_EQ(platform.moves, 0);
  EXPECT_NE(run.lastProblem().find("does not move while the printer reports a job printing"), std::string::npos)
      << run.lastProblem();
}

TEST(PrintRunInterlock, ThePlatformIsNotCommandedWhileThePrintersStateIsUnknown) {
  StillPositioner platform;
  ScriptedPrinter printer;
  printer.state.linkLost = true;
  PrintRun run(platform, {{PlatformOrientation::rotary(0.0), "r1", "/tmp/step-01.gcode"}}, immediate(), &printer);
  ASSERT_TRUE(run.start().ok());
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_EQ(platform.moves, 0);
}

TEST(PrintRunInterlock, ThePrinterIsNotStartedWhileThePlatformReportsMotion) {
  StillPositioner platform;
  ScriptedPrinter printer;
  PrintRun run(platform, {{PlatformOrientation::rotary(0.0), "r1", "/tmp/step-01.gcode"}}, immediate(), &printer);
  ASSERT_TRUE(run.start().ok());
  run.tick();  // reached: settling
  ASSERT_EQ(run.state(), PrintRunState::Settling);
  platform.state.moving = true;  // reached, yet still moving (a vibration, a second client)
  run.tick();
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_TRUE(printer.uploads.empty());
  EXPECT_NE(run.lastProblem().find("not at rest"), std::string::npos) << run.lastProblem();
}

TEST(PrintRunInterlock, AStepWithoutGcodeStaysWithTheOperatorsRegionDone) {
  StillPositioner platform;
  ScriptedPrinter printer;
  PrintRun run(platform, {{PlatformOrientation::rotary(0.0), "r1"}}, immediate(), &printer);
  ASSERT_TRUE(run.start().ok());
  run.tick();
  run.tick();
  ASSERT_EQ(run.state(), PrintRunState::Printing);
  EXPECT_TRUE(printer.uploads.empty());
  ASSERT_TRUE(run.regionDone(0).ok());
  EXPECT_EQ(run.state(), PrintRunState::Completed);
}

TEST(PrintRunInterlock, ARegionThePrinterPrintsCannotBeDeclaredDoneByHand) {
  StillPositioner platform;
  ScriptedPrinter printer;
  PrintRun run(platform, {{PlatformOrientation::rotary(0.0), "r1", "/tmp/step-01.gcode"}}, immediate(), &printer);
  ASSERT_TRUE(run.start().ok());
  run.tick();
  run.tick();
  ASSERT_EQ(run.state(), PrintRunState::Printing);
  ASSERT_EQ(printer.uploads, std::vector<std::string>{"step-01.gcode"});
  EXPECT_FALSE(run.regionDone(0).ok());
}

}  // namespace
}  // namespace multidir::hardware

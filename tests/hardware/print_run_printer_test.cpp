// The print run with a printer: against each printer simulator (Moonraker and OctoPrint on 127.0.0.1, Marlin
// on a pseudo-terminal) and the Modbus device simulator (all record every command with the clock the test
// injects), plus interlock cases with test doubles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "multidir/core/search/decompose.h"
#include "multidir/hardware/content_digest.h"
#include "multidir/hardware/device_simulator.h"
#include "multidir/hardware/print_run.h"
#include "multidir/hardware/rotary_platform.h"
#include "printer_test_support.h"
#include "scripted_http_server.h"
#include "support/test_models.h"

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
    const auto dir =
        std::filesystem::path(testing::TempDir()) / (std::string("print-run-printer-") + protocolText(GetParam()));
    for (int i = 1; i <= 3; ++i)
      gcodes.push_back(writeFile(dir / ("step-0" + std::to_string(i) + ".gcode"), shortGcode()));
  }

  void startPrinter(double speed, PrinterFault midJobFault = PrinterFault::None) {
    printerSim = simulatedPrinter(GetParam(), speed, clock, midJobFault);
    PrinterLinkOptions linkOptions = fastPrinterOptions();
    linkOptions.steadyNow = clock;
    printer = printerSim->link(linkOptions);
    ASSERT_TRUE(printer->connect().ok());
  }

  // The printer started at `speed` (startPrinter) and a run of steps() with it, not started yet.
  PrintRun runWithPrinter(double speed, PrinterFault midJobFault = PrinterFault::None) {
    startPrinter(speed, midJobFault);
    return PrintRun(*positioner, steps(), runOptions(), printer.get());
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

  bool tickUntilCompleted(PrintRun& run, int ticks) {
    return tickUntil(
        run, [&] { return run.state() == PrintRunState::Completed; }, ticks);
  }

  // Ticks until the printer simulator is printing the run's current step (past its heating).
  bool untilPrinting(PrintRun& run) {
    return tickUntil(run, [&] { return run.state() == PrintRunState::Printing && printerSim->printingPastHeating(); });
  }

  // Ticks until the first job's start reached the printer; when it did (Clock::time_point::max() if it never did).
  Clock::time_point untilFirstStart(PrintRun& run) {
    const bool started = tickUntil(run, [&] { return !printerSim->starts().empty(); });
    EXPECT_TRUE(started) << wholeLog(run);
    return started ? printerSim->starts().front() : Clock::time_point::max();
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

  // No platform command while any job printed, on the clock both simulators share.
  void expectNoPlatformCommandWhileAJobPrinted(std::size_t jobs) {
    const auto intervals = printerSim->jobs();
    EXPECT_EQ(intervals.size(), jobs);
    for (const auto& job : intervals)
      for (const auto& command : devices->commandLog())
        EXPECT_FALSE(command.at >= job.from && command.at <= job.to) << "platform command " << command.command;
  }

  std::unique_ptr<DeviceSimulator> devices;
  std::unique_ptr<RotaryPlatform> platform;
  std::unique_ptr<Positioner> positioner;
  std::unique_ptr<SimulatedPrinterUnderTest> printerSim;
  std::unique_ptr<PrinterLink> printer;
  std::vector<std::string> gcodes;
};

INSTANTIATE_TEST_SUITE_P(Protocols, PrintRunWithPrinterTest, allProtocols(), protocolName);

TEST_P(PrintRunWithPrinterTest, RunsEveryStepOnThePlatformAndThePrinterToCompletion) {
  PrintRun run = runWithPrinter(400.0);
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(tickUntilCompleted(run, 4000)) << wholeLog(run);
  EXPECT_EQ(printerSim->completedJobs(), 3);
  EXPECT_EQ(printerSim->starts().size(), 3u);
  EXPECT_NEAR(devices->rotaryState().angleDegrees, -45.0, 0.05);
}

TEST_P(PrintRunWithPrinterTest, NoPlatformCommandReachesTheDeviceWhileThePrinterPrints) {
  PrintRun run = runWithPrinter(400.0);
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(tickUntilCompleted(run, 4000)) << wholeLog(run);
  expectNoPlatformCommandWhileAJobPrinted(3);
  // And every start reached the printer after the platform's move of its step.
  std::vector<Clock::time_point> moves;
  for (const auto& command : devices->commandLog())
    if (command.command == kRotaryMove) moves.push_back(command.at);
  const std::vector<Clock::time_point> starts = printerSim->starts();
  ASSERT_EQ(moves.size(), 3u);
  ASSERT_EQ(starts.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_GT(starts[k], moves[k]);
  for (std::size_t k = 0; k + 1 < 3; ++k) EXPECT_LT(starts[k], moves[k + 1]);
}

// The two faults below are injected by the simulator itself half-way through the first job: a test thread
// that injected them once it saw the job printing could, on a loaded machine, see the first job only after it
// had ended, and fault the second.
TEST_P(PrintRunWithPrinterTest, ThermalRunawayPausesTheRunWithTheTemperatureAndNothingMoves) {
  PrintRun run = runWithPrinter(20.0, PrinterFault::ThermalRunaway);
  ASSERT_TRUE(run.start().ok());
  const Clock::time_point printing = untilFirstStart(run);
  // The run's own check (15 C above the target) sees the climb before either firmware gives up.
  expectPausedWithoutMotion(run, printing, "temperature fault: the extruder reads");
  EXPECT_EQ(run.currentStep(), 0u);
}

TEST_P(PrintRunWithPrinterTest, ALostLinkPausesTheRunAndResumeFollowsThePrinterAgain) {
  PrintRun run = runWithPrinter(20.0);
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
  PrintRun run = runWithPrinter(20.0, PrinterFault::CancelledOnPrinter);
  ASSERT_TRUE(run.start().ok());
  const Clock::time_point printing = untilFirstStart(run);
  expectPausedWithoutMotion(run, printing, "step-01.gcode was cancelled on the printer");
  // The job cannot be resumed; the operator finishes the region by hand and goes on.
  const core::Status resumed = run.resume();
  ASSERT_FALSE(resumed.ok());
  EXPECT_NE(resumed.error().message.find("Region done"), std::string::npos) << resumed.error().message;
  ASSERT_TRUE(run.regionDone(0).ok());
  EXPECT_EQ(run.state(), PrintRunState::Moving);
}

TEST_P(PrintRunWithPrinterTest, RepliesSlowerThanTheLinksTimeoutPauseTheRunAndNothingMoves) {
  PrintRun run = runWithPrinter(20.0);
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(untilPrinting(run)) << wholeLog(run);
  const Clock::time_point printing = clock();
  printerSim->setReplyDelay(1300ms);  // the links wait 1000 ms (Moonraker, OctoPrint) or 400 ms (Marlin)
  expectPausedWithoutMotion(run, printing, "is lost");
  printerSim->setReplyDelay(0ms);
}

TEST_P(PrintRunWithPrinterTest, EmergencyStopDuringPrintingReachesBothDevicesWithin200Ms) {
  PrintRun run = runWithPrinter(20.0);
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
  for (const auto& at : printerSim->emergencyStops())
    if (at >= called) printerAt = std::min(printerAt, at);
  ASSERT_NE(platformAt, Clock::time_point::max());
  ASSERT_NE(printerAt, Clock::time_point::max());
  EXPECT_LE(platformAt - called, 200ms);
  EXPECT_LE(printerAt - called, 200ms);
  const auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
  RecordProperty("platformEmergencyStopMs", std::to_string(ms(platformAt - called)));
  RecordProperty("printerEmergencyStopMs", std::to_string(ms(printerAt - called)));
  std::cout << "[ measured ] " << protocolText(GetParam()) << ": e-stop reached the platform after "
            << ms(platformAt - called) << " ms, the printer after " << ms(printerAt - called) << " ms\n";
  EXPECT_TRUE(printerSim->halted());
  EXPECT_TRUE(logMentions(run, "confirmed the emergency stop"));
}

// Issue 24: a stop while the platform turned between two steps left the heaters as the previous step's
// G-code had left them (on, for the next step): the run only cancels a job it is printing.
TEST_P(PrintRunWithPrinterTest, AnAbortDuringATurnSwitchesTheHeatersOff) {
  startPrinter(400.0);
  const auto dir =
      std::filesystem::path(testing::TempDir()) / (std::string("heaters-left-on-") + protocolText(GetParam()));
  const std::string hot = writeFile(dir / "step-01.gcode", heatersLeftOnGcode());
  PrintRun run(*positioner,
               {{PlatformOrientation::rotary(0.0), "region 1", hot},
                {PlatformOrientation::rotary(-90.0), "region 2", writeFile(dir / "step-02.gcode", shortGcode())}},
               runOptions(), printer.get());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(tickUntil(run, [&] { return run.currentStep() == 1 && run.state() == PrintRunState::Moving; }))
      << wholeLog(run);
  EXPECT_GT(printerSim->bed().targetC, 59.0);  // the first step left them on
  EXPECT_GT(printerSim->extruder().targetC, 199.0);
  ASSERT_TRUE(run.abort().ok());
  ASSERT_TRUE(tickUntil(run, [&] { return !run.stopUnconfirmed(); })) << wholeLog(run);
  EXPECT_TRUE(logMentions(run, "switched the heaters off")) << wholeLog(run);
  // Marlin answers M140 once it is queued: the simulated heater follows a moment later.
  EXPECT_TRUE(tickUntil(run, [&] { return printerSim->extruder().targetC == 0.0 && printerSim->bed().targetC == 0.0; }))
      << "extruder target " << printerSim->extruder().targetC << " C, bed " << printerSim->bed().targetC << " C";
  EXPECT_FALSE(run.stepBegun());  // the second step was never started: --from 2 is true
}

TEST_P(PrintRunWithPrinterTest, AnAbortWhilePrintingCancelsTheJobAndSwitchesTheHeatersOff) {
  PrintRun run = runWithPrinter(20.0);
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(untilPrinting(run)) << wholeLog(run);
  // The run has read the printer's progress of the step since (it reads it as it ticks).
  ASSERT_TRUE(tickUntil(run, [&] { return run.stepProgress() > 0.0; })) << wholeLog(run);
  ASSERT_TRUE(run.abort().ok());
  ASSERT_TRUE(tickUntil(run, [&] { return !run.stopUnconfirmed(); })) << wholeLog(run);
  EXPECT_TRUE(logMentions(run, "switched the heaters off")) << wholeLog(run);
  EXPECT_TRUE(tickUntil(run, [&] { return printerSim->extruder().targetC == 0.0 && printerSim->bed().targetC == 0.0; }))
      << "extruder target " << printerSim->extruder().targetC << " C, bed " << printerSim->bed().targetC << " C";
  EXPECT_TRUE(run.stepBegun());  // part of region 1 is on the platform
}

// The kitten decomposed for this rotary platform (4-DOF about x, up y, greedy search), once per test process.
const core::Decomposition& kittenPlan() {
  static const core::Decomposition plan = [] {
    core::MachineSpec machine;
    machine.kind = core::MachineKind::RotaryPlatform;
    machine.up = core::Vec3::UnitY();
    machine.rotationAxis = core::Vec3::UnitX();
    machine.minAngleDegrees = -90.0;
    machine.maxAngleDegrees = 90.0;
    core::SearchOptions options;
    options.scheme = core::SearchScheme::Greedy;  // a real plan of the kitten in well under a second
    core::JobContext job;
    auto result = core::decompose(multidir::test::loadSharedModel("kitten.off"), machine, options, job);
    if (!result) throw std::runtime_error(result.error().describe());
    return *result;
  }();
  return plan;
}

// A region as a printer would be sent it: heat, then 0.5 mm layers along its printing direction, each the
// outline of the region's extent across that direction at 100 mm/s.
std::string regionGcode(const core::Region& region) {
  const core::Vec3 d = region.printingDirection.normalized();
  const core::Vec3 u = d.unitOrthogonal();
  const core::Vec3 v = d.cross(u);
  double lo[3] = {1e300, 1e300, 1e300};
  double hi[3] = {-1e300, -1e300, -1e300};
  for (const core::Vec3& p : region.mesh.vertices) {
    const double c[3] = {p.dot(d), p.dot(u), p.dot(v)};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], c[k]);
      hi[k] = std::max(hi[k], c[k]);
    }
  }
  const auto mm = [](double x) { return std::to_string(std::round(x * 1000.0) / 1000.0); };
  const double w = hi[1] - lo[1];
  const double h = hi[2] - lo[2];
  std::string text = "; region printed along its direction\nM104 S200\nM109 S200\nG90\nM83\nG1 F6000\n";
  for (double z = 0.5; z <= hi[0] - lo[0] + 1e-9; z += 0.5) {
    text += "G1 X0 Y0 Z" + mm(z) + "\n";
    text += "G1 X" + mm(w) + " Y0 E" + mm(w * 0.05) + "\n";
    text += "G1 X" + mm(w) + " Y" + mm(h) + " E" + mm(h * 0.05) + "\n";
    text += "G1 X0 Y" + mm(h) + " E" + mm(w * 0.05) + "\n";
    text += "G1 X0 Y0 E" + mm(h * 0.05) + " ; layer done\n";
  }
  return text + "M104 S0\n";
}

TEST_P(PrintRunWithPrinterTest, AWholeKittenJobRunsEveryStepAndThePlatformNeverMovesWhileThePrinterPrints) {
  const core::Decomposition& plan = kittenPlan();
  ASSERT_GE(plan.regions.size(), 2u);
  const auto dir = std::filesystem::path(testing::TempDir()) / (std::string("kitten-job-") + protocolText(GetParam()));
  std::vector<PrintStep> kittenSteps;
  std::vector<std::string> programs;
  for (std::size_t k = 0; k < plan.regions.size(); ++k) {
    const std::string name = "step-0" + std::to_string(k + 1) + ".gcode";
    programs.push_back(regionGcode(plan.regions[k]));
    kittenSteps.push_back({PlatformOrientation::rotary(plan.regions[k].angles.rotaryDegrees),
                           "region " + std::to_string(k + 1), writeFile(dir / name, programs.back())});
  }
  startPrinter(20000.0);
  PrintRun run(*positioner, kittenSteps, runOptions(), printer.get());
  const Clock::time_point began = Clock::now();
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(tickUntilCompleted(run, 10000)) << wholeLog(run);
  const double seconds = std::chrono::duration<double>(Clock::now() - began).count();
  EXPECT_EQ(printerSim->completedJobs(), static_cast<int>(plan.regions.size()));
  expectNoPlatformCommandWhileAJobPrinted(plan.regions.size());
  EXPECT_NEAR(devices->rotaryState().angleDegrees, plan.regions.back().angles.rotaryDegrees, 0.05);
  if (auto* marlin = dynamic_cast<SimulatedMarlin*>(printerSim.get())) {
    // Every line of every step was executed once, in order.
    std::vector<std::string> expected;
    for (const std::string& program : programs)
      for (const std::string& command : gcodeCommands(program)) expected.push_back(command);
    std::vector<std::string> executed;
    for (const auto& e : marlin->simulator().executed())
      if (e.command != "M105" && e.command != "M110 N0" && e.command != "M400" && e.command != "M114")
        executed.push_back(e.command);
    EXPECT_EQ(executed.size(), expected.size());
    EXPECT_TRUE(executed == expected);
    std::cout << "[ measured ] kitten job: " << plan.regions.size() << " steps, " << expected.size()
              << " G-code lines streamed to the Marlin simulator, the whole run (platform moves included) in "
              << seconds << " s\n";
  }
}

// Issue 28, with the Marlin link only: its simulator plays what a serial printer can get wrong.
class PrintRunWithMarlinTest : public PrintRunWithPrinterTest {
 protected:
  MarlinSimulator& marlin() { return dynamic_cast<SimulatedMarlin&>(*printerSim).simulator(); }
  std::size_t executedMoves() const {
    const auto executed = dynamic_cast<SimulatedMarlin&>(*printerSim).simulator().executed();
    return static_cast<std::size_t>(std::count_if(executed.begin(), executed.end(), [](const MarlinExecutedRecord& e) {
      return e.command.rfind("G1 ", 0) == 0;
    }));
  }
};

INSTANTIATE_TEST_SUITE_P(Serial, PrintRunWithMarlinTest, ::testing::Values(PrinterProtocol::Marlin), protocolName);

// The platform turned 0.91 s before the printer's last move ended: an ok of no line, written as the M400 arrived,
// was taken as the M400's.
TEST_P(PrintRunWithMarlinTest, AStrayOkAtTheStepsEndDoesNotTurnThePlatformBeforeTheLastMoveEnds) {
  PrintRun run = runWithPrinter(20.0);
  marlin().sendStrayOkOnReceiving("M400");
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(tickUntilCompleted(run, 6000)) << wholeLog(run);
  expectNoPlatformCommandWhileAJobPrinted(3);
}

// Extra oks while the printer reports no temperatures: the step read complete early and the run then waited
// for a status read that never came. Now the run pauses, saying why, and nothing moves.
TEST_P(PrintRunWithMarlinTest, ExtraOksWithoutTemperatureReportsPauseTheRunSayingWhy) {
  // Moves only: 10 simulated seconds at speed 4 are 2.5 s, long enough to see the run pause mid-step.
  std::string program = "G90\nM83\nG1 X0 Y0 Z0.3 F1200\n";
  for (int i = 0; i < 20; ++i)
    program += "G1 X" + std::to_string((i + 1) % 2 * 10) + " Y" + std::to_string(i) + " E0.5\n";
  const auto dir = std::filesystem::path(testing::TempDir()) / "marlin-oks-without-temperatures";
  const std::string moves = writeFile(dir / "step-01.gcode", program);
  startPrinter(4.0);
  PrintRun run(*positioner,
               {{PlatformOrientation::rotary(0.0), "region 1", moves},
                {PlatformOrientation::rotary(30.0), "region 2", writeFile(dir / "step-02.gcode", program)}},
               runOptions(), printer.get());
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(tickUntil(run, [&] { return executedMoves() >= 2; })) << wholeLog(run);
  const Clock::time_point printing = clock();
  marlin().reportTemperatures(false);
  marlin().sendStrayOks(3);
  expectPausedWithoutMotion(run, printing, "temperature");
  EXPECT_EQ(run.currentStep(), 0u);
}

// Issue 28: `multidir run` checked every step's G-code before the first move, but the link read the file again
// when its step came up, so a step-02.gcode replaced while step 1 printed was printed unchecked. Now the link
// compares what it reads with the SHA-256 taken at the check, refuses it, and the run pauses naming the file.
TEST_P(PrintRunWithPrinterTest, AStepFileReplacedAfterItsCheckIsNotSentAndTheRunPausesNamingIt) {
  // Files of this test alone: the fixture's are rewritten by other tests of the protocol running beside it.
  const auto dir = std::filesystem::path(testing::TempDir()) /
                   (std::string("print-run-replaced-step-") + protocolText(GetParam()));
  std::vector<PrintStep> checked = steps();
  for (std::size_t i = 0; i < checked.size(); ++i) {
    checked[i].gcodePath = writeFile(dir / ("step-0" + std::to_string(i + 1) + ".gcode"), shortGcode());
    checked[i].gcodeSha256 = sha256Hex(shortGcode());  // as the pre-run check took it
  }
  startPrinter(20.0);
  PrintRun run(*positioner, checked, runOptions(), printer.get());
  ASSERT_TRUE(run.start().ok());
  untilFirstStart(run);
  writeFile(checked[1].gcodePath, heatersLeftOnGcode());  // replaced while step 1 prints

  ASSERT_TRUE(tickUntil(run, [&] { return run.state() == PrintRunState::Paused; }, 6000)) << wholeLog(run);
  EXPECT_EQ(run.currentStep(), 1u);
  EXPECT_NE(run.lastProblem().find("step-02.gcode changed after it was checked; nothing of it was sent"),
            std::string::npos)
      << run.lastProblem();
  EXPECT_EQ(printerSim->starts().size(), 1u);  // step 1's only
  EXPECT_EQ(printerSim->completedJobs(), 1);
  EXPECT_FALSE(run.stepBegun());
}

// Issue 28: the Marlin link counted stray oks in PrinterStatus::protocolWarnings, but neither the run's log nor
// `multidir run` said anything of them.
TEST_P(PrintRunWithMarlinTest, AStrayOkIsLoggedOnceInTheRunsLog) {
  PrintRun run = runWithPrinter(20.0);
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(untilPrinting(run)) << wholeLog(run);
  marlin().sendStrayOks(1);
  const auto warnings = [&] {
    return std::count_if(run.log().begin(), run.log().end(), [](const PrintRunLogEntry& e) {
      return e.message.find("warning from Marlin printer") != std::string::npos;
    });
  };
  ASSERT_TRUE(tickUntil(run, [&] { return warnings() > 0; })) << wholeLog(run);
  EXPECT_TRUE(logMentions(run, "an ok")) << wholeLog(run);
  tickUntil(run, [] { return false; }, 50);  // 100 ms more: the same warning is not logged again
  EXPECT_EQ(static_cast<std::uint64_t>(warnings()), printer->status().protocolWarnings) << wholeLog(run);
}

// Noise on the serial line (a wrong baud rate) is logged in the link's words, without raw control characters.
TEST_P(PrintRunWithMarlinTest, NoiseOnTheSerialLineIsLoggedAsAWarningWithoutControlCharacters) {
  PrintRun run = runWithPrinter(20.0);
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(untilPrinting(run)) << wholeLog(run);
  marlin().garbleOutput(true);
  ASSERT_TRUE(tickUntil(run, [&] { return logMentions(run, "warning from Marlin printer"); })) << wholeLog(run);
  EXPECT_TRUE(logMentions(run, "not Marlin's protocol")) << wholeLog(run);
  marlin().garbleOutput(false);
  for (const PrintRunLogEntry& e : run.log())
    for (const char c : e.message)
      EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 || c == 0x7f) << "raw control character in: " << e.message;
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
  using PrinterLink::upload;
  std::future<core::Status> upload(const std::string&, const std::string& name, const std::string&) override {
    uploads.push_back(name);
    return done();
  }
  std::future<core::Status> startPrint(const std::string&) override { return done(); }
  std::future<core::Status> pausePrint() override { return done(); }
  std::future<core::Status> resumePrint() override { return done(); }
  std::future<core::Status> cancelPrint() override { return done(); }
  std::future<core::Status> switchHeatersOff() override {
    ++heatersOff;
    return done();
  }
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
  int heatersOff = 0;
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

// One step at 0 degrees, printed from `gcodePath` ("": the operator prints it), without settling.
PrintRun oneStepRun(StillPositioner& platform, ScriptedPrinter& printer,
                    const std::string& gcodePath = "/tmp/step-01.gcode") {
  return PrintRun(platform, {{PlatformOrientation::rotary(0.0), "r1", gcodePath}}, immediate(), &printer);
}

TEST(PrintRunInterlock, ThePlatformIsNotCommandedWhileThePrinterReportsAJobPrinting) {
  StillPositioner platform;
  ScriptedPrinter printer;
  printer.state.state = PrinterJobState::Printing;
  printer.state.currentFile = "someone-elses.gcode";
  PrintRun run = oneStepRun(platform, printer);
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
  PrintRun run = oneStepRun(platform, printer);
  ASSERT_TRUE(run.start().ok());
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_EQ(platform.moves, 0);
}

// Issue 28: a state word the link did not recognise counted as idle, and the run moved.
TEST(PrintRunInterlock, ThePlatformIsNotCommandedWhileThePrinterReportsAStateMultiDirDoesNotKnow) {
  StillPositioner platform;
  ScriptedPrinter printer;
  printer.state.state = PrinterJobState::Unknown;  // read, but not a word of the documented set
  printer.state.message = "Moonraker's print_stats.state 'calibrating' is not one MultiDir knows";
  PrintRun run = oneStepRun(platform, printer);
  ASSERT_TRUE(run.start().ok());
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_EQ(platform.moves, 0);
  EXPECT_NE(run.lastProblem().find("the printer reports a state MultiDir does not know"), std::string::npos)
      << run.lastProblem();
  EXPECT_NE(run.lastProblem().find("'calibrating'"), std::string::npos) << run.lastProblem();
}

TEST(PrintRunInterlock, AStateMultiDirDoesNotKnowWhileTheRegionPrintsPausesTheRunAtOnce) {
  StillPositioner platform;
  ScriptedPrinter printer;
  PrintRun run = oneStepRun(platform, printer);
  ASSERT_TRUE(run.start().ok());
  run.tick();  // settling
  run.tick();  // uploading
  run.tick();  // uploaded: the start is sent
  run.tick();  // started
  printer.state.state = PrinterJobState::Printing;
  printer.state.currentFile = "step-01.gcode";
  printer.state.polls = 2;
  run.tick();
  ASSERT_EQ(run.state(), PrintRunState::Printing);
  printer.state.state = PrinterJobState::Unknown;
  printer.state.polls = 3;
  run.tick();
  EXPECT_EQ(run.state(), PrintRunState::Paused);
  EXPECT_NE(run.lastProblem().find("the printer reports a state MultiDir does not know"), std::string::npos)
      << run.lastProblem();
  EXPECT_EQ(platform.moves, 1);
}

// The same through a real link: Moonraker answering with a job state outside the documented set.
TEST(PrintRunInterlock, ARunWithAMoonrakerReportingAnUnknownJobStateNeverMovesThePlatform) {
  ScriptedHttpServer server(
      [](ScriptedConnection& c, const SeenHttpRequest&) { c.send(jsonReply(moonrakerStatusJson("calibrating", 0.0))); });
  auto printer = moonrakerLinkTo(server.port());
  ASSERT_TRUE(printer->connect().ok());
  StillPositioner platform;
  PrintRun run(platform, {{PlatformOrientation::rotary(0.0), "r1", "/tmp/step-01.gcode"}}, immediate(), printer.get());
  ASSERT_TRUE(run.start().ok());
  EXPECT_EQ(run.state(), PrintRunState::Faulted);
  EXPECT_EQ(platform.moves, 0);
  EXPECT_NE(run.lastProblem().find("'calibrating'"), std::string::npos) << run.lastProblem();
}

// Issue 28: a G-code name's control characters reached the log (and the terminal) raw.
TEST(PrintRunInterlock, TheLogHoldsNoRawControlCharactersOfAFileName) {
  StillPositioner platform;
  ScriptedPrinter printer;
  PrintRun run = oneStepRun(platform, printer, "/tmp/step\r\n01\x1b[2J.gcode");
  ASSERT_TRUE(run.start().ok());
  run.tick();
  run.tick();  // uploading: the log names the file
  for (const PrintRunLogEntry& e : run.log())
    for (const char c : e.message)
      EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 || c == 0x7f) << "raw control character in: " << e.message;
  EXPECT_TRUE(logMentions(run, R"(step\r\n01\x1b[2J.gcode)")) << wholeLog(run);
}

// A link's warning quotes what came from outside: its control characters reach the log escaped.
TEST(PrintRunInterlock, AProtocolWarningIsLoggedWithItsControlCharactersEscaped) {
  StillPositioner platform;
  ScriptedPrinter printer;
  PrintRun run = oneStepRun(platform, printer);
  printer.state.protocolWarnings = 1;
  printer.state.lastWarning = "noise \r\n\x1b[2J";
  run.tick();
  EXPECT_TRUE(logMentions(run, R"(warning from test printer: noise \r\n\x1b[2J)")) << wholeLog(run);
}

TEST(PrintRunInterlock, ThePrinterIsNotStartedWhileThePlatformReportsMotion) {
  StillPositioner platform;
  ScriptedPrinter printer;
  PrintRun run = oneStepRun(platform, printer);
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
  PrintRun run = oneStepRun(platform, printer, "");
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
  PrintRun run = oneStepRun(platform, printer);
  ASSERT_TRUE(run.start().ok());
  run.tick();
  run.tick();
  ASSERT_EQ(run.state(), PrintRunState::Printing);
  ASSERT_EQ(printer.uploads, std::vector<std::string>{"step-01.gcode"});
  EXPECT_FALSE(run.regionDone(0).ok());
}

// Issue 24: --from N after a stop reprinted a step the printer had begun over its printed part; the run tells
// its owner whether the step was begun.
TEST(PrintRunInterlock, AStepIsBegunFromTheStartSentUntilThePrinterReportsItComplete) {
  StillPositioner platform;
  ScriptedPrinter printer;
  PrintRun run = oneStepRun(platform, printer);
  ASSERT_TRUE(run.start().ok());
  run.tick();  // settling
  run.tick();  // uploading
  ASSERT_EQ(run.state(), PrintRunState::Printing);
  EXPECT_FALSE(run.stepBegun());  // only uploaded: nothing printed yet
  run.tick();                     // uploaded: the start is sent
  EXPECT_TRUE(run.stepBegun());
  run.tick();  // started
  printer.state.state = PrinterJobState::Printing;
  printer.state.currentFile = "step-01.gcode";
  printer.state.progress = 0.4;
  printer.state.polls = 2;
  run.tick();
  EXPECT_TRUE(run.stepBegun());
  EXPECT_DOUBLE_EQ(run.stepProgress(), 0.4);
  printer.state.state = PrinterJobState::Complete;
  printer.state.polls = 3;
  run.tick();
  EXPECT_EQ(run.state(), PrintRunState::Completed);
  EXPECT_FALSE(run.stepBegun());
}

TEST(PrintRunInterlock, AnAbortBetweenStepsSwitchesTheHeatersOffAndAnAbortWithoutAPrinterSendsNothing) {
  StillPositioner platform;
  ScriptedPrinter printer;
  PrintRun run(platform, {{PlatformOrientation::rotary(0.0), "r1", "/tmp/step-01.gcode"}}, immediate(), &printer);
  ASSERT_TRUE(run.start().ok());
  ASSERT_EQ(run.state(), PrintRunState::Moving);
  ASSERT_TRUE(run.abort().ok());
  EXPECT_EQ(printer.heatersOff, 1);
  platform.state.stopConfirmed = true;
  run.tick();
  EXPECT_FALSE(run.stopUnconfirmed());
  EXPECT_TRUE(logMentions(run, "test printer switched the heaters off"));
}

// The command line ends the run at a pause: its log must not send the operator to the studio's buttons.
TEST(PrintRunInterlock, TheOwnersAdviceReplacesTheStudiosButtonsAfterAPause) {
  StillPositioner platform;
  ScriptedPrinter printer;
  PrintRunOptions options = immediate();
  options.advice = [](PrintRunAdvice situation) {
    return situation == PrintRunAdvice::PrintInterrupted ? std::string("the owner says how to go on")
                                                         : std::string("other advice");
  };
  PrintRun run(platform, {{PlatformOrientation::rotary(0.0), "r1", "/tmp/step-01.gcode"}}, options, &printer);
  ASSERT_TRUE(run.start().ok());
  run.tick();
  run.tick();
  printer.state.linkLost = true;  // the link lost while the step prints: paused, print interrupted
  run.tick();
  ASSERT_EQ(run.state(), PrintRunState::Paused);
  EXPECT_TRUE(logMentions(run, "the platform stays where it is; the owner says how to go on"));
  EXPECT_FALSE(logMentions(run, "Region done"));
}

TEST(PrintRunInterlock, ARefusedStopSendsTheOperatorToTheOwnersEmergencyStop) {
  struct RefusingStop : StillPositioner {
    core::Status stopMotion() override {
      return core::Error{core::ErrorCode::DeviceUnreachable, "the link is down", "test platform"};
    }
  } platform;
  ScriptedPrinter printer;
  PrintRunOptions options = immediate();
  options.advice = [](PrintRunAdvice situation) {
    return situation == PrintRunAdvice::EmergencyStop ? std::string("press the red button") : std::string("other");
  };
  PrintRun run(platform, {{PlatformOrientation::rotary(0.0), "r1", "/tmp/step-01.gcode"}}, options, &printer);
  ASSERT_TRUE(run.start().ok());
  ASSERT_TRUE(run.abort().ok());
  EXPECT_TRUE(logMentions(run, "test platform may still move; press the red button")) << wholeLog(run);
  EXPECT_FALSE(logMentions(run, "E-STOP"));
}

}  // namespace
}  // namespace multidir::hardware

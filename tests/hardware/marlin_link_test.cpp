// The Marlin serial link against the Marlin simulator on a pseudo-terminal (serial:// URLs: printer_url_test.cpp).
#include "multidir/hardware/marlin_link.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>

#include "multidir/hardware/marlin_simulator.h"
#include "printer/marlin_protocol.h"
#include "printer_test_support.h"

namespace multidir::hardware {
namespace {

using namespace test;
using Outcome = MarlinLineRecord::Outcome;

class MarlinLinkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    startSimulator(400.0);  // the short program takes about 70 ms
    gcode = shortGcodeFile("marlin-link");
  }

  void startSimulator(double speed) {
    sim = std::make_unique<MarlinSimulator>(fastMarlinSimulatorOptions(speed));
    ASSERT_TRUE(sim->start().ok());
  }

  std::unique_ptr<PrinterLink> connected(int window = 1) {
    return connectedLink(marlinLinkTo(sim->devicePath(), fastPrinterOptions(), window));
  }

  // Uploads and starts the short program; true once the printer accepted both.
  bool printing(PrinterLink& link) { return uploadedAndStarted(link, gcode); }

  // The file's commands the printer executed, in order.
  std::vector<std::string> executedFileCommands() const {
    const std::vector<std::string> file = gcodeCommands(shortGcode());
    std::vector<std::string> out;
    for (const auto& e : sim->executed())
      if (std::find(file.begin(), file.end(), e.command) != file.end()) out.push_back(e.command);
    return out;
  }

  std::unique_ptr<MarlinSimulator> sim;
  std::string gcode;
};

TEST(MarlinProtocol, ChecksumIsTheXorOfTheLinesBytes) {
  // Lines a host sent to Marlin, with the checksums Marlin accepted (a public OctoPrint log).
  EXPECT_EQ(marlinNumberedLine(65048, "G1 X136.689 Y160.389 E6563.257"), "N65048 G1 X136.689 Y160.389 E6563.257*93");
  EXPECT_EQ(marlinNumberedLine(3186, "M105"), "N3186 M105*27");
}

TEST(MarlinProtocol, AnAdvancedOkNamesTheLineItAnswers) {
  EXPECT_EQ(marlin::parseReply("ok N12 P15 B3").okLine, 12);
  EXPECT_EQ(marlin::parseReply("ok").okLine, -1);
  const marlin::Reply temperatures = marlin::parseReply("ok T:210.0 /210.0 B:60.0 /60.0 @:0 B@:0");
  EXPECT_EQ(temperatures.kind, marlin::Reply::Kind::Ok);
  EXPECT_EQ(temperatures.okLine, -1);
  ASSERT_TRUE(temperatures.bed.has_value());
  EXPECT_DOUBLE_EQ(temperatures.bed->targetC, 60.0);
}

TEST(MarlinProtocol, TellsMarlinsOwnLinesFromNoise) {
  using Kind = marlin::Reply::Kind;
  EXPECT_EQ(marlin::parseReply("X:10.00 Y:20.00 Z:0.30 E:0.00 Count X:800 Y:1600 Z:120").kind, Kind::Position);
  EXPECT_EQ(marlin::parseReply(" T:200.00 /200.00 B:22.00 /0.00 @:0 B@:0 W:?").kind, Kind::Info);
  EXPECT_EQ(marlin::parseReply("echo:Marlin 2.1.2").kind, Kind::Info);
  EXPECT_EQ(marlin::parseReply("start").kind, Kind::Info);
  EXPECT_EQ(marlin::parseReply("echo:busy: processing").kind, Kind::Busy);
  const marlin::Reply noise = marlin::parseReply("\xf8\x1f~#x% T:5 \x7f&q?");
  EXPECT_EQ(noise.kind, Kind::Unknown);
  EXPECT_FALSE(noise.extruder.has_value());  // a "T:" inside noise is no temperature
}

TEST(MarlinUrl, TakesTheDevicePathAndTheBaudRate) {
  auto a = parseMarlinUrl("serial:///dev/ttyACM0?baud=250000");
  ASSERT_TRUE(a.ok()) << a.error().describe();
  EXPECT_EQ(a->devicePath, "/dev/ttyACM0");
  EXPECT_EQ(a->baud, 250000);
  auto b = parseMarlinUrl("serial:///dev/ttyUSB1");
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(b->baud, 115200);
  EXPECT_EQ(b->maxUnacknowledgedLines, 1);
}

TEST(MarlinUrl, RefusesRatesTheTermiosCannotSetRelativePathsAndUnknownOptionsSayingWhy) {
  EXPECT_NE(parseMarlinUrl("serial:///dev/ttyACM0?baud=123").error().message.find("baud must be one of"),
            std::string::npos);
  EXPECT_NE(parseMarlinUrl("serial://ttyACM0").error().message.find("absolute device path"), std::string::npos);
  EXPECT_NE(parseMarlinUrl("serial:///dev/ttyACM0?speed=1").error().message.find("unknown option 'speed'"),
            std::string::npos);
  EXPECT_FALSE(parseMarlinUrl("serial:///dev/ttyACM0?window=9").ok());
}

TEST_F(MarlinLinkTest, ConnectNumbersFromZeroAndReadsTheTemperatures) {
  auto link = connected();
  expectConnectedAndIdle(link->status());
  const auto received = sim->received();
  ASSERT_FALSE(received.empty());
  EXPECT_EQ(received.front().text, marlinNumberedLine(0, "M110 N0"));
  EXPECT_EQ(received.front().outcome, Outcome::Accepted);
}

TEST_F(MarlinLinkTest, ConnectToAMissingDeviceSaysWhatToCheck) {
  auto link = marlinLinkTo("/dev/nonexistent-printer");
  const core::Status status = link->connect();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, core::ErrorCode::DeviceUnreachable);
  EXPECT_NE(messageOf(status).find("plugged in"), std::string::npos) << messageOf(status);
  EXPECT_TRUE(link->status().linkLost);
}

TEST_F(MarlinLinkTest, ConnectToAPrinterThatNeverAnswersSaysToCheckTheBaudRate) {
  sim->dropLink();  // what a wrong baud rate looks like: nothing that reads as a line comes back
  auto link = marlinLinkTo(sim->devicePath());
  const core::Status status = link->connect();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, core::ErrorCode::DeviceUnreachable);
  EXPECT_NE(messageOf(status).find("check the baud rate"), std::string::npos) << messageOf(status);
  EXPECT_TRUE(link->status().linkLost);
}

TEST_F(MarlinLinkTest, StreamsTheFileWithLineNumbersAndChecksumsToCompletion) {
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }))
      << link->status().lastError;
  EXPECT_DOUBLE_EQ(link->status().progress, 1.0);
  EXPECT_EQ(link->status().currentFile, "step-01.gcode");
  // Every line reached the printer numbered in order from the job's M110, each with its right checksum.
  const auto received = sim->received();
  long expected = -1;
  bool inJob = false;
  for (const auto& r : received) {
    EXPECT_EQ(r.outcome, Outcome::Accepted) << r.text;
    if (r.command == "M110 N0") {
      expected = 1;
      inJob = true;
      continue;
    }
    if (!inJob) continue;
    EXPECT_EQ(r.lineNumber, expected) << r.text;
    EXPECT_EQ(r.text, marlinNumberedLine(r.lineNumber, r.command));
    ++expected;
  }
  EXPECT_EQ(executedFileCommands(), gcodeCommands(shortGcode()));
  // The job ended with M400 and M114: complete means every move was done, proven by the report after the M400.
  const auto executed = sim->executed();
  const auto last = std::find_if(executed.rbegin(), executed.rend(),
                                 [](const MarlinExecutedRecord& e) { return e.command != "M105"; });
  ASSERT_NE(last, executed.rend());
  EXPECT_EQ(last->command, "M114");
  const auto beforeLast =
      std::find_if(std::next(last), executed.rend(), [](const MarlinExecutedRecord& e) { return e.command != "M105"; });
  ASSERT_NE(beforeLast, executed.rend());
  EXPECT_EQ(beforeLast->command, "M400");
  EXPECT_EQ(sim->state().queuedMoves, 0u);
}

TEST_F(MarlinLinkTest, RecoversFromAResendWithoutLosingOrRepeatingALine) {
  auto link = connected();
  ASSERT_TRUE(outcome(link->upload(gcode, "step-01.gcode")).ok());
  sim->corruptNextLines(1);  // the job's M110 goes through; its first numbered line does not
  ASSERT_TRUE(outcome(link->startPrint("step-01.gcode")).ok());
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }))
      << link->status().lastError;
  const auto received = sim->received();
  const auto bad = std::find_if(received.begin(), received.end(),
                                [](const MarlinLineRecord& r) { return r.outcome == Outcome::ChecksumMismatch; });
  ASSERT_NE(bad, received.end());
  // The same line number came again, right, next.
  const auto again = std::next(bad);
  ASSERT_NE(again, received.end());
  EXPECT_EQ(again->lineNumber, bad->lineNumber);
  EXPECT_EQ(again->outcome, Outcome::Accepted);
  EXPECT_EQ(again->text, marlinNumberedLine(again->lineNumber, again->command));
  EXPECT_EQ(executedFileCommands(), gcodeCommands(shortGcode()));
}

TEST_F(MarlinLinkTest, RecoversFromResendsWithSeveralLinesInFlight) {
  auto link = connected(4);
  ASSERT_TRUE(outcome(link->upload(gcode, "step-01.gcode")).ok());
  sim->corruptNextLines(3);
  ASSERT_TRUE(outcome(link->startPrint("step-01.gcode")).ok());
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }))
      << link->status().lastError;
  EXPECT_EQ(executedFileCommands(), gcodeCommands(shortGcode()));
}

TEST_F(MarlinLinkTest, ReadsTheHeatersWhileThePrinterWaitsForThem) {
  startSimulator(2.0);  // 18 simulated seconds of heating take 9 s: the test sees them on the way, even when loaded
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(eventually(
      [&] {
        const PrinterStatus s = link->status();
        return s.state == PrinterJobState::Printing && s.extruder.targetC == 200.0 && s.extruder.actualC > 23.0;
      },
      6000ms));
  EXPECT_LT(link->status().extruder.actualC, 200.0);
  EXPECT_FALSE(link->status().linkLost);  // busy and temperature lines keep it alive while M109 blocks
}

TEST_F(MarlinLinkTest, ThermalRunawayEndsInErrorWithMarlinsOwnWords) {
  startSimulator(20.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  sim->injectThermalRunaway();
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Error; }, 5000ms));
  const PrinterStatus s = link->status();
  EXPECT_EQ(s.firmwareState, "halted");
  EXPECT_NE(s.message.find("Thermal Runaway, system stopped! Heater_ID: 0"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("kill() called"), std::string::npos) << s.message;
  // A halted printer takes nothing more.
  const core::Status started = outcome(link->startPrint("step-01.gcode"));
  ASSERT_FALSE(started.ok());
  EXPECT_NE(messageOf(started).find("reset it"), std::string::npos) << messageOf(started);
}

TEST_F(MarlinLinkTest, AJobStoppedAtThePrintersScreenIsReportedCancelled) {
  startSimulator(1.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  sim->cancelJobOnPrinter();
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Cancelled; }));
}

TEST_F(MarlinLinkTest, CancelStopsStreamingAndSwitchesTheHeatersOff) {
  // Cancelled once the printer waits in M109 (18 simulated seconds, 0.9 s here): a cancel during a heater wait
  // takes effect when the wait ends, so the test cancels in that state every time, however loaded the machine.
  startSimulator(20.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(eventually([&] {
    const auto received = sim->received();
    return std::any_of(received.begin(), received.end(),
                       [](const MarlinLineRecord& r) { return r.command == "M109 S200"; });
  }));
  ASSERT_TRUE(outcome(link->cancelPrint(), 10000ms).ok());
  EXPECT_EQ(link->status().state, PrinterJobState::Cancelled);
  const auto executed = sim->executed();
  const auto at = [&](const std::string& c) {
    return std::find_if(executed.begin(), executed.end(),
                        [&](const MarlinExecutedRecord& e) { return e.command == c; });
  };
  EXPECT_NE(at("M104 S0"), executed.end());
  EXPECT_NE(at("M140 S0"), executed.end());
  EXPECT_LT(executedFileCommands().size(), gcodeCommands(shortGcode()).size());
}

TEST_F(MarlinLinkTest, SwitchHeatersOffIsRefusedWhileAJobStreamsAndSentBetweenJobs) {
  startSimulator(20.0);  // the short program heats for about a second here
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  const core::Status whileStreaming = outcome(link->switchHeatersOff());
  ASSERT_FALSE(whileStreaming.ok());
  EXPECT_NE(messageOf(whileStreaming).find("cancel it first"), std::string::npos) << messageOf(whileStreaming);
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }, 10000ms));
  const std::string hot =
      writeFile(std::filesystem::path(testing::TempDir()) / "marlin-link-hot" / "step-01.gcode", heatersLeftOnGcode());
  startSimulator(400.0);
  link = connected();
  ASSERT_TRUE(uploadedAndStarted(*link, hot));
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }));
  ASSERT_GT(sim->state().bed.targetC, 59.0);
  const core::Status off = outcome(link->switchHeatersOff());
  ASSERT_TRUE(off.ok()) << messageOf(off);
  EXPECT_TRUE(eventually([&] { return sim->state().extruder.targetC == 0.0 && sim->state().bed.targetC == 0.0; }));
}

TEST_F(MarlinLinkTest, APrinterThatStopsAnsweringIsLostAfterItsTimeAndComesBack) {
  auto link = connected();
  sim->dropLink();
  ASSERT_TRUE(eventually([&] { return link->status().linkLost; }));
  sim->restoreLink();
  ASSERT_TRUE(eventually([&] { return !link->status().linkLost; }));
  EXPECT_EQ(link->status().link, LinkState::Connected);
}

TEST_F(MarlinLinkTest, AStreamCutByASilenceGoesOnWithoutLosingALine) {
  startSimulator(20.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  sim->dropLink();
  ASSERT_TRUE(eventually([&] { return link->status().linkLost; }));
  sim->restoreLink();
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }, 5000ms))
      << link->status().lastError;
  EXPECT_EQ(executedFileCommands(), gcodeCommands(shortGcode()));
}

TEST_F(MarlinLinkTest, AnUnpluggedPrinterEndsTheJobInErrorAndTheLinkIsLost) {
  startSimulator(5.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  sim->closePort();
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Error; }));
  EXPECT_EQ(link->status().link, LinkState::Reconnecting);
  EXPECT_NE(link->status().message.find("serial link was lost"), std::string::npos) << link->status().message;
  ASSERT_TRUE(eventually([&] { return link->status().linkLost; }, 10000ms));  // bounded; long only when loaded
}

TEST_F(MarlinLinkTest, EmergencyStopReachesThePrinterWhilePrintingAndIsConfirmedByItsHalt) {
  startSimulator(5.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  auto stopped = link->emergencyStop();
  ASSERT_TRUE(outcome(std::move(stopped)).ok());
  EXPECT_TRUE(link->status().stop.confirmed);
  const auto received = sim->received();
  EXPECT_TRUE(std::any_of(received.begin(), received.end(),
                          [](const MarlinLineRecord& r) { return r.outcome == Outcome::EmergencyStop; }));
  EXPECT_TRUE(sim->state().halted);
  EXPECT_EQ(link->status().state, PrinterJobState::Error);
  EXPECT_TRUE(link->clearStop().ok());
}

TEST_F(MarlinLinkTest, EmergencyStopIsResentUntilThePrinterHearsItAndRefusesStartsUntilCleared) {
  auto link = connected();
  ASSERT_TRUE(outcome(link->upload(gcode, "step-01.gcode")).ok());
  sim->dropLink();
  auto stopped = link->emergencyStop();
  EXPECT_EQ(stopped.wait_for(100ms), std::future_status::timeout);  // not heard: not confirmed
  EXPECT_TRUE(link->status().stop.latched());
  EXPECT_FALSE(link->status().stop.confirmed);
  EXPECT_FALSE(link->clearStop().ok());
  auto refused = link->startPrint("step-01.gcode");
  ASSERT_TRUE(readyAtOnce(refused));
  EXPECT_EQ(refused.get().error().code, core::ErrorCode::InvalidParameter);
  EXPECT_FALSE(sim->state().halted);
  sim->restoreLink();
  EXPECT_TRUE(outcome(std::move(stopped)).ok());
  EXPECT_TRUE(link->status().stop.confirmed);
  EXPECT_TRUE(sim->state().halted);
  EXPECT_TRUE(link->clearStop().ok());
}

// Issue 28: an ok that answers no line was taken as the final M400's, so the step read complete while moves
// were still queued. The simulator's clock is held by the test: its planner cannot drain until the test says so.
TEST(MarlinLinkEndOfStep, AStrayOkDoesNotEndTheStep) {
  static std::atomic<long long> elapsedMs{0};
  elapsedMs = 0;
  const auto origin = std::chrono::steady_clock::now();
  MarlinSimulatorOptions options = test::fastMarlinSimulatorOptions(1.0);
  options.plannerMoves = 32;  // the whole program fits: it is all received while the clock stands still
  options.steadyNow = [origin] { return origin + std::chrono::milliseconds(elapsedMs.load()); };
  MarlinSimulator sim(options);
  ASSERT_TRUE(sim.start().ok());
  sim.sendStrayOkOnReceiving("M400");  // the printer writes an ok of no line as the M400 arrives
  auto link = test::connectedLink(test::marlinLinkTo(sim.devicePath()));
  ASSERT_TRUE(test::uploadedAndStarted(*link, test::shortGcodeFile("marlin-stray-ok")));
  ASSERT_TRUE(test::eventually([&] {
    const auto received = sim.received();
    return !received.empty() && received.back().command == "M109 S200";
  }));
  elapsedMs = 17800;  // heated: the rest is streamed, M400 last; the moves need until 27.862 s
  const auto receivedM400 = [&] {
    const auto received = sim.received();
    return std::find_if(received.begin(), received.end(),
                        [](const MarlinLineRecord& r) { return r.command == "M400"; }) != received.end();
  };
  ASSERT_TRUE(test::eventually(receivedM400));
  // The link has acted on the stray ok once it sends its next line (whatever that line is).
  ASSERT_TRUE(test::eventually([&] { return sim.received().back().command != "M400"; }));
  EXPECT_GT(sim.state().queuedMoves, 0u);
  EXPECT_EQ(link->status().state, PrinterJobState::Printing);
  elapsedMs = 27900;  // the last move ends
  ASSERT_TRUE(test::eventually([&] { return link->status().state == PrinterJobState::Complete; }))
      << link->status().lastError;
  EXPECT_EQ(sim.state().queuedMoves, 0u);
}

TEST_F(MarlinLinkTest, AStrayOkIsCountedAsAProtocolWarningAndForNoLine) {
  auto link = connected();
  sim->sendStrayOks(2);
  ASSERT_TRUE(eventually([&] { return link->status().protocolWarnings >= 2; }));
  EXPECT_NE(link->status().lastWarning.find("answers no line"), std::string::npos) << link->status().lastWarning;
  // The printer is still read as before: the strays took no line's place.
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }));
  EXPECT_EQ(executedFileCommands(), gcodeCommands(shortGcode()));
}

TEST_F(MarlinLinkTest, WithAdvancedOkAStrayOkIsKnownAtOnceAndTheStepStillEndsWhenItsMovesDo) {
  MarlinSimulatorOptions options = fastMarlinSimulatorOptions(20.0);
  options.advancedOk = true;
  sim = std::make_unique<MarlinSimulator>(options);
  ASSERT_TRUE(sim->start().ok());
  sim->sendStrayOkOnReceiving("G1 X0 Y5 E0.5");  // mid-job
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }, 5000ms))
      << link->status().lastError;
  EXPECT_EQ(sim->state().queuedMoves, 0u);
  EXPECT_GE(link->status().protocolWarnings, 1u);
  EXPECT_EQ(executedFileCommands(), gcodeCommands(shortGcode()));
}

// Issue 28: noise on the line kept the link "alive": the job sat at 31 % with no warning.
TEST_F(MarlinLinkTest, APrinterSendingOnlyNoiseIsNotAnsweringAfterTheTimeout) {
  startSimulator(2.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  sim->garbleOutput(true);
  ASSERT_TRUE(eventually([&] { return link->status().linkLost; }, 5000ms)) << link->status().lastError;
  EXPECT_NE(link->status().lastError.find("not Marlin's protocol"), std::string::npos) << link->status().lastError;
  EXPECT_NE(link->status().state, PrinterJobState::Complete);
}

// Issue 28: oks alone, with no temperature report, kept the status fresh (and "complete") while nothing was read.
TEST_F(MarlinLinkTest, APrinterAnsweringOksWithoutTemperaturesIsNotAnsweringAfterTheTimeout) {
  auto link = connected();
  sim->reportTemperatures(false);  // M105 answered with a bare ok
  ASSERT_TRUE(eventually([&] { return link->status().linkLost; }, 5000ms)) << link->status().lastError;
  EXPECT_NE(link->status().lastError.find("no temperature"), std::string::npos) << link->status().lastError;
}

}  // namespace
}  // namespace multidir::hardware

namespace multidir::hardware {
namespace {

// The simulator's own clock, set by the test: the streamed moves take what their feed rates say.
TEST(MarlinSimulatorTiming, ExecutesStreamedMovesInTheTimeTheirHeatingAndFeedRatesTake) {
  static std::atomic<long long> elapsedMs{0};
  elapsedMs = 0;
  const auto origin = std::chrono::steady_clock::now();
  MarlinSimulatorOptions options;
  options.busyInterval = 50ms;  // real time: keeps the link alive while the test holds the clock
  options.plannerMoves = 32;    // the whole program fits: its timing does not depend on when lines arrive
  options.steadyNow = [origin] { return origin + std::chrono::milliseconds(elapsedMs.load()); };
  MarlinSimulator sim(options);
  ASSERT_TRUE(sim.start().ok());
  const std::string gcode = test::shortGcodeFile("marlin-timing");
  auto link = test::marlinLinkTo(sim.devicePath());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(test::outcome(link->upload(gcode, "step-01.gcode")).ok());
  ASSERT_TRUE(test::outcome(link->startPrint("step-01.gcode")).ok());
  // M109 S200 blocks: nothing after it runs until the heater is within 1 C of 200 C (17.7 s at 10 C/s).
  ASSERT_TRUE(test::eventually([&] {
    const auto received = sim.received();
    return !received.empty() && received.back().command == "M109 S200";
  }));
  elapsedMs = 17600;
  EXPECT_NEAR(sim.state().extruder.actualC, 198.0, 1e-6);
  EXPECT_EQ(sim.received().back().command, "M109 S200");
  // At 17.8 s the rest is streamed at once (the planner holds it all); the moves take 0.015 s to the first
  // layer's height and 20 moves of 10 mm or sqrt(101) mm at 1200 mm/min: 10.062 s, done at 27.862 s.
  elapsedMs = 17800;
  ASSERT_TRUE(test::eventually([&] {
    const auto received = sim.received();
    return !received.empty() && received.back().command == "M400";
  }));
  elapsedMs = 27800;
  EXPECT_GT(sim.state().queuedMoves, 0u);
  EXPECT_EQ(link->status().state, PrinterJobState::Printing);
  elapsedMs = 27900;
  EXPECT_EQ(sim.state().queuedMoves, 0u);
  ASSERT_TRUE(test::eventually([&] { return link->status().state == PrinterJobState::Complete; }));
}

}  // namespace
}  // namespace multidir::hardware

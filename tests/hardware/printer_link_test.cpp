// Every printer link against its simulator on 127.0.0.1: the behaviour PrinterLink promises, whatever the
// protocol (Moonraker, OctoPrint). Protocol-only cases are in moonraker_link_test.cpp and octoprint_link_test.cpp.
#include <gtest/gtest.h>

#include "printer_test_support.h"

namespace multidir::hardware {
namespace {

using namespace test;

class PrinterLinkTest : public ::testing::TestWithParam<PrinterProtocol> {
 protected:
  void SetUp() override {
    startSimulator(400.0);  // the short program takes about 70 ms
    gcode = shortGcodeFile("printer-link");
  }

  void startSimulator(double speed) {
    PrinterSimulatorOptions options;
    options.speed = speed;
    sim = printerSimulator(GetParam(), options);
    ASSERT_TRUE(sim->start().ok());
  }

  std::unique_ptr<PrinterLink> connected() { return connectedLink(printerLinkTo(GetParam(), sim->port())); }

  // Uploads and starts the short program; true once the printer accepted both.
  bool printing(PrinterLink& link) { return uploadedAndStarted(link, gcode); }

  bool moonraker() const { return GetParam() == PrinterProtocol::Moonraker; }

  std::unique_ptr<PrinterSimulator> sim;
  std::string gcode;
};

INSTANTIATE_TEST_SUITE_P(Protocols, PrinterLinkTest,
                         ::testing::Values(PrinterProtocol::Moonraker, PrinterProtocol::OctoPrint), protocolName);

// Issue 24: cpp-httplib's SO_REUSEPORT let a second simulator listen on the port of the first, and the
// kernel split the requests between the two printers.
TEST_P(PrinterLinkTest, ASimulatorOnAPortInUseFailsNamingThePortAndWhatToDo) {
  PrinterSimulatorOptions options;
  options.port = sim->port();
  auto second = printerSimulator(GetParam(), options);
  const core::Status started = second->start();
  ASSERT_FALSE(started.ok()) << "a second simulator listens on port " << sim->port();
  const std::string port = std::to_string(sim->port());
  EXPECT_NE(started.error().message.find("port " + port + " on 127.0.0.1 is in use"), std::string::npos)
      << started.error().message;
  EXPECT_NE(started.error().message.find("stop the other program"), std::string::npos) << started.error().message;
  EXPECT_NE(started.error().message.find("--port"), std::string::npos) << started.error().message;
  // The first one still answers every request.
  auto link = connected();
  expectConnectedAndIdle(link->status());
}

TEST_P(PrinterLinkTest, ConnectReadsTheIdlePrintersStatus) {
  auto link = connected();
  const PrinterStatus s = link->status();
  expectConnectedAndIdle(s);
  EXPECT_EQ(s.currentFile, "");
}

TEST_P(PrinterLinkTest, ConnectToNothingSaysTheLinkIsLostAndWhy) {
  auto link = printerLinkTo(GetParam(), sim->port());
  sim->stop();
  const core::Status status = link->connect();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, core::ErrorCode::DeviceUnreachable);
  const std::string expected = moonraker() ? "check that Moonraker runs" : "check that OctoPrint runs";
  EXPECT_NE(messageOf(status).find(expected), std::string::npos) << messageOf(status);
  EXPECT_TRUE(link->status().linkLost);
}

TEST_P(PrinterLinkTest, UploadsStartsAndFollowsAPrintToCompletion) {
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }));
  const PrinterStatus s = link->status();
  EXPECT_EQ(s.currentFile, "step-01.gcode");
  EXPECT_DOUBLE_EQ(s.progress, 1.0);
  const auto requests = sim->requests();
  const auto upload = std::find_if(requests.begin(), requests.end(),
                                   [&](const PrinterRequestRecord& r) { return isUpload(GetParam(), r); });
  ASSERT_NE(upload, requests.end());
  EXPECT_EQ(upload->detail, "step-01.gcode");
  EXPECT_EQ(upload->httpStatus, 201);
  const auto start = std::find_if(requests.begin(), requests.end(),
                                  [&](const PrinterRequestRecord& r) { return isStart(GetParam(), r); });
  ASSERT_NE(start, requests.end());
  EXPECT_EQ(start->detail, "step-01.gcode");
  EXPECT_GT(start->at, upload->at);
  std::vector<std::string> states;
  for (const auto& e : sim->jobEvents()) states.push_back(e.state);
  EXPECT_EQ(states, (std::vector<std::string>{"printing", "complete"}));
}

TEST_P(PrinterLinkTest, SwitchHeatersOffSetsEveryHeatersTargetToZeroAfterAJobLeftThemOn) {
  auto link = connected();
  const std::string hot =
      writeFile(std::filesystem::path(testing::TempDir()) / "printer-link-hot" / "step-01.gcode", heatersLeftOnGcode());
  ASSERT_TRUE(uploadedAndStarted(*link, hot));
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }));
  ASSERT_GT(sim->state().bed.targetC, 59.0);
  const core::Status off = outcome(link->switchHeatersOff());
  ASSERT_TRUE(off.ok()) << messageOf(off);
  EXPECT_EQ(sim->state().extruder.targetC, 0.0);
  EXPECT_EQ(sim->state().bed.targetC, 0.0);
  EXPECT_TRUE(eventually([&] { return link->status().extruder.targetC == 0.0 && link->status().bed.targetC == 0.0; }));
}

TEST_P(PrinterLinkTest, ReadsTheHeatersAndProgressWhileThePrinterHeats) {
  // 18 simulated seconds of heating take 9 s: the test sees it on the way, even on a loaded machine.
  startSimulator(2.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(eventually(
      [&] {
        const PrinterStatus s = link->status();
        return s.state == PrinterJobState::Printing && s.extruder.targetC == 200.0 && s.extruder.actualC > 23.0;
      },
      8000ms));
  const PrinterStatus s = link->status();
  EXPECT_LT(s.extruder.actualC, 200.0);
  EXPECT_EQ(s.currentFile, "step-01.gcode");
  EXPECT_GT(s.progress, 0.0);  // the heater commands' bytes are read
  EXPECT_LT(s.progress, 0.5);
}

TEST_P(PrinterLinkTest, PauseAndResumeReachThePrinter) {
  startSimulator(5.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(outcome(link->pausePrint()).ok());
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Paused; }));
  EXPECT_EQ(sim->state().jobState, "paused");
  ASSERT_TRUE(outcome(link->resumePrint()).ok());
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Printing; }));
  ASSERT_TRUE(outcome(link->cancelPrint()).ok());
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Cancelled; }));
}

TEST_P(PrinterLinkTest, APrintThePrinterRefusesIsADeviceFaultInThePrintersWords) {
  auto link = connected();
  const core::Status started = outcome(link->startPrint("missing.gcode"));
  ASSERT_FALSE(started.ok());
  EXPECT_EQ(started.error().code, core::ErrorCode::DeviceFault);
  const std::string words = moonraker() ? "Unable to open file" : "File not found on 'local': missing.gcode";
  EXPECT_NE(messageOf(started).find(words), std::string::npos) << messageOf(started);
}

TEST_P(PrinterLinkTest, AnUploadOfAMissingFileSendsNothing) {
  auto link = connected();
  const core::Status uploaded = outcome(link->upload("/nonexistent/step-09.gcode", "step-09.gcode"));
  ASSERT_FALSE(uploaded.ok());
  EXPECT_EQ(uploaded.error().code, core::ErrorCode::FileNotFound);
  EXPECT_EQ(countRequests(sim->requests(), [&](const PrinterRequestRecord& r) { return isUpload(GetParam(), r); }), 0);
}

// Issue 28: a name with `"` and CR LF went unescaped into the upload's multipart header (a header of the
// name's choosing) and into the log.
TEST_P(PrinterLinkTest, AnUploadNamedWithAQuoteOrALineBreakIsRefusedAtOnceAndNamedEscaped) {
  auto link = connected();
  std::future<core::Status> uploading = link->upload(gcode, "step\"\r\nX-Injected: 1.gcode");
  ASSERT_TRUE(readyAtOnce(uploading));
  const core::Status uploaded = uploading.get();
  ASSERT_FALSE(uploaded.ok());
  EXPECT_EQ(uploaded.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_NE(messageOf(uploaded).find(R"(step"\r\nX-Injected: 1.gcode)"), std::string::npos) << messageOf(uploaded);
  EXPECT_EQ(messageOf(uploaded).find_first_of("\r\n"), std::string::npos) << messageOf(uploaded);
  EXPECT_EQ(countRequests(sim->requests(), [&](const PrinterRequestRecord& r) { return isUpload(GetParam(), r); }), 0);
}

TEST_P(PrinterLinkTest, AStartOfANameWithAControlCharacterIsRefusedAtOnce) {
  auto link = connected();
  std::future<core::Status> starting = link->startPrint("step-01\x1b[2J.gcode");
  ASSERT_TRUE(readyAtOnce(starting));
  const core::Status started = starting.get();
  ASSERT_FALSE(started.ok());
  EXPECT_EQ(started.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_NE(messageOf(started).find(R"(step-01\x1b[2J.gcode)"), std::string::npos) << messageOf(started);
  EXPECT_EQ(countRequests(sim->requests(), [&](const PrinterRequestRecord& r) { return isStart(GetParam(), r); }), 0);
}

TEST_P(PrinterLinkTest, ThermalRunawayEndsInAnErrorWithTheFirmwaresWords) {
  startSimulator(20.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  sim->injectThermalRunaway();
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Error; }, 5000ms));
  const PrinterStatus s = link->status();
  EXPECT_FALSE(s.linkLost);
  EXPECT_EQ(s.firmwareState, moonraker() ? "shutdown" : "error");
  EXPECT_NE(s.message.find(moonraker() ? "ADC out of range" : "MAXTEMP triggered"), std::string::npos) << s.message;
}

TEST_P(PrinterLinkTest, AJobCancelledAtThePrinterIsReportedCancelled) {
  startSimulator(1.0);
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Printing; }));
  sim->cancelJobOnPrinter();
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Cancelled; }));
  EXPECT_EQ(link->status().currentFile, "step-01.gcode");
}

TEST_P(PrinterLinkTest, ADroppedLinkIsLostAfterItsTimeAndComesBack) {
  auto link = connected();
  sim->dropLink();
  ASSERT_TRUE(eventually([&] { return link->status().linkLost; }));
  EXPECT_EQ(link->status().link, LinkState::Reconnecting);
  EXPECT_NE(link->status().lastError.find("no answer"), std::string::npos) << link->status().lastError;
  sim->restoreLink();
  ASSERT_TRUE(eventually([&] { return !link->status().linkLost; }));
  EXPECT_EQ(link->status().link, LinkState::Connected);
}

TEST_P(PrinterLinkTest, RepliesSlowerThanTheTimeoutLoseTheLink) {
  auto link = connected();
  sim->setReplyDelay(1300ms);  // the link waits 1000 ms
  ASSERT_TRUE(eventually([&] { return link->status().linkLost; }));
  sim->setReplyDelay(0ms);
  ASSERT_TRUE(eventually([&] { return !link->status().linkLost; }));
}

TEST_P(PrinterLinkTest, EmergencyStopWaitsForTheLinkIsResentAndRefusesStartsUntilCleared) {
  auto link = connected();
  sim->dropLink();
  auto stopped = link->emergencyStop();
  EXPECT_EQ(stopped.wait_for(100ms), std::future_status::timeout);  // not answered: not confirmed
  EXPECT_TRUE(link->status().stop.latched());
  EXPECT_FALSE(link->status().stop.confirmed);
  EXPECT_NE(link->status().stop.problem.find("no answer"), std::string::npos) << link->status().stop.problem;
  EXPECT_FALSE(link->clearStop().ok());
  auto refused = link->startPrint("step-01.gcode");
  ASSERT_TRUE(readyAtOnce(refused));
  EXPECT_EQ(refused.get().error().code, core::ErrorCode::InvalidParameter);
  EXPECT_EQ(
      countRequests(sim->requests(), [&](const PrinterRequestRecord& r) { return isEmergencyStop(GetParam(), r); }), 0);
  sim->restoreLink();
  EXPECT_TRUE(outcome(std::move(stopped)).ok());
  EXPECT_TRUE(link->status().stop.confirmed);
  EXPECT_GE(link->status().stop.writes, 1u);
  EXPECT_GE(
      countRequests(sim->requests(), [&](const PrinterRequestRecord& r) { return isEmergencyStop(GetParam(), r); }), 1);
  EXPECT_EQ(sim->state().firmwareState, "shutdown");
  EXPECT_TRUE(link->clearStop().ok());
}

TEST_P(PrinterLinkTest, RestartFirmwareAfterAnEmergencyStopBringsTheShutDownPrinterBackToReady) {
  auto link = connected();
  ASSERT_TRUE(outcome(link->emergencyStop()).ok());
  ASSERT_EQ(sim->state().firmwareState, "shutdown");
  ASSERT_TRUE(eventually([&] { return link->status().firmwareState != "ready"; }));

  const core::Status restarted = outcome(link->restartFirmware());
  ASSERT_TRUE(restarted.ok()) << messageOf(restarted);
  EXPECT_EQ(sim->state().firmwareState, "ready");
  EXPECT_TRUE(eventually([&] { return link->status().firmwareState == "ready"; })) << link->status().firmwareState;
  // The latch still holds starts until the operator clears it.
  EXPECT_TRUE(link->status().stop.latched());
  EXPECT_TRUE(link->clearStop().ok());
}

}  // namespace
}  // namespace multidir::hardware

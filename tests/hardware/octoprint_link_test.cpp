// OctoPrint only: its API key and what follows its emergency stop (OctoPrint closes its
// connection to the printer; /api/printer then answers 409). The behaviour every link shares is in
// printer_link_test.cpp.
#include "multidir/hardware/octoprint_link.h"

#include <gtest/gtest.h>

#include "multidir/hardware/octoprint_simulator.h"
#include "printer_test_support.h"

namespace multidir::hardware {
namespace {

using namespace test;

class OctoPrintLinkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    OctoPrintSimulatorOptions options;
    options.speed = 5.0;
    sim = std::make_unique<OctoPrintSimulator>(options);
    ASSERT_TRUE(sim->start().ok());
    gcode = shortGcodeFile("octoprint-link");
  }

  std::unique_ptr<OctoPrintSimulator> sim;
  std::string gcode;
};

TEST_F(OctoPrintLinkTest, AWrongApiKeyIsADeviceFaultSayingWhereToFindTheKey) {
  auto link = octoPrintLinkTo(sim->port(), "not-the-key");
  const core::Status status = link->connect();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, core::ErrorCode::DeviceFault);
  EXPECT_NE(messageOf(status).find("HTTP 403"), std::string::npos) << messageOf(status);
  EXPECT_NE(messageOf(status).find("the API key is wrong"), std::string::npos) << messageOf(status);
  EXPECT_NE(messageOf(status).find("Settings > Application Keys"), std::string::npos) << messageOf(status);
  const auto requests = sim->requests();
  ASSERT_FALSE(requests.empty());
  EXPECT_EQ(requests.front().httpStatus, 403);
}

TEST_F(OctoPrintLinkTest, TheSimulatorAnswersOnlyItsOwnKey) {
  auto link = octoPrintLinkTo(sim->port(), sim->apiKey());
  ASSERT_TRUE(link->connect().ok());
  for (const auto& r : sim->requests()) EXPECT_EQ(r.httpStatus, 200) << r.path;
}

TEST_F(OctoPrintLinkTest, ALinkWithoutAnApiKeyIsRefusedSayingWhereToGetOne) {
  OctoPrintSettings settings;
  settings.port = sim->port();
  const auto link = makeOctoPrintLink(settings);
  ASSERT_FALSE(link.ok());
  EXPECT_EQ(link.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_NE(link.error().message.find("Application Keys"), std::string::npos) << link.error().message;
  EXPECT_TRUE(sim->requests().empty());
}

TEST_F(OctoPrintLinkTest, AnUploadNeitherSelectsNorStartsTheFile) {
  auto link = octoPrintLinkTo(sim->port());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(outcome(link->upload(gcode, "step-01.gcode")).ok());
  const SimulatedPrinterState s = sim->state();
  EXPECT_EQ(s.files, std::vector<std::string>{"step-01.gcode"});
  EXPECT_EQ(s.jobState, "standby");
  ASSERT_TRUE(eventually([&] { return link->status().polls >= 2; }));
  EXPECT_EQ(link->status().currentFile, "");
}

TEST_F(OctoPrintLinkTest, EmergencyStopSendsM112AndOctoPrintsClosedConnectionReadsAsAnErrorNotALostLink) {
  auto link = octoPrintLinkTo(sim->port());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(outcome(link->upload(gcode, "step-01.gcode")).ok());
  ASSERT_TRUE(outcome(link->startPrint("step-01.gcode")).ok());
  ASSERT_TRUE(outcome(link->emergencyStop()).ok());
  const auto stops = sim->requests();
  ASSERT_EQ(countRequests(stops,
                          [](const PrinterRequestRecord& r) { return isEmergencyStop(PrinterProtocol::OctoPrint, r); }),
            1);
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Error; }));
  const PrinterStatus s = link->status();
  EXPECT_FALSE(s.linkLost);
  EXPECT_EQ(s.firmwareState, "error");
  EXPECT_EQ(s.message, "Closing serial port due to emergency stop M112.");
  // /api/printer answers 409 from now on; the status reads go on.
  const std::uint64_t polls = s.polls;
  ASSERT_TRUE(eventually([&] { return link->status().polls > polls + 2; }));
  int conflicts = 0;
  for (const auto& r : sim->requests()) conflicts += r.path == "/api/printer" && r.httpStatus == 409 ? 1 : 0;
  EXPECT_GE(conflicts, 2);
  EXPECT_FALSE(link->status().linkLost);
}

TEST_F(OctoPrintLinkTest, AStartWhileOctoPrintIsNotConnectedToThePrinterSaysSo) {
  auto link = octoPrintLinkTo(sim->port());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(outcome(link->upload(gcode, "step-01.gcode")).ok());
  ASSERT_TRUE(outcome(link->emergencyStop()).ok());
  ASSERT_TRUE(link->clearStop().ok());
  const core::Status started = outcome(link->startPrint("step-01.gcode"));
  ASSERT_FALSE(started.ok());
  EXPECT_EQ(started.error().code, core::ErrorCode::DeviceFault);
  EXPECT_NE(messageOf(started).find("HTTP 409"), std::string::npos) << messageOf(started);
  EXPECT_NE(messageOf(started).find("not connected to OctoPrint"), std::string::npos) << messageOf(started);
}

TEST_F(OctoPrintLinkTest, ASecondEmergencyStopWhileOctoPrintIsOfflineCountsAsAnswered) {
  auto link = octoPrintLinkTo(sim->port());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(outcome(link->emergencyStop()).ok());
  ASSERT_TRUE(outcome(link->emergencyStop()).ok());  // 409: nothing prints through OctoPrint any more
  int conflicts = 0;
  for (const auto& r : sim->requests())
    conflicts += isEmergencyStop(PrinterProtocol::OctoPrint, r) && r.httpStatus == 409 ? 1 : 0;
  EXPECT_EQ(conflicts, 1);
  EXPECT_TRUE(link->status().stop.confirmed);
}

}  // namespace
}  // namespace multidir::hardware

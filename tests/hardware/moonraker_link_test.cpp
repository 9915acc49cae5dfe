#include "multidir/hardware/moonraker_link.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>

#include "multidir/hardware/moonraker_simulator.h"
#include "printer_test_support.h"

namespace multidir::hardware {
namespace {

using namespace test;

class MoonrakerLinkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    MoonrakerSimulatorOptions options;
    options.speed = 400.0;  // the short program takes about 70 ms
    sim = std::make_unique<MoonrakerSimulator>(options);
    ASSERT_TRUE(sim->start().ok());
    gcode = writeFile(std::filesystem::path(testing::TempDir()) / "moonraker-link" / "step-01.gcode", shortGcode());
  }

  std::unique_ptr<PrinterLink> connected() {
    auto link = moonrakerLinkTo(sim->port());
    const core::Status status = link->connect();
    EXPECT_TRUE(status.ok()) << messageOf(status);
    return link;
  }

  // Uploads and starts the short program; true once the printer reports it printing or done.
  bool printing(PrinterLink& link) {
    return outcome(link.upload(gcode, "step-01.gcode")).ok() && outcome(link.startPrint("step-01.gcode")).ok();
  }

  std::unique_ptr<MoonrakerSimulator> sim;
  std::string gcode;
};

TEST_F(MoonrakerLinkTest, ConnectReadsTheIdlePrintersStatus) {
  auto link = connected();
  const PrinterStatus s = link->status();
  EXPECT_EQ(s.link, LinkState::Connected);
  EXPECT_FALSE(s.linkLost);
  EXPECT_EQ(s.state, PrinterJobState::Standby);
  EXPECT_EQ(s.firmwareState, "ready");
  EXPECT_NEAR(s.extruder.actualC, 22.0, 1e-9);
  EXPECT_EQ(s.currentFile, "");
}

TEST_F(MoonrakerLinkTest, ConnectToNothingSaysTheLinkIsLostAndWhy) {
  auto link = moonrakerLinkTo(sim->port());
  sim->stop();
  const core::Status status = link->connect();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, core::ErrorCode::DeviceUnreachable);
  EXPECT_NE(messageOf(status).find("check that Moonraker runs"), std::string::npos) << messageOf(status);
  EXPECT_TRUE(link->status().linkLost);
}

TEST_F(MoonrakerLinkTest, UploadsStartsAndFollowsAPrintToCompletion) {
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Complete; }));
  const PrinterStatus s = link->status();
  EXPECT_EQ(s.currentFile, "step-01.gcode");
  EXPECT_DOUBLE_EQ(s.progress, 1.0);
  const auto requests = sim->requests();
  const auto upload = std::find_if(requests.begin(), requests.end(),
                                   [](const PrinterRequestRecord& r) { return r.path == "/server/files/upload"; });
  ASSERT_NE(upload, requests.end());
  EXPECT_EQ(upload->detail, "step-01.gcode");
  EXPECT_EQ(upload->httpStatus, 201);
  const auto start = std::find_if(requests.begin(), requests.end(),
                                  [](const PrinterRequestRecord& r) { return r.path == "/printer/print/start"; });
  ASSERT_NE(start, requests.end());
  EXPECT_EQ(start->detail, "step-01.gcode");
  EXPECT_GT(start->at, upload->at);
}

TEST_F(MoonrakerLinkTest, ReadsTheHeatersWhileThePrinterHeats) {
  MoonrakerSimulatorOptions options;
  options.speed = 5.0;  // 18 simulated seconds of heating take 3.6 s: the test sees it on the way
  sim = std::make_unique<MoonrakerSimulator>(options);
  ASSERT_TRUE(sim->start().ok());
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  ASSERT_TRUE(eventually([&] {
    const PrinterStatus s = link->status();
    return s.state == PrinterJobState::Printing && s.extruder.targetC == 200.0 && s.extruder.actualC > 23.0;
  }));
  EXPECT_LT(link->status().extruder.actualC, 200.0);
}

TEST_F(MoonrakerLinkTest, APrintThePrinterRefusesQuotesThePrintersReason) {
  auto link = connected();
  const core::Status started = outcome(link->startPrint("missing.gcode"));
  ASSERT_FALSE(started.ok());
  EXPECT_EQ(started.error().code, core::ErrorCode::DeviceFault);
  EXPECT_NE(messageOf(started).find("Unable to open file"), std::string::npos) << messageOf(started);
}

TEST_F(MoonrakerLinkTest, AnUploadOfAMissingFileSendsNothing) {
  auto link = connected();
  const core::Status uploaded = outcome(link->upload("/nonexistent/step-09.gcode", "step-09.gcode"));
  ASSERT_FALSE(uploaded.ok());
  EXPECT_EQ(uploaded.error().code, core::ErrorCode::FileNotFound);
  for (const auto& r : sim->requests()) EXPECT_NE(r.path, "/server/files/upload");
}

TEST_F(MoonrakerLinkTest, ThermalRunawayEndsInTheFirmwaresShutdownMessage) {
  MoonrakerSimulatorOptions options;
  options.speed = 20.0;
  sim = std::make_unique<MoonrakerSimulator>(options);
  ASSERT_TRUE(sim->start().ok());
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  sim->injectThermalRunaway();
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Error; }, 5000ms));
  const PrinterStatus s = link->status();
  EXPECT_EQ(s.firmwareState, "shutdown");
  EXPECT_NE(s.message.find("ADC out of range"), std::string::npos) << s.message;
}

TEST_F(MoonrakerLinkTest, AJobCancelledAtThePrinterIsReportedCancelled) {
  MoonrakerSimulatorOptions options;
  options.speed = 1.0;
  sim = std::make_unique<MoonrakerSimulator>(options);
  ASSERT_TRUE(sim->start().ok());
  auto link = connected();
  ASSERT_TRUE(printing(*link));
  sim->cancelJobOnPrinter();
  ASSERT_TRUE(eventually([&] { return link->status().state == PrinterJobState::Cancelled; }));
}

TEST_F(MoonrakerLinkTest, ADroppedLinkIsLostAfterItsTimeAndComesBack) {
  auto link = connected();
  sim->dropLink();
  ASSERT_TRUE(eventually([&] { return link->status().linkLost; }));
  EXPECT_EQ(link->status().link, LinkState::Reconnecting);
  EXPECT_NE(link->status().lastError.find("no answer"), std::string::npos) << link->status().lastError;
  sim->restoreLink();
  ASSERT_TRUE(eventually([&] { return !link->status().linkLost; }));
  EXPECT_EQ(link->status().link, LinkState::Connected);
}

TEST_F(MoonrakerLinkTest, RepliesSlowerThanTheTimeoutLoseTheLink) {
  auto link = connected();
  sim->setReplyDelay(1300ms);  // the link waits 1000 ms
  ASSERT_TRUE(eventually([&] { return link->status().linkLost; }));
  sim->setReplyDelay(0ms);
  ASSERT_TRUE(eventually([&] { return !link->status().linkLost; }));
}

TEST_F(MoonrakerLinkTest, EmergencyStopWaitsForTheLinkIsResentAndRefusesStartsUntilCleared) {
  auto link = connected();
  sim->dropLink();
  auto stopped = link->emergencyStop();
  EXPECT_EQ(stopped.wait_for(100ms), std::future_status::timeout);  // not answered: not confirmed
  EXPECT_TRUE(link->status().stop.latched());
  EXPECT_FALSE(link->status().stop.confirmed);
  EXPECT_FALSE(link->clearStop().ok());
  auto refused = link->startPrint("step-01.gcode");
  ASSERT_TRUE(readyAtOnce(refused));
  EXPECT_EQ(refused.get().error().code, core::ErrorCode::InvalidParameter);
  sim->restoreLink();
  EXPECT_TRUE(outcome(std::move(stopped)).ok());
  EXPECT_TRUE(link->status().stop.confirmed);
  EXPECT_EQ(sim->state().firmwareState, "shutdown");
  EXPECT_TRUE(link->clearStop().ok());
}

TEST(MoonrakerUrl, TakesHostAndPortWithOrWithoutTheScheme) {
  auto a = parseMoonrakerUrl("http://192.168.0.20:7125");
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(a->host, "192.168.0.20");
  EXPECT_EQ(a->port, 7125);
  auto b = parseMoonrakerUrl("http://printer.local/");
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(b->port, 80);
  auto c = parseMoonrakerUrl("127.0.0.1");
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c->port, 7125);
}

TEST(MoonrakerUrl, RefusesHttpsPathsAndBadPortsSayingWhy) {
  EXPECT_NE(parseMoonrakerUrl("https://p:7125").error().message.find("https is not supported"), std::string::npos);
  EXPECT_NE(parseMoonrakerUrl("http://p:7125/api").error().message.find("without a path"), std::string::npos);
  EXPECT_NE(parseMoonrakerUrl("p:99999").error().message.find("1 to 65535"), std::string::npos);
  EXPECT_FALSE(parseMoonrakerUrl("http://:80").ok());
}

}  // namespace
}  // namespace multidir::hardware

namespace multidir::hardware {
namespace {

// The simulator's own clock, set by the test: the print's timing follows the G-code's feed rates exactly.
TEST(MoonrakerSimulatorTiming, PrintsTheFileInTheTimeItsHeatingAndFeedRatesTake) {
  static std::atomic<long long> elapsedMs{0};
  elapsedMs = 0;
  const auto origin = std::chrono::steady_clock::now();
  MoonrakerSimulatorOptions options;
  options.speed = 1.0;
  options.steadyNow = [origin] { return origin + std::chrono::milliseconds(elapsedMs.load()); };
  MoonrakerSimulator sim(options);
  ASSERT_TRUE(sim.start().ok());
  const std::string gcode = test::writeFile(
      std::filesystem::path(testing::TempDir()) / "simulator-timing" / "step-01.gcode", test::shortGcode());
  auto link = test::moonrakerLinkTo(sim.port());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(test::outcome(link->upload(gcode, "step-01.gcode")).ok());
  ASSERT_TRUE(test::outcome(link->startPrint("step-01.gcode")).ok());
  // M109 S200 from 22 C at 10 C/s ends within 1 C of 200: 17.7 s. Then 0.015 s to the first layer's height and
  // 20 moves of 10 mm (the first) or sqrt(101) mm at 1200 mm/min: 10.047 s. Done at 27.762 s.
  elapsedMs = 17600;
  SimulatedPrinterState s = sim.state();
  EXPECT_EQ(s.jobState, "printing");
  EXPECT_NEAR(s.extruder.actualC, 198.0, 1e-6);
  const double heatingProgress = s.progress;
  elapsedMs = 22700;  // 5 s into the moves: about half of them
  s = sim.state();
  EXPECT_GT(s.progress, heatingProgress + 0.3);
  EXPECT_LT(s.progress, 0.8);
  elapsedMs = 27700;
  EXPECT_EQ(sim.state().jobState, "printing");
  elapsedMs = 27800;
  s = sim.state();
  EXPECT_EQ(s.jobState, "complete");
  EXPECT_DOUBLE_EQ(s.progress, 1.0);
}

}  // namespace
}  // namespace multidir::hardware

// The HTTP printer links against hostile printers (a scripted server on 127.0.0.1): every request ends by its
// deadline however slowly the reply trickles in, no reply grows past its size limit, no reply's nesting
// overflows the stack, and a stuck request never holds up a cancel or the emergency stop. The limits are in
// docs/hardware.md, "Printer link".
#include <gtest/gtest.h>

#include <atomic>
#include <future>

#include "printer_test_support.h"
#include "scripted_http_server.h"

namespace multidir::hardware {
namespace {

using namespace test;

bool isStatusRead(const SeenHttpRequest& r) { return r.target.rfind("/printer/objects/query", 0) == 0; }

// A Moonraker printing at 94 %; once `dripping` is set, every status reply trickles in one byte per 100 ms
// (well inside the link's 1000 ms wait for each read) for at most 10 s. Commands are answered at once.
class DrippingMoonraker {
 public:
  DrippingMoonraker()
      : server([this](ScriptedConnection& c, const SeenHttpRequest& r) {
          if (!isStatusRead(r)) {
            c.send(jsonReply(R"({"result": "ok"})"));
            return;
          }
          const std::string reply = jsonReply(moonrakerStatusJson("printing", 0.94));
          if (dripping) {
            c.drip(reply, 100ms, 10000ms);
          } else {
            c.send(reply);
          }
        }) {}

  // Sets dripping and waits until a status read began since.
  bool startDripping() {
    const auto before = server.requests().size();
    dripping = true;
    return eventually([&] { return server.requests().size() > before; });
  }

  std::atomic<bool> dripping{false};
  ScriptedHttpServer server;
};

// Issue 28: the timeout was per read; a 1 byte/s reply never timed out and the status froze at 94 % shown
// as live.
TEST(HttpPrinterLinkDeadline, AStatusReplyDrippedByteByByteEndsAtTheDeadlineAndTheStatusReadsLinkLost) {
  DrippingMoonraker printer;
  auto link = moonrakerLinkTo(printer.server.port());  // requestTimeout 1000 ms, linkLostAfter 400 ms
  ASSERT_TRUE(link->connect().ok());
  ASSERT_EQ(link->status().state, PrinterJobState::Printing);
  ASSERT_NEAR(link->status().progress, 0.94, 1e-9);
  ASSERT_TRUE(printer.startDripping());
  EXPECT_TRUE(eventually([&] { return link->status().linkLost; }, 6000ms));
  EXPECT_TRUE(eventually([&] { return link->status().lastError.find("1000 ms") != std::string::npos; }, 6000ms))
      << link->status().lastError;
}

TEST(HttpPrinterLinkDeadline, ConnectToAPrinterThatDripsItsReplyFailsAtTheDeadline) {
  DrippingMoonraker printer;
  printer.dripping = true;
  auto link = moonrakerLinkTo(printer.server.port());
  auto connecting = std::async(std::launch::async, [&] { return link->connect(); });
  ASSERT_EQ(connecting.wait_for(6000ms), std::future_status::ready) << "connect() still waits for the drip";
  const core::Status connected = connecting.get();
  ASSERT_FALSE(connected.ok());
  EXPECT_EQ(connected.error().code, core::ErrorCode::DeviceUnreachable);
  EXPECT_NE(messageOf(connected).find("1000 ms"), std::string::npos) << messageOf(connected);
}

// Ctrl-C's cancel never reached the printer: it waited behind the stuck status read.
TEST(HttpPrinterLinkDeadline, ACancelQueuedBehindAStuckStatusReadReachesThePrinterAfterTheDeadline) {
  DrippingMoonraker printer;
  auto link = moonrakerLinkTo(printer.server.port());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(printer.startDripping());
  const core::Status cancelled = outcome(link->cancelPrint(), 6000ms);
  EXPECT_TRUE(cancelled.ok()) << messageOf(cancelled);
  EXPECT_EQ(printer.server.count("POST", "/printer/print/cancel"), 1);
}

TEST(HttpPrinterLinkDeadline, TheEmergencyStopIsAnsweredWhileAStatusReadIsStuck) {
  DrippingMoonraker printer;
  auto link = moonrakerLinkTo(printer.server.port());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(printer.startDripping());
  const core::Status stopped = outcome(link->emergencyStop(), 3000ms);
  EXPECT_TRUE(stopped.ok()) << messageOf(stopped);
  EXPECT_EQ(printer.server.count("POST", "/printer/emergency_stop"), 1);
}

// Issue 28: a 2 GiB body took 8.2 GB of memory and, under a memory limit, std::bad_alloc aborted the run.
TEST(HttpPrinterLinkReplySize, AReplyDeclaringMoreThanTheLimitIsRefusedAsTooLarge) {
  ScriptedHttpServer server([](ScriptedConnection& c, const SeenHttpRequest&) {
    if (!c.send("HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: 2147483648\r\n\r\n")) return;
    c.stream(std::string(65536, ' '), 64u << 20, 5000ms);  // the first 64 MiB of the 2 GiB, at most 5 s
  });
  auto link = moonrakerLinkTo(server.port());
  const core::Status connected = link->connect();
  ASSERT_FALSE(connected.ok());
  EXPECT_EQ(connected.error().code, core::ErrorCode::DeviceFault);
  EXPECT_NE(messageOf(connected).find("larger than the 1 MiB"), std::string::npos) << messageOf(connected);
}

TEST(HttpPrinterLinkReplySize, AReplyWithoutALengthThatGrowsPastTheLimitIsRefusedAsTooLarge) {
  ScriptedHttpServer server([](ScriptedConnection& c, const SeenHttpRequest&) {
    if (!c.send("HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nConnection: close\r\n\r\n")) return;
    c.stream(std::string(65536, ' '), 4u << 20, 5000ms);  // 4 MiB of blanks, then a good status
    c.send(moonrakerStatusJson("standby", 0.0));
  });
  auto link = moonrakerLinkTo(server.port());
  const core::Status connected = link->connect();
  ASSERT_FALSE(connected.ok());
  EXPECT_EQ(connected.error().code, core::ErrorCode::DeviceFault);
  EXPECT_NE(messageOf(connected).find("larger than the 1 MiB"), std::string::npos) << messageOf(connected);
}

// Issue 28: 100,000 nested JSON objects from Moonraker overflowed the stack (SIGSEGV).
TEST(HttpPrinterLinkReplyJson, AReplyNested100000DeepIsRefusedWithoutOverflowingTheStack) {
  std::string nested;
  for (int i = 0; i < 100000; ++i) nested += R"({"a":)";
  nested += "1" + std::string(100000, '}');
  ScriptedHttpServer server(
      [&](ScriptedConnection& c, const SeenHttpRequest&) { c.send(jsonReply(R"({"result": )" + nested + "}")); });
  auto link = moonrakerLinkTo(server.port());
  const core::Status connected = link->connect();
  ASSERT_FALSE(connected.ok());
  EXPECT_EQ(connected.error().code, core::ErrorCode::DeviceFault);
  EXPECT_NE(messageOf(connected).find("nested deeper than 64 levels"), std::string::npos) << messageOf(connected);
}

TEST(HttpPrinterLinkReplyJson, AnOctoPrintErrorNested100000DeepIsRefusedWithoutOverflowingTheStack) {
  const std::string nested = std::string(100000, '[') + std::string(100000, ']');
  ScriptedHttpServer server([&](ScriptedConnection& c, const SeenHttpRequest&) {
    c.send(jsonReply(R"({"state": "Operational", "error": )" + nested + "}"));
  });
  auto link = octoPrintLinkTo(server.port());
  const core::Status connected = link->connect();
  ASSERT_FALSE(connected.ok());
  EXPECT_EQ(connected.error().code, core::ErrorCode::DeviceFault);
  EXPECT_NE(messageOf(connected).find("nested deeper than 64 levels"), std::string::npos) << messageOf(connected);
}

// Item 6 of issue 28: a state word outside the documented set is unknown, never idle.
TEST(HttpPrinterLinkState, AMoonrakerJobStateOutsideTheDocumentedSetReadsUnknownWithTheWordInTheMessage) {
  ScriptedHttpServer server(
      [](ScriptedConnection& c, const SeenHttpRequest&) { c.send(jsonReply(moonrakerStatusJson("calibrating\\u001b[2J", 0.0))); });
  auto link = moonrakerLinkTo(server.port());
  ASSERT_TRUE(link->connect().ok());
  const PrinterStatus s = link->status();
  EXPECT_FALSE(s.linkLost);
  EXPECT_EQ(s.state, PrinterJobState::Unknown);
  EXPECT_NE(s.message.find("calibrating\\x1b[2J"), std::string::npos) << s.message;
}

}  // namespace
}  // namespace multidir::hardware

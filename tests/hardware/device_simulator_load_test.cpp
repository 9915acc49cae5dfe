// Issue 14, item 2: the simulator under load and against hostile or careless clients. Each test failed on
// the select()/libmodbus server it replaced.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "hardware_test_support.h"
#include "multidir/hardware/device_simulator.h"
#include "multidir/hardware/rotary_platform.h"
#include "raw_modbus_client.h"

namespace multidir::hardware {
namespace {

using namespace test;

constexpr std::uint8_t kRotaryUnit = 1;

// Raises the soft limit on open files towards the hard one; the number of descriptors this process may hold.
rlim_t raiseOpenFileLimit(rlim_t wanted) {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0) return 0;
  if (limit.rlim_cur < wanted) {
    limit.rlim_cur = std::min(wanted, limit.rlim_max);
    setrlimit(RLIMIT_NOFILE, &limit);
    getrlimit(RLIMIT_NOFILE, &limit);
  }
  return limit.rlim_cur;
}

std::unique_ptr<RotaryPlatform> connectedPlatform(int port) {
  RotaryPlatformOptions options;
  options.connection = fastSettings(port, kRotaryUnit);
  options.machine.kind = core::MachineKind::RotaryPlatform;
  auto platform = std::make_unique<RotaryPlatform>(options);
  const core::Status status = platform->connect();
  EXPECT_TRUE(status.ok()) << messageOf(status);
  return platform;
}

// The reply's PDU: what follows the 7-byte MBAP header.
std::vector<std::uint8_t> pduOf(const std::vector<std::uint8_t>& frame) {
  return std::vector<std::uint8_t>(frame.begin() + 7, frame.end());
}

std::uint16_t transactionOf(const std::vector<std::uint8_t>& frame) {
  return static_cast<std::uint16_t>((frame[0] << 8) | frame[1]);
}

TEST(DeviceSimulatorLoad, ElevenHundredClientsOpenedThenClosedLeaveItServingANormalClient) {
  // More descriptors than select() can watch (FD_SETSIZE 1024): the old server overflowed its fd_set.
  const rlim_t available = raiseOpenFileLimit(4096);
  ASSERT_GE(available, 1300u) << "this test needs about 1300 open files (ulimit -n)";
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  {
    std::vector<RawClient> clients;
    clients.reserve(1100);
    for (int i = 0; i < 1100; ++i) clients.emplace_back(sim.port());
    for (const RawClient& client : clients) ASSERT_TRUE(client.connected());
    ASSERT_TRUE(eventually([&] { return sim.refusedConnectionCount() >= 1100u - 64u; }));
    EXPECT_EQ(sim.connectionCount(), 64);  // the limit, and not one more
  }                                        // all closed
  ASSERT_TRUE(eventually([&] { return sim.connectionCount() == 0; }));
  EXPECT_TRUE(sim.running());
  auto platform = connectedPlatform(sim.port());
  EXPECT_TRUE(outcome(platform->enable()).ok());
  EXPECT_TRUE(eventually([&] { return sim.rotaryState().enabled; }));
}

TEST(DeviceSimulatorLoad, ClientsBeyondTheLimitAreClosedAtOnceAndTheOthersKeepBeingServed) {
  SimulatorOptions options;
  options.maxClients = 3;
  DeviceSimulator sim(options);
  ASSERT_TRUE(sim.start().ok());
  std::vector<RawClient> clients;
  for (int i = 0; i < 5; ++i) clients.emplace_back(sim.port());
  ASSERT_TRUE(eventually([&] { return sim.connectionCount() == 3 && sim.refusedConnectionCount() == 2; }));
  EXPECT_TRUE(clients[3].closedByServer());
  EXPECT_TRUE(clients[4].closedByServer());
  for (std::size_t i = 0; i < 3; ++i) {
    ASSERT_TRUE(clients[i].send(mbapFrame(static_cast<std::uint16_t>(i + 1), kRotaryUnit, readPdu(0, 13))));
    const auto reply = clients[i].readFrame();
    ASSERT_TRUE(reply.has_value()) << "client " << i;
    EXPECT_EQ(pduOf(*reply)[0], 0x03);
    EXPECT_EQ(transactionOf(*reply), i + 1);
  }
}

TEST(DeviceSimulatorLoad, SlowClientSendingAByteEvery400MsNeverHoldsUpTheOthers) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  auto platform = connectedPlatform(sim.port());  // 150 ms response timeout: a stall of 400 ms breaks its link
  RawClient slow(sim.port());
  ASSERT_TRUE(slow.connected());
  const std::vector<std::uint8_t> request = mbapFrame(7, kRotaryUnit, readPdu(0, 13));
  for (std::size_t i = 0; i < 3; ++i) {
    const auto sentAt = std::chrono::steady_clock::now();
    ASSERT_TRUE(slow.send({request[i]}));
    const auto polls = platform->status().polls;
    // While the slow request trickles in, the driver's polls go on and its link never breaks.
    EXPECT_TRUE(eventually([&] { return platform->status().polls >= polls + 5; }, 2000ms));
    EXPECT_EQ(platform->status().link, LinkState::Connected) << platform->status().lastError;
    std::this_thread::sleep_until(sentAt + 400ms);  // the slow client's pace
  }
  // Its request never completes within the simulator's 1 s request timeout: it is disconnected.
  EXPECT_TRUE(slow.closedByServer());
  EXPECT_EQ(sim.droppedClientCount(), 1u);
  EXPECT_EQ(platform->status().link, LinkState::Connected);
}

TEST(DeviceSimulatorLoad, ReadsOfQuantityZeroOr126GetIllegalDataValueAndTheNextRequestIsAnswered) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  RawClient client(sim.port());
  ASSERT_TRUE(client.connected());
  // Pipelined in one write: the old server slept and flushed the stream after the bad quantity.
  std::vector<std::uint8_t> bytes = mbapFrame(1, kRotaryUnit, readPdu(0, 0));
  const std::vector<std::uint8_t> tooMany = mbapFrame(2, kRotaryUnit, readPdu(0, 126));
  const std::vector<std::uint8_t> good = mbapFrame(3, kRotaryUnit, readPdu(0, 13));
  bytes.insert(bytes.end(), tooMany.begin(), tooMany.end());
  bytes.insert(bytes.end(), good.begin(), good.end());
  ASSERT_TRUE(client.send(bytes));
  for (std::uint16_t transaction : {1, 2}) {
    const auto reply = client.readFrame();
    ASSERT_TRUE(reply.has_value()) << "transaction " << transaction;
    EXPECT_EQ(transactionOf(*reply), transaction);
    EXPECT_EQ(pduOf(*reply), (std::vector<std::uint8_t>{0x83, 0x03}));
  }
  const auto reply = client.readFrame();
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(transactionOf(*reply), 3);
  EXPECT_EQ(pduOf(*reply)[0], 0x03);
  EXPECT_EQ(pduOf(*reply)[1], 26);  // 13 registers
}

TEST(DeviceSimulatorLoad, UnknownFunctionCodeGetsIllegalFunctionAndTheConnectionStaysInSync) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  RawClient client(sim.port());
  ASSERT_TRUE(client.connected());
  // 0x2B/0x0E (read device identification) with its data, then a read: the old server took the unknown
  // function's data for the next request.
  std::vector<std::uint8_t> bytes = mbapFrame(1, kRotaryUnit, {0x2B, 0x0E, 0x01, 0x00});
  const std::vector<std::uint8_t> good = mbapFrame(2, kRotaryUnit, readPdu(8, 2));
  bytes.insert(bytes.end(), good.begin(), good.end());
  ASSERT_TRUE(client.send(bytes));
  const auto refused = client.readFrame();
  ASSERT_TRUE(refused.has_value());
  EXPECT_EQ(transactionOf(*refused), 1);
  EXPECT_EQ(pduOf(*refused), (std::vector<std::uint8_t>{0xAB, 0x01}));
  const auto reply = client.readFrame();
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(transactionOf(*reply), 2);
  EXPECT_EQ(pduOf(*reply)[0], 0x03);
  EXPECT_EQ(pduOf(*reply)[1], 4);
}

TEST(DeviceSimulatorLoad, NonZeroProtocolIdIsNotModbusAndClosesThatConnectionOnly) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  auto platform = connectedPlatform(sim.port());
  const auto requests = sim.requestCount(SimulatedDevice::Rotary);
  RawClient client(sim.port());
  ASSERT_TRUE(client.connected());
  ASSERT_TRUE(client.send(mbapFrame(1, kRotaryUnit, {0x06, 0x00, 0x03, 0x00, 0x01}, /*protocol=*/1)));
  EXPECT_TRUE(client.closedByServer());
  EXPECT_EQ(sim.commandWriteCount(SimulatedDevice::Rotary), 0u);  // the write in it was not taken
  EXPECT_FALSE(sim.rotaryState().enabled);
  EXPECT_TRUE(eventually([&] { return sim.requestCount(SimulatedDevice::Rotary) > requests + 3; }));  // polls go on
  EXPECT_EQ(platform->status().link, LinkState::Connected);
}

TEST(DeviceSimulatorLoad, LengthFieldNoRequestCanHaveClosesTheConnection) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  RawClient client(sim.port());
  ASSERT_TRUE(client.connected());
  ASSERT_TRUE(client.send({0x00, 0x01, 0x00, 0x00, 0xFF, 0xFF, kRotaryUnit, 0x03}));  // length 65535
  EXPECT_TRUE(client.closedByServer());
}

TEST(DeviceSimulatorLoad, WriteOfAReadOnlyRegisterGetsIllegalDataAddress) {
  DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  RawClient client(sim.port());
  ASSERT_TRUE(client.connected());
  ASSERT_TRUE(client.send(mbapFrame(1, kRotaryUnit, {0x06, 0x00, 0x0A, 0x00, 0x01})));  // STATUS (10)
  const auto reply = client.readFrame();
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(pduOf(*reply), (std::vector<std::uint8_t>{0x86, 0x02}));
}

}  // namespace
}  // namespace multidir::hardware

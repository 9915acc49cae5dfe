// The UR simulator on loopback and the link to it: the dashboard's replies in UR's words, a program outside the
// subset reported with its line, an emergency stop that stops the arm within 200 ms of the call (on the
// injected clock) with nothing moving after it, a dropped link reported and the stop resent after reconnecting.
#include "multidir/hardware/ur_simulator.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "hardware_test_support.h"
#include "multidir/hardware/ur_link.h"
#include "multidir/robot/cell.h"

namespace {

using namespace std::chrono_literals;
using multidir::hardware::StopKind;
using multidir::hardware::UrLink;
using multidir::hardware::UrLinkMessage;
using multidir::hardware::UrLinkSettings;
using multidir::hardware::UrSimulator;
using multidir::hardware::UrSimulatorOptions;
using multidir::hardware::test::eventually;
using Clock = std::chrono::steady_clock;

// The injected clock: a ticker thread moves it 8 ms (one control tick) every 2 ms of real time, and stands
// still while paused, so a test can hold the controller's time around a call.
class SteppedClock {
 public:
  SteppedClock() : m_thread([this] { run(); }) {}
  ~SteppedClock() {
    m_quit = true;
    m_thread.join();
  }
  Clock::time_point now() const { return Clock::time_point(std::chrono::nanoseconds(m_ns.load())); }
  void pause() {
    m_paused = true;
    std::this_thread::sleep_for(5ms);  // a step under way lands before the caller reads the time
  }
  void resume() { m_paused = false; }

 private:
  void run() {
    while (!m_quit) {
      if (!m_paused) m_ns += 8'000'000;
      std::this_thread::sleep_for(2ms);
    }
  }
  std::atomic<std::int64_t> m_ns{1'000'000'000};
  std::atomic<bool> m_paused{false};
  std::atomic<bool> m_quit{false};
  std::thread m_thread;
};

UrSimulatorOptions optionsOn(const SteppedClock& clock) {
  UrSimulatorOptions options;
  options.steadyNow = [&clock] { return clock.now(); };
  options.keepTrace = true;
  return options;
}

UrLinkSettings linkTo(const UrSimulator& simulator) {
  UrLinkSettings settings;
  settings.dashboardPort = simulator.dashboardPort();
  settings.secondaryPort = simulator.secondaryPort();
  settings.realtimePort = simulator.realtimePort();
  settings.rtdePort = simulator.rtdePort();
  settings.reconnectInterval = 50ms;
  settings.stopResendInterval = 100ms;
  return settings;
}

// A plain TCP client of the dashboard server, one line at a time.
class DashboardClient {
 public:
  explicit DashboardClient(int port) {
    m_fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    inet_pton(AF_INET, "127.0.0.1", &address.sin_addr);
    timeval timeout{3, 0};
    setsockopt(m_fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    m_connected = ::connect(m_fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  }
  ~DashboardClient() { ::close(m_fd); }
  bool connected() const { return m_connected; }
  std::string line() {
    std::string text;
    char c = 0;
    while (::recv(m_fd, &c, 1, 0) == 1 && c != '\n') text += c;
    return text;
  }
  std::string ask(const std::string& command) {
    const std::string bytes = command + "\n";
    if (::send(m_fd, bytes.data(), bytes.size(), MSG_NOSIGNAL) != static_cast<ssize_t>(bytes.size())) return "";
    return line();
  }

 private:
  int m_fd = -1;
  bool m_connected = false;
};

// The arm powered on and running a long movej, as the link sees it.
void startLongMove(UrLink& link) {
  ASSERT_TRUE(link.connect().ok());
  ASSERT_TRUE(link.powerOn(5000ms).ok()) << link.status().robotMode;
  ASSERT_TRUE(
      link.sendProgram("def long_move():\n  movej([2.5, -1.0, 1.2, -1.7, -1.2, 0.5], a=3.0, v=1.5)\nend\n").ok());
  ASSERT_TRUE(eventually([&] { return !link.status().atRest; }, 3000ms));
}

TEST(UrSimulator, TheDashboardAnswersInUrsWords) {
  SteppedClock clock;
  UrSimulator simulator(optionsOn(clock));
  ASSERT_TRUE(simulator.start().ok());
  DashboardClient dashboard(simulator.dashboardPort());
  ASSERT_TRUE(dashboard.connected());
  EXPECT_EQ(dashboard.line(), "Connected: Universal Robots Dashboard Server");
  EXPECT_EQ(dashboard.ask("robotmode"), "Robotmode: POWER_OFF");
  EXPECT_EQ(dashboard.ask("power on"), "Powering on");
  ASSERT_TRUE(eventually([&] { return simulator.state().robotMode == "IDLE"; }));
  EXPECT_EQ(dashboard.ask("robotmode"), "Robotmode: IDLE");
  EXPECT_EQ(dashboard.ask("brake release"), "Brake releasing");
  EXPECT_EQ(dashboard.ask("robotmode"), "Robotmode: RUNNING");
  EXPECT_EQ(dashboard.ask("safetymode"), "Safetymode: NORMAL");
  EXPECT_EQ(dashboard.ask("safetystatus"), "Safetystatus: NORMAL");
  EXPECT_EQ(dashboard.ask("programState"), "STOPPED <unnamed>");
  EXPECT_EQ(dashboard.ask("running"), "Program running: false");
  EXPECT_EQ(dashboard.ask("play"), "Failed to execute: play");
  EXPECT_EQ(dashboard.ask("pause"), "Failed to execute: pause");
  EXPECT_EQ(dashboard.ask("unlock protective stop"), "Protective stop releasing");
  EXPECT_EQ(dashboard.ask("close safety popup"), "closing safety popup");
  EXPECT_EQ(dashboard.ask("load multidir.urp"), "could not understand: 'load multidir.urp'");
  EXPECT_EQ(dashboard.ask("quit"), "Disconnected");
}

TEST(UrSimulator, APausedProgramSaysSoAndPlayResumesIt) {
  SteppedClock clock;
  UrSimulator simulator(optionsOn(clock));
  ASSERT_TRUE(simulator.start().ok());
  UrLink link(linkTo(simulator));
  startLongMove(link);
  DashboardClient dashboard(simulator.dashboardPort());
  dashboard.line();
  EXPECT_EQ(dashboard.ask("programState"), "PLAYING long_move");
  EXPECT_EQ(dashboard.ask("running"), "Program running: true");
  EXPECT_EQ(dashboard.ask("pause"), "Pausing program");
  EXPECT_EQ(dashboard.ask("programState"), "PAUSED long_move");
  ASSERT_TRUE(eventually([&] { return simulator.state().atRest; }));
  EXPECT_EQ(dashboard.ask("play"), "Starting program");
  ASSERT_TRUE(eventually([&] { return simulator.state().programsFinished == 1; }, 10000ms));
  EXPECT_NEAR(simulator.state().joints[0], 2.5, 1e-9);
}

TEST(UrLink, AProgramOutsideTheSubsetIsReportedWithItsLine) {
  SteppedClock clock;
  UrSimulator simulator(optionsOn(clock));
  ASSERT_TRUE(simulator.start().ok());
  UrLink link(linkTo(simulator));
  ASSERT_TRUE(link.connect().ok());
  ASSERT_TRUE(link.powerOn(5000ms).ok());
  ASSERT_TRUE(link.sendProgram("def step():\n  sleep(0.1)\n  socket_open(\"10.0.0.1\", 502)\nend\n").ok());
  std::vector<UrLinkMessage> messages;
  ASSERT_TRUE(eventually([&] {
    for (UrLinkMessage& m : link.takeMessages()) messages.push_back(m);
    return !messages.empty();
  }));
  EXPECT_EQ(messages[0].kind, UrLinkMessage::Kind::RuntimeException);
  EXPECT_EQ(messages[0].line, 3);
  EXPECT_NE(messages[0].describe().find("runtime exception at line 3, column 3: Compile error: 'socket_open' is not "
                                        "in the URScript subset"),
            std::string::npos)
      << messages[0].describe();
  EXPECT_EQ(simulator.state().programState, "STOPPED");
}

TEST(UrLink, AnEmergencyStopMidProgramStopsTheArmWithin200MsOfTheCallAndNothingMovesAfter) {
  SteppedClock clock;
  UrSimulator simulator(optionsOn(clock));
  ASSERT_TRUE(simulator.start().ok());
  UrLink link(linkTo(simulator));
  startLongMove(link);
  ASSERT_TRUE(eventually([&] { return std::abs(simulator.state().joints[0]) > 0.3; }, 5000ms));
  // The controller's time stands still from the call until the command reached it.
  clock.pause();
  const double calledAt = simulator.state().time;
  link.emergencyStop();
  ASSERT_TRUE(eventually([&] {
    for (const auto& record : simulator.dashboardLog())
      if (record.command == "power off") return true;
    return false;
  }));
  clock.resume();
  ASSERT_TRUE(eventually([&] { return link.status().stop.confirmed; }, 5000ms)) << link.status().stop.problem;
  ASSERT_TRUE(simulator.waitForSimulatedTime(simulator.state().time + 1.0));
  const auto trace = simulator.trace();
  double lastMove = calledAt;
  for (std::size_t k = 1; k < trace.size(); ++k)
    if (trace[k].joints != trace[k - 1].joints) lastMove = trace[k].time;
  EXPECT_LE(lastMove - calledAt, 0.2 + 1e-9);
  const auto s = simulator.state();
  EXPECT_EQ(s.robotMode, "POWER_OFF");
  EXPECT_EQ(s.programState, "STOPPED");
  EXPECT_TRUE(link.status().atRest);
  // Latched: no program goes out until the stop is cleared.
  EXPECT_FALSE(link.sendProgram("def again():\n  sleep(1)\nend\n").ok());
  EXPECT_TRUE(link.clearStop().ok());
}

TEST(UrLink, ALinkDropIsReportedAndTheStopIsResentAfterReconnecting) {
  SteppedClock clock;
  UrSimulator simulator(optionsOn(clock));
  ASSERT_TRUE(simulator.start().ok());
  UrLinkSettings settings = linkTo(simulator);
  settings.silenceLimit = 300ms;
  UrLink link(settings);
  startLongMove(link);
  simulator.dropLinks();
  ASSERT_TRUE(eventually([&] { return link.status().linkLost; }, 3000ms));
  EXPECT_FALSE(link.status().linkProblem.empty());
  // The stop asked for while the link is down is latched, unconfirmed, and says why.
  link.stop();
  auto s = link.status();
  EXPECT_EQ(s.stop.kind, StopKind::Stop);
  EXPECT_FALSE(s.stop.confirmed);
  EXPECT_NE(s.stop.problem.find("the link is down"), std::string::npos) << s.stop.problem;
  EXPECT_EQ(simulator.state().programState, "PLAYING");  // the controller never heard it
  const std::size_t commandsBefore = simulator.dashboardLog().size();
  simulator.restoreLinks();
  ASSERT_TRUE(eventually([&] { return link.status().connected; }, 3000ms)) << link.status().linkProblem;
  ASSERT_TRUE(eventually([&] { return link.status().stop.confirmed; }, 5000ms)) << link.status().stop.problem;
  const auto log = simulator.dashboardLog();
  ASSERT_GT(log.size(), commandsBefore);
  EXPECT_EQ(log[commandsBefore].command, "stop");
  EXPECT_EQ(log[commandsBefore].reply, "Stopped");
  EXPECT_GE(link.status().reconnects, 1u);
  EXPECT_EQ(simulator.state().programState, "STOPPED");
  EXPECT_TRUE(simulator.state().atRest);
}

// With the cell, the trace says where the fixed nozzle is on the platform: the tip (base frame) in the frame of
// the platform pose the cell's own kinematics give for the traced joints; and the extruder's filament speed.
TEST(UrSimulator, WithACellTheTraceHasTheNozzleInThePlatformFrameAndTheFilamentSpeed) {
  const std::string cellPath = std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json";
  const auto cell = multidir::robot::loadCell(cellPath);
  ASSERT_TRUE(cell.ok()) << cell.error().describe();
  SteppedClock clock;
  UrSimulatorOptions options = optionsOn(clock);
  options.cellPath = cellPath;
  UrSimulator simulator(options);
  ASSERT_TRUE(simulator.start().ok());
  UrLink link(linkTo(simulator));
  ASSERT_TRUE(link.connect().ok());
  ASSERT_TRUE(link.powerOn(5000ms).ok());
  // The cell's TCP (its flangeToPlatform), the extruder at half speed, a turn of the base.
  const Eigen::Vector3d t = cell->flangeToPlatform.translation() / 1000.0;
  const Eigen::AngleAxisd r(cell->flangeToPlatform.linear());
  const Eigen::Vector3d rv = r.axis() * r.angle();
  char tcp[160];
  std::snprintf(tcp, sizeof tcp, "  set_tcp(p[%.9f, %.9f, %.9f, %.12f, %.12f, %.12f])\n", t.x(), t.y(), t.z(), rv.x(),
                rv.y(), rv.z());
  std::string program = "def turn():\n" + std::string(tcp) + "  set_standard_analog_out(0, 0.5)\n  movej([";
  for (int j = 0; j < 6; ++j)
    program += std::to_string(cell->home[static_cast<std::size_t>(j)] + (j == 0 ? 0.3 : 0.0)) + (j < 5 ? ", " : "");
  program += "], a=1.4, v=1.05)\nend\n";
  ASSERT_TRUE(link.sendProgram(program).ok());
  ASSERT_TRUE(eventually([&] { return simulator.state().programsFinished == 1; }, 5000ms));
  const auto trace = simulator.trace();
  ASSERT_GT(trace.size(), 10u);
  for (const auto& record : trace) {
    ASSERT_TRUE(record.hasCell);
    multidir::robot::Joints q{};
    std::copy(record.joints.begin(), record.joints.end(), q.begin());
    const Eigen::Vector3d expected = multidir::robot::platformPose(*cell, q).inverse() * cell->nozzleTipMm;
    const Eigen::Vector3d traced(record.nozzleInPlatform[0], record.nozzleInPlatform[1], record.nozzleInPlatform[2]);
    EXPECT_LT((traced - expected).norm(), 1e-6) << record.time;
  }
  EXPECT_DOUBLE_EQ(trace.back().filamentMmPerS, 0.5 * cell->maxFilamentMmPerS);
}

// The program's movel register (written by write_output_integer_register) reaches the link over RTDE, the
// real-time interface not carrying the registers; with it the controller time of its package.
TEST(UrLink, TheProgramsMovelRegisterReachesTheLinkOverRtde) {
  SteppedClock clock;
  UrSimulator simulator(optionsOn(clock));
  ASSERT_TRUE(simulator.start().ok());
  UrLink link(linkTo(simulator));
  ASSERT_TRUE(link.connect().ok());
  ASSERT_TRUE(link.powerOn(5000ms).ok()) << link.status().robotMode;
  EXPECT_EQ(link.status().movelRegister, 0);
  ASSERT_TRUE(link.sendProgram("def numbered():\n  write_output_integer_register(24, 7)\n  sleep(2)\n"
                               "  write_output_integer_register(24, 9)\nend\n")
                  .ok());
  ASSERT_TRUE(eventually([&] { return link.status().movelRegister == 7; }, 3000ms));
  const double sevenAt = link.status().movelRegisterTime;
  EXPECT_GT(sevenAt, 0.0);
  ASSERT_TRUE(eventually([&] { return link.status().movelRegister == 9; }, 5000ms));
  // The package that brought 9 is a later one of the controller's (the first seen with 7 may come late, so no
  // more than that can be said of the 2 s between the writes).
  EXPECT_GT(link.status().movelRegisterTime, sevenAt);
  EXPECT_LE(link.status().movelRegisterTime, link.status().controllerTime + 0.1);
}

}  // namespace

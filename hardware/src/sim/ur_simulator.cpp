// The UR controller's four client interfaces on loopback sockets, in front of sim::UrController.
#include "multidir/hardware/ur_simulator.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <condition_variable>
#include <fstream>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>
#include <tuple>

#include "multidir/robot/cell.h"
#include "multidir/robot/ur_kinematics.h"
#include "sim/listen_socket.h"
#include "sim/ur_controller.h"
#include "ur/rtde_wire.h"
#include "ur/ur_wire.h"

namespace multidir::hardware {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kBacklog = 16;
constexpr std::size_t kMaxUnsent = 1 << 20;          // a client that does not read loses real-time packages
constexpr std::size_t kMaxProgramBytes = 64u << 20;  // a secondary-interface program larger than this is refused
constexpr int kMaxTicksPerLoop = 12500;              // 100 simulated seconds, then the sockets are served again
// Real time spent on ticks before the sockets are served again: a simulator that fell behind its clock (a loaded
// machine) catches up in slices, so its clients still get a package well within their silence limit (1 s).
constexpr std::chrono::milliseconds kMaxTickingPerLoop{20};
constexpr const char* kGreeting = "Connected: Universal Robots Dashboard Server\n";

enum class Port { Dashboard, Secondary, Realtime, Rtde };
constexpr int kPorts = 4;

core::Error invalid(const std::string& where, const std::string& message) {
  return core::Error{core::ErrorCode::InvalidParameter, message, where};
}

std::string csvNumber(double value, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// How far the secondary interface's text has been read for a program's end: the lines before `scanned` are
// read, and `sawFirst` says whether a first line (a def, or a one-line program) was among them. Kept per client
// so that each chunk is read once: reading the whole text again after every chunk took seconds on a program of
// megabytes, on the thread that must send the real-time state every 8 ms.
struct ProgramScan {
  std::size_t scanned = 0;
  bool sawFirst = false;
};

// A top-level `end` (no indentation) closes a program; a first line that is not a def is a program of itself.
bool programComplete(const std::string& text, ProgramScan& scan) {
  while (scan.scanned < text.size()) {
    const std::size_t begin = scan.scanned;
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) return false;
    scan.scanned = end + 1;
    if (end > begin && text[end - 1] == '\r') --end;
    const std::size_t content = text.find_first_not_of(" \t", begin);
    if (content >= end || text[content] == '#') continue;
    if (!scan.sawFirst && text.compare(content, 4, "def ") != 0) return true;
    scan.sawFirst = true;
    if (text.compare(begin, 3, "end") == 0) {
      const std::size_t after = text.find_first_not_of(" \t", begin + 3);
      if (after >= end) return true;
    }
  }
  return false;
}

}  // namespace

const char* urSimulatorFaultName(UrSimulatorFault fault) {
  switch (fault) {
    case UrSimulatorFault::None:
      return "none";
    case UrSimulatorFault::ProtectiveStop:
      return "protective-stop";
    case UrSimulatorFault::EmergencyStop:
      return "emergency-stop";
    case UrSimulatorFault::LinkDrop:
      return "link-drop";
    case UrSimulatorFault::ProgramError:
      return "program-error";
  }
  return "none";
}

core::Result<UrSimulatorFault> parseUrSimulatorFault(const std::string& name) {
  for (UrSimulatorFault fault :
       {UrSimulatorFault::None, UrSimulatorFault::ProtectiveStop, UrSimulatorFault::EmergencyStop,
        UrSimulatorFault::LinkDrop, UrSimulatorFault::ProgramError})
    if (name == urSimulatorFaultName(fault)) return fault;
  return invalid("--fault", "'" + name +
                                "' is not a fault of the UR simulator: protective-stop, emergency-stop, link-drop or "
                                "program-error");
}

class UrSimulator::Impl {
 public:
  explicit Impl(UrSimulatorOptions options) : m_options(std::move(options)) {
    if (!m_options.steadyNow) m_options.steadyNow = [] { return Clock::now(); };
  }
  ~Impl() { stop(); }

  core::Status start() {
    if (m_thread.joinable()) return core::Done{};
    core::Result<robot::ArmModel> arm = robot::armModel(m_options.model);
    if (!arm) return invalid("model", arm.error().message);
    if (!(m_options.speed > 0.0) || m_options.speed > 100000.0)
      return invalid("--speed", "the speed must be above 0 and at most 100000");
    for (int port : {m_options.dashboardPort, m_options.secondaryPort, m_options.realtimePort, m_options.rtdePort})
      if (port < 0 || port > 65535) return invalid("port", "must be between 0 and 65535");
    if (m_options.fault != UrSimulatorFault::None && m_options.faultAtSeconds < 0.0 && m_options.faultAtLine <= 0)
      return invalid("fault", "a fault needs a time (seconds after the first program started) or a line");
    robot::Joints initial{};
    std::copy(m_options.initialJoints.begin(), m_options.initialJoints.end(), initial.begin());
    robot::ArmModel model = *arm;
    std::size_t maxProgramBytes = robot::kDefaultMaxProgramBytes;
    std::optional<robot::Cell> cellBodies;  // the cell's bodies and table: the arm's collisions (no cell: none)
    if (!m_options.cellPath.empty()) {
      core::Result<robot::Cell> cell = robot::loadCell(m_options.cellPath);
      if (!cell) return invalid("--cell", cell.error().describe());
      if (cell->arm.name != m_options.model)
        return invalid("--cell", "the cell " + m_options.cellPath + " is for a " + cell->arm.name + ", not a " +
                                     m_options.model + ": simulate --ur " + cell->arm.name);
      model = cell->arm;
      initial = cell->home;
      m_nozzleTip = cell->nozzleTipMm;
      m_maxFilamentMmPerS = cell->maxFilamentMmPerS;
      maxProgramBytes = cell->maxProgramBytes;
      cellBodies = *cell;
    }
    if (m_options.maxProgramBytes > 0) maxProgramBytes = m_options.maxProgramBytes;
    m_controller.emplace(model, initial);
    m_controller->setMaxProgramBytes(maxProgramBytes);
    if (cellBodies) m_controller->watchCollisions(*cellBodies);
    if (!m_options.tracePath.empty()) {
      m_traceFile.open(m_options.tracePath, std::ios::trunc);
      if (!m_traceFile)
        return core::Error{core::ErrorCode::WriteFailed,
                           "cannot write the trace file: check that its folder exists and is writable",
                           m_options.tracePath};
      m_traceFile << "time_s,q1_rad,q2_rad,q3_rad,q4_rad,q5_rad,q6_rad,x_mm,y_mm,z_mm,rx_rad,ry_rad,rz_rad,"
                     "analog_out0,analog_out1,nozzle_c,program,line,nozzle_x_mm,nozzle_y_mm,nozzle_z_mm,"
                     "filament_mm_s\n";
    }
    const int ports[kPorts] = {m_options.dashboardPort, m_options.secondaryPort, m_options.realtimePort,
                               m_options.rtdePort};
    for (int i = 0; i < kPorts; ++i) {
      core::Result<int> fd = sim::listenTcp(m_options.listenAddress, ports[i], kBacklog);
      if (!fd) {
        closeListeners();
        return fd.error();
      }
      m_listen[i] = *fd;
      sockaddr_in bound{};
      socklen_t length = sizeof bound;
      if (getsockname(m_listen[i], reinterpret_cast<sockaddr*>(&bound), &length) == 0)
        m_port[i] = ntohs(bound.sin_port);
    }
    m_started = m_options.steadyNow();
    m_quit = false;
    m_thread = std::thread([this] { loop(); });
    return core::Done{};
  }

  void stop() {
    m_quit = true;
    if (m_thread.joinable()) m_thread.join();
    std::lock_guard<std::mutex> lock(m_mutex);
    for (Client& client : m_clients) ::close(client.fd);
    m_clients.clear();
    closeListeners();
    if (m_traceFile.is_open()) m_traceFile.close();
  }

  int port(int i) const { return m_port[i]; }

  void protectiveStop(const std::string& reason) {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_controller) m_controller->protectiveStop(reason);
  }
  void pressEmergencyStop() {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_controller) m_controller->pressEmergencyStop();
  }
  void releaseEmergencyStop() {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_controller) m_controller->releaseEmergencyStop();
  }
  void programError(const std::string& text) {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_controller) m_controller->programError(text);
  }
  void dropLinks() {
    std::lock_guard<std::mutex> lock(m_mutex);
    dropLinksLocked();
  }
  void restoreLinks() {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_linkDropped = false;
    m_restoreAt.reset();
  }

  UrSimulatorState state() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    UrSimulatorState s;
    if (!m_controller) return s;
    const sim::UrController& c = *m_controller;
    s.time = c.time();
    s.robotMode = ur::urRobotModeName(c.robotMode());
    s.safetyMode = ur::urSafetyModeName(c.safetyMode());
    s.programState = ur::urProgramStateName(c.programState());
    s.programName = c.programName();
    s.line = c.currentLine();
    std::copy(c.joints().begin(), c.joints().end(), s.joints.begin());
    s.atRest = c.atRest();
    s.nozzleC = c.nozzleC();
    s.analogOut = {c.analogOut(0), c.analogOut(1)};
    for (int i = 0; i < 8; ++i) s.digitalOut |= (c.digitalOut(i) ? 1u : 0u) << i;
    s.lastFault = c.lastFault();
    s.programsReceived = m_programs.size();
    s.programsFinished = c.programsFinished();
    s.linkDropped = m_linkDropped;
    s.connections = static_cast<int>(m_clients.size());
    return s;
  }
  std::vector<UrTraceRecord> trace() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_trace;
  }
  std::vector<UrDashboardRecord> dashboardLog() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_dashboardLog;
  }
  std::vector<std::string> programsReceived() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_programs;
  }
  bool waitForSimulatedTime(double seconds, std::chrono::milliseconds limit) const {
    std::unique_lock<std::mutex> lock(m_mutex);
    return m_advanced.wait_for(lock, limit, [&] { return m_controller && m_controller->time() >= seconds - 1e-9; });
  }

 private:
  struct Client {
    int fd = -1;
    Port port = Port::Dashboard;
    std::string received;
    ProgramScan scan;  // the secondary interface: how far `received` has been read for a program's end
    std::string unsent;
    bool closing = false;
    // RTDE: the output recipe's variables (set up by the client), sent every tick once started.
    std::vector<std::string> rtdeOutputs;
    std::vector<std::string> rtdeTypes;
    bool rtdeStarted = false;
  };

  void closeListeners() {
    for (int& fd : m_listen) {
      if (fd >= 0) ::close(fd);
      fd = -1;
    }
  }

  void dropLinksLocked() {
    for (Client& client : m_clients) ::close(client.fd);
    m_clients.clear();
    m_linkDropped = true;
  }

  void queue(Client& client, const std::string& bytes) {
    if (client.unsent.size() + bytes.size() > kMaxUnsent) return;  // a client that does not read
    client.unsent += bytes;
  }

  void accept(int index) {
    for (int i = 0; i < 64; ++i) {
      const int fd = ::accept4(m_listen[index], nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd < 0) return;
      if (m_linkDropped) {
        ::close(fd);
        continue;
      }
      Client client;
      client.fd = fd;
      client.port = static_cast<Port>(index);
      if (client.port == Port::Dashboard) client.unsent = kGreeting;
      if (client.port == Port::Secondary) {
        ur::UrRobotMessage version;
        version.kind = ur::UrRobotMessage::Kind::Version;
        version.text = "URControl";
        const std::vector<std::uint8_t> bytes = ur::encodeRobotMessage(version);
        client.unsent.assign(bytes.begin(), bytes.end());
      }
      m_clients.push_back(std::move(client));
    }
  }

  void serve(Client& client) {
    if (client.port == Port::Dashboard) {
      std::size_t end;
      while ((end = client.received.find('\n')) != std::string::npos) {
        const std::string command = client.received.substr(0, end);
        client.received.erase(0, end + 1);
        bool quit = false;
        const std::string reply = m_controller->dashboard(command, quit);
        m_dashboardLog.push_back(UrDashboardRecord{m_controller->time(), command, reply});
        queue(client, reply + "\n");
        if (quit) client.closing = true;
      }
      return;
    }
    if (client.port == Port::Secondary) {
      if (client.received.size() > kMaxProgramBytes) {
        client.received.clear();
        client.scan = {};
        client.closing = true;
        return;
      }
      if (programComplete(client.received, client.scan)) {
        m_programs.push_back(client.received);
        m_controller->receiveProgram(client.received);
        client.received.clear();
        client.scan = {};
      }
      return;
    }
    if (client.port == Port::Rtde) {
      serveRtde(client);
      return;
    }
    client.received.clear();  // the real-time interface reads nothing MultiDir sends
  }

  // RTDE's requests (ur/rtde_wire.h): protocol version 2 accepted, one output recipe (id 1), start, pause.
  // Inputs are not served: setting them up is refused with recipe id 0, as a controller refuses a recipe whose
  // inputs another client holds.
  void serveRtde(Client& client) {
    while (true) {
      std::size_t used = 0;
      const auto* bytes = reinterpret_cast<const std::uint8_t*>(client.received.data());
      const std::optional<ur::RtdePackage> request = ur::decodeRtde(bytes, client.received.size(), used);
      if (used == std::numeric_limits<std::size_t>::max()) {
        client.closing = true;
        return;
      }
      if (!request) return;
      client.received.erase(0, used);
      const auto reply = [&](const std::vector<std::uint8_t>& payload) {
        const std::vector<std::uint8_t> package = ur::encodeRtde(request->type, payload);
        queue(client, std::string(package.begin(), package.end()));
      };
      const std::vector<std::uint8_t>& p = request->payload;
      switch (request->type) {
        case ur::RtdeType::RequestProtocolVersion: {
          const bool accepted = p.size() == 2 && ((p[0] << 8) | p[1]) == ur::kRtdeProtocolVersion;
          reply(std::vector<std::uint8_t>(1, accepted ? 1 : 0));
          break;
        }
        case ur::RtdeType::SetupOutputs: {
          if (client.rtdeStarted || p.size() < 8) {
            reply(std::vector<std::uint8_t>(1, 0));
            break;
          }
          const std::string names(p.begin() + 8, p.end());
          client.rtdeOutputs.clear();
          client.rtdeTypes.clear();
          std::string types;
          bool known = true;
          for (std::size_t begin = 0; begin <= names.size();) {
            std::size_t end = names.find(',', begin);
            if (end == std::string::npos) end = names.size();
            client.rtdeOutputs.push_back(names.substr(begin, end - begin));
            client.rtdeTypes.push_back(ur::rtdeOutputType(client.rtdeOutputs.back()));
            known = known && client.rtdeTypes.back() != "NOT_FOUND";
            types += (types.empty() ? "" : ",") + client.rtdeTypes.back();
            begin = end + 1;
          }
          if (!known) client.rtdeOutputs.clear();
          std::vector<std::uint8_t> payload(types.size() + 1, known ? 1 : 0);
          std::copy(types.begin(), types.end(), payload.begin() + 1);
          reply(payload);
          break;
        }
        case ur::RtdeType::SetupInputs:
          reply(std::vector<std::uint8_t>(1, 0));
          break;
        case ur::RtdeType::Start:
          client.rtdeStarted = !client.rtdeOutputs.empty();
          reply(std::vector<std::uint8_t>(1, client.rtdeStarted ? 1 : 0));
          break;
        case ur::RtdeType::Pause:
          client.rtdeStarted = false;
          reply(std::vector<std::uint8_t>(1, 1));
          break;
        default:
          break;  // a data package for inputs nobody set up, or a type this subset does not have: ignored
      }
    }
  }

  // One RTDE data package of the client's recipe with the controller's state now.
  std::string rtdeData(const Client& client) const {
    std::vector<std::uint8_t> payload(1, 1);  // the recipe id
    const ur::UrRealtimeState state = m_controller->realtime();
    for (const std::string& name : client.rtdeOutputs) {
      if (name == "timestamp") {
        ur::putDouble(payload, state.time);
      } else if (name == "actual_TCP_pose") {
        for (double v : state.toolVectorActual) ur::putDouble(payload, v);
      } else if (name == "runtime_state") {
        ur::putU32(payload, static_cast<std::uint32_t>(state.programState));
      } else {  // output_int_register_N
        const int index = std::stoi(name.substr(std::string("output_int_register_").size()));
        ur::putU32(payload, static_cast<std::uint32_t>(m_controller->outputIntRegister(index)));
      }
    }
    const std::vector<std::uint8_t> package = ur::encodeRtde(ur::RtdeType::DataPackage, payload);
    return std::string(package.begin(), package.end());
  }

  void pollOnce() {
    std::vector<pollfd> fds;
    for (int fd : m_listen) fds.push_back(pollfd{fd, POLLIN, 0});
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      for (const Client& client : m_clients)
        fds.push_back(pollfd{client.fd, static_cast<short>(POLLIN | (client.unsent.empty() ? 0 : POLLOUT)), 0});
    }
    ::poll(fds.data(), fds.size(), 1);
    std::lock_guard<std::mutex> lock(m_mutex);
    for (int i = 0; i < kPorts; ++i)
      if (fds[static_cast<std::size_t>(i)].revents & POLLIN) accept(i);
    for (Client& client : m_clients) {
      char buffer[65536];
      while (!client.closing) {
        const ssize_t got = ::recv(client.fd, buffer, sizeof buffer, 0);
        if (got > 0) {
          client.received.append(buffer, static_cast<std::size_t>(got));
          continue;
        }
        if (got == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) client.closing = true;
        break;
      }
      if (!client.closing) serve(client);
    }
    advance();
    for (Client& client : m_clients) {
      while (!client.unsent.empty()) {
        const ssize_t sent = ::send(client.fd, client.unsent.data(), client.unsent.size(), MSG_NOSIGNAL);
        if (sent > 0) {
          client.unsent.erase(0, static_cast<std::size_t>(sent));
          continue;
        }
        if (sent < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) client.closing = true;
        break;
      }
    }
    for (const Client& client : m_clients)
      if (client.closing) ::close(client.fd);
    m_clients.erase(std::remove_if(m_clients.begin(), m_clients.end(), [](const Client& c) { return c.closing; }),
                    m_clients.end());
  }

  // The controller's ticks up to the clock; the newest state to every real-time client, the messages to the
  // secondary clients. Called with the mutex held.
  void advance() {
    const Clock::time_point now = m_options.steadyNow();
    if (m_restoreAt && now >= *m_restoreAt) {
      m_linkDropped = false;
      m_restoreAt.reset();
    }
    const double target = std::chrono::duration<double>(now - m_started).count() * m_options.speed;
    int ticks = 0;
    // A real controller sends every tick's package; faster than real time the newest is sent, and with it every
    // tick whose modes or program state changed, so a client sees every program start and end.
    std::string packages;
    // RTDE's packages: the same ticks as the real-time interface's, per client (each has its own recipe).
    std::vector<std::string> rtde(m_clients.size());
    const auto modes = [&] {
      return std::make_tuple(m_controller->programState(), m_controller->robotMode(), m_controller->safetyMode());
    };
    const Clock::time_point ticking = Clock::now();
    const auto mayTick = [&] {
      return m_controller->time() + sim::kUrTickSeconds <= target + 1e-9 && ticks < kMaxTicksPerLoop &&
             Clock::now() - ticking < kMaxTickingPerLoop;
    };
    bool more = mayTick();
    while (more) {
      injectScheduledFault(now);
      const auto before = modes();
      m_controller->tick();
      ++ticks;
      if (!m_firstProgramAt && !m_controller->programName().empty()) m_firstProgramAt = m_controller->time();
      for (sim::UrTraceSample& sample : m_controller->takeTrace()) keep(sample);
      more = mayTick();
      const bool last = !more;
      if (modes() != before || last) {
        const std::vector<std::uint8_t> bytes = ur::encodeRealtime(m_controller->realtime());
        packages.append(bytes.begin(), bytes.end());
        for (std::size_t c = 0; c < m_clients.size(); ++c)
          if (m_clients[c].port == Port::Rtde && m_clients[c].rtdeStarted) rtde[c] += rtdeData(m_clients[c]);
      }
    }
    std::string messages;
    for (const ur::UrRobotMessage& message : m_controller->takeMessages()) {
      const std::vector<std::uint8_t> bytes = ur::encodeRobotMessage(message);
      messages.append(bytes.begin(), bytes.end());
    }
    for (std::size_t c = 0; c < m_clients.size(); ++c)
      if (!rtde[c].empty()) queue(m_clients[c], rtde[c]);
    for (Client& client : m_clients) {
      if (client.port == Port::Realtime && !packages.empty()) queue(client, packages);
      if (client.port == Port::Secondary && !messages.empty()) queue(client, messages);
    }
    if (ticks > 0) m_advanced.notify_all();
  }

  void injectScheduledFault(Clock::time_point now) {
    if (m_faultInjected || m_options.fault == UrSimulatorFault::None) return;
    const bool byTime = m_options.faultAtSeconds >= 0.0 && m_firstProgramAt &&
                        m_controller->time() - *m_firstProgramAt >= m_options.faultAtSeconds;
    const bool byLine = m_options.faultAtLine > 0 && m_controller->currentLine() == m_options.faultAtLine &&
                        m_controller->programState() == ur::UrProgramState::Playing;
    if (!byTime && !byLine) return;
    m_faultInjected = true;
    switch (m_options.fault) {
      case UrSimulatorFault::ProtectiveStop:
        m_controller->protectiveStop("the simulator's injected fault (a collision detected)");
        break;
      case UrSimulatorFault::EmergencyStop:
        m_controller->pressEmergencyStop();
        break;
      case UrSimulatorFault::ProgramError:
        m_controller->programError("the simulator's injected program error");
        break;
      case UrSimulatorFault::LinkDrop:
        dropLinksLocked();
        m_restoreAt = now + std::chrono::milliseconds(static_cast<long>(m_options.linkDropSeconds * 1000.0));
        break;
      case UrSimulatorFault::None:
        break;
    }
  }

  void keep(const sim::UrTraceSample& sample) {
    std::array<double, 3> nozzle{};
    if (m_nozzleTip) {
      std::array<double, 6> metres = sample.tcp;
      for (std::size_t i = 0; i < 3; ++i) metres[i] /= 1000.0;
      const Eigen::Vector3d inPlatform = sim::urPoseToIsometry(metres).inverse() * *m_nozzleTip;
      nozzle = {inPlatform.x(), inPlatform.y(), inPlatform.z()};
    }
    const double filament = sample.analogOut0 * m_maxFilamentMmPerS;
    if (m_traceFile.is_open()) {
      std::string row = csvNumber(sample.time, 3);
      for (double q : sample.q) row += "," + csvNumber(q, 9);
      for (std::size_t i = 0; i < 6; ++i) row += "," + csvNumber(sample.tcp[i], i < 3 ? 6 : 9);
      row += "," + csvNumber(sample.analogOut0, 6) + "," + csvNumber(sample.analogOut1, 6) + "," +
             csvNumber(sample.nozzleC, 2) + "," + sample.program + "," + std::to_string(sample.line);
      if (m_nozzleTip)
        row += "," + csvNumber(nozzle[0], 6) + "," + csvNumber(nozzle[1], 6) + "," + csvNumber(nozzle[2], 6) + "," +
               csvNumber(filament, 6) + "\n";
      else
        row += ",,,,\n";
      m_traceFile << row;
    }
    if (!m_options.keepTrace) return;
    UrTraceRecord record;
    record.time = sample.time;
    std::copy(sample.q.begin(), sample.q.end(), record.joints.begin());
    record.tcp = sample.tcp;
    record.analogOut0 = sample.analogOut0;
    record.analogOut1 = sample.analogOut1;
    record.nozzleC = sample.nozzleC;
    record.program = sample.program;
    record.line = sample.line;
    record.hasCell = m_nozzleTip.has_value();
    record.nozzleInPlatform = nozzle;
    record.filamentMmPerS = filament;
    m_trace.push_back(std::move(record));
  }

  void loop() {
    while (!m_quit) pollOnce();
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_traceFile.is_open()) m_traceFile.flush();
  }

  UrSimulatorOptions m_options;
  mutable std::mutex m_mutex;
  mutable std::condition_variable m_advanced;
  std::optional<sim::UrController> m_controller;
  int m_listen[kPorts] = {-1, -1, -1, -1};
  int m_port[kPorts] = {0, 0, 0, 0};
  std::vector<Client> m_clients;
  Clock::time_point m_started{};
  std::atomic<bool> m_quit{false};
  std::thread m_thread;
  bool m_linkDropped = false;
  std::optional<Clock::time_point> m_restoreAt;
  bool m_faultInjected = false;
  std::optional<double> m_firstProgramAt;
  std::vector<UrTraceRecord> m_trace;
  std::vector<UrDashboardRecord> m_dashboardLog;
  std::vector<std::string> m_programs;
  std::ofstream m_traceFile;
  std::optional<Eigen::Vector3d> m_nozzleTip;  // base frame, mm (with a cell)
  double m_maxFilamentMmPerS = 0.0;
};

UrSimulator::UrSimulator(UrSimulatorOptions options) : m_impl(std::make_unique<Impl>(std::move(options))) {}
UrSimulator::~UrSimulator() = default;
core::Status UrSimulator::start() { return m_impl->start(); }
void UrSimulator::stop() { m_impl->stop(); }
int UrSimulator::dashboardPort() const { return m_impl->port(0); }
int UrSimulator::secondaryPort() const { return m_impl->port(1); }
int UrSimulator::realtimePort() const { return m_impl->port(2); }
int UrSimulator::rtdePort() const { return m_impl->port(3); }
void UrSimulator::protectiveStop(const std::string& reason) { m_impl->protectiveStop(reason); }
void UrSimulator::pressEmergencyStop() { m_impl->pressEmergencyStop(); }
void UrSimulator::releaseEmergencyStop() { m_impl->releaseEmergencyStop(); }
void UrSimulator::programError(const std::string& text) { m_impl->programError(text); }
void UrSimulator::dropLinks() { m_impl->dropLinks(); }
void UrSimulator::restoreLinks() { m_impl->restoreLinks(); }
UrSimulatorState UrSimulator::state() const { return m_impl->state(); }
std::vector<UrTraceRecord> UrSimulator::trace() const { return m_impl->trace(); }
std::vector<UrDashboardRecord> UrSimulator::dashboardLog() const { return m_impl->dashboardLog(); }
std::vector<std::string> UrSimulator::programsReceived() const { return m_impl->programsReceived(); }
bool UrSimulator::waitForSimulatedTime(double seconds, std::chrono::milliseconds limit) const {
  return m_impl->waitForSimulatedTime(seconds, limit);
}

}  // namespace multidir::hardware

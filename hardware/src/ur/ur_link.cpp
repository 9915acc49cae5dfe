#include "multidir/hardware/ur_link.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <thread>

#include "multidir/robot/robot_program.h"
#include "ur/rtde_wire.h"
#include "ur/ur_wire.h"

namespace multidir::hardware {
namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr std::size_t kMaxPackage = 1u << 20;
constexpr double kRestSpeed = 1e-6;  // rad/s: a joint slower than this is at rest

core::Error unreachable(const std::string& where, const std::string& message) {
  return core::Error{core::ErrorCode::DeviceUnreachable, message, where};
}

// A TCP connection to host:port within `limit`; -1 and `why` when it fails.
int connectTcp(const std::string& host, int port, std::chrono::milliseconds limit, std::string& why) {
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0 || found == nullptr) {
    why = "the host name " + host + " cannot be resolved";
    return -1;
  }
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) {
    freeaddrinfo(found);
    why = std::strerror(errno);
    return -1;
  }
  const int result = ::connect(fd, found->ai_addr, found->ai_addrlen);
  freeaddrinfo(found);
  if (result != 0 && errno != EINPROGRESS) {
    why = std::strerror(errno);
    ::close(fd);
    return -1;
  }
  pollfd p{fd, POLLOUT, 0};
  if (::poll(&p, 1, static_cast<int>(limit.count())) != 1) {
    why = "no answer within " + std::to_string(limit.count()) + " ms";
    ::close(fd);
    return -1;
  }
  int error = 0;
  socklen_t length = sizeof error;
  getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length);
  if (error != 0) {
    why = std::strerror(error);
    ::close(fd);
    return -1;
  }
  const int yes = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
  return fd;
}

bool sendAll(int fd, const std::string& bytes, std::chrono::milliseconds limit) {
  std::size_t done = 0;
  const auto deadline = Clock::now() + limit;
  while (done < bytes.size()) {
    const ssize_t sent = ::send(fd, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
    if (sent > 0) {
      done += static_cast<std::size_t>(sent);
      continue;
    }
    if (sent < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return false;
    if (Clock::now() >= deadline) return false;
    pollfd p{fd, POLLOUT, 0};
    ::poll(&p, 1, 10);
  }
  return true;
}

}  // namespace

std::string UrLinkMessage::describe() const {
  switch (kind) {
    case Kind::Text:
      return "textmsg: " + text;
    case Kind::RuntimeException:
      return "runtime exception at line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + text;
    case Kind::ErrorCode:
      return "C" + std::to_string(code) + ": " + text;
  }
  return text;
}

core::Result<UrLinkSettings> parseUrAddress(const std::string& text) {
  UrLinkSettings settings;
  const std::size_t colon = text.rfind(':');
  settings.host = colon == std::string::npos ? text : text.substr(0, colon);
  if (settings.host.empty())
    return core::Error{core::ErrorCode::InvalidParameter,
                       "'" + text + "' names no host: give HOST or HOST:PORT, such as 192.168.0.40 or 127.0.0.1:29999",
                       "--robot"};
  if (colon != std::string::npos) {
    const std::string portText = text.substr(colon + 1);
    char* end = nullptr;
    const long port = std::strtol(portText.c_str(), &end, 10);
    if (portText.empty() || *end != '\0' || port < 1 || port > 65532)
      return core::Error{core::ErrorCode::InvalidParameter,
                         "the port in '" + text +
                             "' must be a whole number from 1 to 65532 (the dashboard's; the "
                             "secondary, real-time and RTDE interfaces are the next three)",
                         "--robot"};
    settings.dashboardPort = static_cast<int>(port);
    settings.secondaryPort = static_cast<int>(port) + 1;
    settings.realtimePort = static_cast<int>(port) + 2;
    settings.rtdePort = static_cast<int>(port) + 3;
  }
  return settings;
}

class UrLink::Impl {
 public:
  explicit Impl(UrLinkSettings settings) : m_settings(std::move(settings)) {}
  ~Impl() { disconnect(); }

  core::Status connect() {
    if (m_thread.joinable()) return core::Done{};
    std::string why;
    if (!open(why)) return unreachable(m_settings.host, why);
    // The first state, so status() describes the arm when connect() returns.
    const auto deadline = Clock::now() + m_settings.silenceLimit;
    while (Clock::now() < deadline && m_packages == 0) readStreams(20);
    if (m_packages == 0) {
      closeAll();
      return unreachable(m_settings.host + ":" + std::to_string(m_settings.realtimePort),
                         "the real-time interface sent no state package within " +
                             std::to_string(m_settings.silenceLimit.count()) + " ms: is this a UR controller?");
    }
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_status.connected = true;
      m_status.linkProblem.clear();
    }
    m_quit = false;
    m_thread = std::thread([this] { work(); });
    return core::Done{};
  }

  void disconnect() {
    m_quit = true;
    if (m_thread.joinable()) m_thread.join();
    closeAll();
    std::lock_guard<std::mutex> lock(m_mutex);
    m_status.connected = false;
  }

  core::Result<std::string> dashboard(const std::string& command) {
    std::lock_guard<std::mutex> dash(m_dashboardMutex);
    if (m_fd[0] < 0) return unreachable("dashboard", "the link to the robot is down: " + problem());
    if (!sendAll(m_fd[0], command + "\n", m_settings.replyTimeout))
      return unreachable("dashboard", "the dashboard server did not take '" + command + "'");
    std::string reply;
    if (!readLine(m_fd[0], reply, m_settings.replyTimeout))
      return unreachable("dashboard", "the dashboard server did not answer '" + command + "' within " +
                                          std::to_string(m_settings.replyTimeout.count()) + " ms");
    return reply;
  }

  core::Status powerOn(std::chrono::milliseconds limit) {
    const auto waitMode = [&](const std::string& wanted) {
      const auto deadline = Clock::now() + limit;
      while (Clock::now() < deadline) {
        if (status().robotMode == wanted) return true;
        std::this_thread::sleep_for(10ms);
      }
      return status().robotMode == wanted;
    };
    UrLinkStatus s = status();
    if (s.robotMode == "RUNNING") return core::Done{};
    if (s.robotMode == "POWER_OFF") {
      core::Result<std::string> reply = dashboard("power on");
      if (!reply) return reply.error();
      if (*reply != "Powering on")
        return core::Error{core::ErrorCode::DeviceFault,
                           "the robot refused to power on (\"" + *reply + "\"; safety mode " + s.safetyMode +
                               "): release the emergency stop or unlock the protective stop, then try again",
                           "power on"};
      if (!waitMode("IDLE") && status().robotMode != "RUNNING")
        return core::Error{core::ErrorCode::DeviceFault,
                           "the robot did not reach IDLE after power on (robot mode " + status().robotMode + ")",
                           "power on"};
    }
    if (status().robotMode != "RUNNING") {
      core::Result<std::string> reply = dashboard("brake release");
      if (!reply) return reply.error();
      if (!waitMode("RUNNING"))
        return core::Error{core::ErrorCode::DeviceFault,
                           "the robot did not reach RUNNING after brake release (robot mode " + status().robotMode +
                               ", \"" + *reply + "\")",
                           "brake release"};
    }
    return core::Done{};
  }

  core::Status sendProgram(const std::string& script) {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (m_status.stop.latched())
        return core::Error{core::ErrorCode::DeviceFault,
                           std::string("a ") + stopKindName(m_status.stop.kind) +
                               " is latched: no program is sent until it is cleared",
                           "program"};
    }
    std::lock_guard<std::mutex> sending(m_sendMutex);
    if (m_fd[1] < 0) return unreachable("secondary interface", "the link to the robot is down: " + problem());
    std::string text = script;
    if (text.empty() || text.back() != '\n') text += '\n';
    if (!sendAll(m_fd[1], text, m_settings.replyTimeout))
      return unreachable("secondary interface", "the program could not be sent");
    return core::Done{};
  }

  void latch(StopKind kind) {
    std::lock_guard<std::mutex> lock(m_mutex);
    // An emergency stop is never downgraded to a stop.
    if (m_status.stop.kind == StopKind::EmergencyStop) return;
    m_status.stop.kind = kind;
    m_status.stop.confirmed = false;
    m_status.stop.problem =
        m_status.connected ? "sent, waiting for the robot to stop" : "the link is down: " + m_status.linkProblem;
    m_nextStopSend = Clock::now();  // the worker sends it at once
  }

  core::Status clearStop() {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_status.stop.latched()) return core::Done{};
    if (!m_status.stop.confirmed)
      return core::Error{core::ErrorCode::InvalidParameter,
                         std::string("the ") + stopKindName(m_status.stop.kind) + " is not confirmed yet (" +
                             m_status.stop.problem + "): it stays latched",
                         "stop"};
    m_status.stop = StopLatch{};
    return core::Done{};
  }

  UrLinkStatus status() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_status;
  }

  std::vector<UrLinkMessage> takeMessages() {
    std::lock_guard<std::mutex> lock(m_mutex);
    std::vector<UrLinkMessage> taken;
    taken.swap(m_messages);
    return taken;
  }

 private:
  std::string problem() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_status.linkProblem.empty() ? std::string("not connected") : m_status.linkProblem;
  }

  bool open(std::string& why) {
    const int ports[4] = {m_settings.dashboardPort, m_settings.secondaryPort, m_settings.realtimePort,
                          m_settings.rtdePort};
    const char* names[4] = {"the dashboard server", "the secondary interface", "the real-time interface",
                            "the RTDE interface"};
    int fds[4] = {-1, -1, -1, -1};
    const auto closeFds = [&] {
      for (int fd : fds)
        if (fd >= 0) ::close(fd);
    };
    for (int i = 0; i < 4; ++i) {
      std::string reason;
      fds[i] = connectTcp(m_settings.host, ports[i], m_settings.replyTimeout, reason);
      if (fds[i] < 0) {
        why = std::string(names[i]) + " at " + m_settings.host + ":" + std::to_string(ports[i]) +
              " cannot be reached (" + reason + ")";
        closeFds();
        return false;
      }
    }
    std::string greeting;
    if (!readLine(fds[0], greeting, m_settings.replyTimeout) ||
        greeting.rfind("Connected: Universal Robots Dashboard Server", 0) != 0) {
      why = "the dashboard server at " + m_settings.host + ":" + std::to_string(ports[0]) +
            " did not greet as UR's does (\"" + greeting + "\")";
      closeFds();
      return false;
    }
    std::string rtdeRest;
    if (!startRtde(fds[3], rtdeRest, why)) {
      why = "the RTDE interface at " + m_settings.host + ":" + std::to_string(ports[3]) + " " + why;
      closeFds();
      return false;
    }
    std::lock_guard<std::mutex> dash(m_dashboardMutex);
    std::lock_guard<std::mutex> sending(m_sendMutex);
    std::lock_guard<std::mutex> streams(m_streamMutex);
    for (int i = 0; i < 4; ++i) m_fd[i] = fds[i];
    m_buffer[0].clear();
    m_buffer[1].clear();
    m_buffer[2] = rtdeRest;
    m_lastPackageAt = Clock::now();
    return true;
  }

  // One RTDE request and its reply (the package of the same type) within the reply timeout; bytes after the
  // reply (data packages that follow a start) are kept in `rest`.
  bool rtdeExchange(int fd, ur::RtdeType type, const std::vector<std::uint8_t>& payload, ur::RtdePackage& reply,
                    std::string& rest, std::string& why) {
    const std::vector<std::uint8_t> request = ur::encodeRtde(type, payload);
    if (!sendAll(fd, std::string(request.begin(), request.end()), m_settings.replyTimeout)) {
      why = "did not take a request";
      return false;
    }
    const auto deadline = Clock::now() + m_settings.replyTimeout;
    while (Clock::now() < deadline) {
      std::size_t used = 0;
      const auto* bytes = reinterpret_cast<const std::uint8_t*>(rest.data());
      const std::optional<ur::RtdePackage> package = ur::decodeRtde(bytes, rest.size(), used);
      if (used == std::numeric_limits<std::size_t>::max()) {
        why = "sent a package that is not RTDE's format";
        return false;
      }
      if (package) {
        rest.erase(0, used);
        if (package->type != type) continue;  // a text message or an earlier recipe's data
        reply = *package;
        return true;
      }
      char buffer[4096];
      const ssize_t got = ::recv(fd, buffer, sizeof buffer, 0);
      if (got > 0) {
        rest.append(buffer, static_cast<std::size_t>(got));
        continue;
      }
      if (got == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        why = "closed the connection";
        return false;
      }
      pollfd p{fd, POLLIN, 0};
      ::poll(&p, 1, 10);
    }
    why = "did not answer within " + std::to_string(m_settings.replyTimeout.count()) + " ms";
    return false;
  }

  // RTDE protocol version 2, the output recipe (timestamp and the movel register, at the control frequency),
  // started.
  bool startRtde(int fd, std::string& rest, std::string& why) {
    ur::RtdePackage reply;
    std::vector<std::uint8_t> version;
    ur::putU16(version, ur::kRtdeProtocolVersion);
    if (!rtdeExchange(fd, ur::RtdeType::RequestProtocolVersion, version, reply, rest, why)) return false;
    if (reply.payload.size() != 1 || reply.payload[0] != 1) {
      why = "refused RTDE protocol version 2 (a controller older than CB3 3.3?)";
      return false;
    }
    std::vector<std::uint8_t> setup;
    ur::putDouble(setup, 125.0);
    const std::string names = "timestamp,output_int_register_" + std::to_string(robot::kMovelRegister);
    setup.insert(setup.end(), names.begin(), names.end());
    if (!rtdeExchange(fd, ur::RtdeType::SetupOutputs, setup, reply, rest, why)) return false;
    const std::string types = reply.payload.size() > 1 ? std::string(reply.payload.begin() + 1, reply.payload.end())
                                                       : std::string();
    if (reply.payload.empty() || reply.payload[0] == 0 || types != "DOUBLE,INT32") {
      why = "refused the output recipe " + names + " (types \"" + types + "\")";
      return false;
    }
    m_rtdeRecipe = reply.payload[0];
    if (!rtdeExchange(fd, ur::RtdeType::Start, {}, reply, rest, why)) return false;
    if (reply.payload.size() != 1 || reply.payload[0] != 1) {
      why = "refused to start sending its outputs";
      return false;
    }
    return true;
  }

  void closeAll() {
    std::lock_guard<std::mutex> dash(m_dashboardMutex);
    std::lock_guard<std::mutex> sending(m_sendMutex);
    std::lock_guard<std::mutex> streams(m_streamMutex);
    for (int& fd : m_fd) {
      if (fd >= 0) ::close(fd);
      fd = -1;
    }
  }

  // Reads one line ending in '\n' (without it) from `fd` within `limit`.
  static bool readLine(int fd, std::string& line, std::chrono::milliseconds limit) {
    line.clear();
    const auto deadline = Clock::now() + limit;
    while (Clock::now() < deadline) {
      char c = 0;
      const ssize_t got = ::recv(fd, &c, 1, 0);
      if (got == 1) {
        if (c == '\n') {
          if (!line.empty() && line.back() == '\r') line.pop_back();
          return true;
        }
        line += c;
        if (line.size() > 65536) return false;
        continue;
      }
      if (got == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) return false;
      pollfd p{fd, POLLIN, 0};
      ::poll(&p, 1, 10);
    }
    return false;
  }

  // Reads what the secondary and real-time interfaces sent, waiting at most `waitMs`; false when one closed
  // or sent what is not UR's format (the reason in m_lost).
  bool readStreams(int waitMs) {
    // Only the worker (or connect() before it starts) reads and replaces the descriptors, so the wait needs no
    // lock: a sender or a dashboard request is never held up by it.
    if (m_fd[1] < 0 || m_fd[2] < 0 || m_fd[3] < 0) return false;
    pollfd fds[3] = {{m_fd[1], POLLIN, 0}, {m_fd[2], POLLIN, 0}, {m_fd[3], POLLIN, 0}};
    ::poll(fds, 3, waitMs);
    std::lock_guard<std::mutex> streams(m_streamMutex);
    if (!readRtde()) return false;
    const char* names[2] = {"the secondary interface", "the real-time interface"};
    for (int i = 0; i < 2; ++i) {
      char buffer[65536];
      while (true) {
        const ssize_t got = ::recv(m_fd[i + 1], buffer, sizeof buffer, 0);
        if (got > 0) {
          m_buffer[i].append(buffer, static_cast<std::size_t>(got));
          continue;
        }
        if (got == 0) {
          m_lost = std::string(names[i]) + " closed the connection";
          return false;
        }
        if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
          m_lost = std::string(names[i]) + ": " + std::strerror(errno);
          return false;
        }
        break;
      }
      std::string& data = m_buffer[i];
      std::size_t at = 0;
      while (data.size() - at >= 4) {
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(data.data() + at);
        const std::uint32_t size = ur::packageSize(bytes, data.size() - at);
        if (size < 5 || size > kMaxPackage) {
          m_lost =
              std::string(names[i]) + " sent a package of " + std::to_string(size) + " bytes, which is not UR's format";
          return false;
        }
        if (data.size() - at < size) break;
        if (i == 0)
          takeMessage(bytes, size);
        else
          takeState(bytes, size);
        at += size;
      }
      data.erase(0, at);
    }
    return true;
  }

  // RTDE's data packages: the movel register with its timestamp. Called with m_streamMutex held.
  bool readRtde() {
    char buffer[65536];
    while (true) {
      const ssize_t got = ::recv(m_fd[3], buffer, sizeof buffer, 0);
      if (got > 0) {
        m_buffer[2].append(buffer, static_cast<std::size_t>(got));
        continue;
      }
      if (got == 0) {
        m_lost = "the RTDE interface closed the connection";
        return false;
      }
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
        m_lost = std::string("the RTDE interface: ") + std::strerror(errno);
        return false;
      }
      break;
    }
    std::string& data = m_buffer[2];
    std::size_t at = 0;
    while (true) {
      std::size_t used = 0;
      const auto* bytes = reinterpret_cast<const std::uint8_t*>(data.data() + at);
      const std::optional<ur::RtdePackage> package = ur::decodeRtde(bytes, data.size() - at, used);
      if (used == std::numeric_limits<std::size_t>::max()) {
        m_lost = "the RTDE interface sent a package that is not RTDE's format";
        return false;
      }
      if (!package) break;
      at += used;
      // Recipe id, timestamp (DOUBLE), the register (INT32).
      if (package->type != ur::RtdeType::DataPackage || package->payload.size() != 13 ||
          package->payload[0] != m_rtdeRecipe)
        continue;
      std::lock_guard<std::mutex> lock(m_mutex);
      m_status.movelRegisterTime = ur::getDouble(package->payload.data() + 1);
      m_status.movelRegister = static_cast<std::int32_t>(ur::getU32(package->payload.data() + 9));
    }
    data.erase(0, at);
    return true;
  }

  void takeMessage(const std::uint8_t* bytes, std::size_t size) {
    const std::optional<ur::UrRobotMessage> m = ur::decodeRobotMessage(bytes, size);
    if (!m || m->kind == ur::UrRobotMessage::Kind::Version) return;
    UrLinkMessage message;
    message.kind = m->kind == ur::UrRobotMessage::Kind::Text               ? UrLinkMessage::Kind::Text
                   : m->kind == ur::UrRobotMessage::Kind::RuntimeException ? UrLinkMessage::Kind::RuntimeException
                                                                           : UrLinkMessage::Kind::ErrorCode;
    message.text = m->text;
    message.line = m->line;
    message.column = m->column;
    message.code = m->code;
    std::lock_guard<std::mutex> lock(m_mutex);
    m_messages.push_back(std::move(message));
  }

  void takeState(const std::uint8_t* bytes, std::size_t size) {
    const std::optional<ur::UrRealtimeState> s = ur::decodeRealtime(bytes, size);
    if (!s) return;
    ++m_packages;
    m_lastPackageAt = Clock::now();
    std::lock_guard<std::mutex> lock(m_mutex);
    m_status.controllerTime = s->time;
    m_status.robotMode = ur::urRobotModeName(s->robotMode);
    m_status.safetyMode = ur::urSafetyModeName(s->safetyMode);
    const std::string previous = m_status.programState;
    m_status.programState = ur::urProgramStateName(s->programState);
    if (previous != "PLAYING" && previous != "PAUSED" && m_status.programState == "PLAYING") ++m_status.programStarts;
    if ((previous == "PLAYING" || previous == "PAUSED") && m_status.programState == "STOPPED") ++m_status.programEnds;
    m_status.joints = s->qActual;
    m_status.jointSpeeds = s->qdActual;
    m_status.tcp = s->toolVectorActual;
    m_status.atRest =
        std::all_of(s->qdActual.begin(), s->qdActual.end(), [](double v) { return std::abs(v) < kRestSpeed; });
    // A latched stop is confirmed by a state sent after it: the program stopped, the arm at rest (and, for an
    // emergency stop, powered off).
    StopLatch& stop = m_status.stop;
    if (stop.latched() && !stop.confirmed && m_stopSentAtPackage && m_packages > *m_stopSentAtPackage &&
        m_status.programState == "STOPPED" && m_status.atRest &&
        (stop.kind != StopKind::EmergencyStop || s->robotMode == ur::UrRobotMode::PowerOff)) {
      stop.confirmed = true;
      stop.problem.clear();
    }
  }

  void lose(const std::string& why) {
    closeAll();
    std::lock_guard<std::mutex> lock(m_mutex);
    m_status.connected = false;
    m_status.linkLost = true;
    m_status.linkProblem = why;
    m_stopSentAtPackage.reset();
    if (m_status.stop.latched()) {
      m_status.stop.confirmed = false;
      m_status.stop.problem = "the link is down (" + why + "): resent when it is back";
    }
  }

  void sendLatchedStop() {
    StopKind kind;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      kind = m_status.stop.kind;
      m_nextStopSend = Clock::now() + m_settings.stopResendInterval;
    }
    std::vector<std::string> commands{"stop"};
    if (kind == StopKind::EmergencyStop) commands.push_back("power off");
    for (const std::string& command : commands) {
      core::Result<std::string> reply = dashboard(command);
      std::lock_guard<std::mutex> lock(m_mutex);
      if (!reply) {
        m_status.stop.problem = reply.error().describe();
        return;
      }
      ++m_status.stop.writes;
    }
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stopSentAtPackage = m_packages;
    if (!m_status.stop.confirmed) m_status.stop.problem = "sent, waiting for the robot to stop";
  }

  void work() {
    while (!m_quit) {
      bool connected;
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        connected = m_status.connected;
      }
      if (!connected) {
        std::string why;
        if (open(why)) {
          bool resend;
          {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_status.connected = true;
            m_status.linkLost = false;
            m_status.linkProblem.clear();
            ++m_status.reconnects;
            resend = m_status.stop.latched();
          }
          // The stop rule: a latched stop goes first after a reconnect, before anything else is sent.
          if (resend) sendLatchedStop();
        } else {
          {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_status.linkProblem = why;
            if (m_status.stop.latched())
              m_status.stop.problem = "the link is down (" + why + "): resent when it is back";
          }
          const auto until = Clock::now() + m_settings.reconnectInterval;
          while (!m_quit && Clock::now() < until) std::this_thread::sleep_for(10ms);
        }
        continue;
      }
      if (!readStreams(5)) {
        lose(m_lost);
        continue;
      }
      if (Clock::now() - m_lastPackageAt > m_settings.silenceLimit) {
        lose("the real-time interface sent nothing for " + std::to_string(m_settings.silenceLimit.count()) + " ms");
        continue;
      }
      bool send;
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        send = m_status.stop.latched() && !m_status.stop.confirmed && Clock::now() >= m_nextStopSend;
      }
      if (send) sendLatchedStop();
    }
  }

  UrLinkSettings m_settings;
  mutable std::mutex m_mutex;   // m_status, m_messages, m_nextStopSend, m_stopSentAtPackage
  std::mutex m_dashboardMutex;  // the dashboard socket: one request and its reply at a time
  std::mutex m_sendMutex;       // writes to the secondary interface: one program at a time
  std::mutex m_streamMutex;     // reads of the secondary and real-time interfaces and their buffers
  int m_fd[4] = {-1, -1, -1, -1};  // dashboard, secondary, real-time, RTDE
  std::string m_buffer[3];         // secondary, real-time, RTDE bytes not yet a whole package
  std::uint8_t m_rtdeRecipe = 1;   // the output recipe's id, as the controller gave it
  std::atomic<std::uint64_t> m_packages{0};
  Clock::time_point m_lastPackageAt{};
  std::string m_lost;
  UrLinkStatus m_status;
  std::vector<UrLinkMessage> m_messages;
  Clock::time_point m_nextStopSend{};
  std::optional<std::uint64_t> m_stopSentAtPackage;
  std::atomic<bool> m_quit{false};
  std::thread m_thread;
};

UrLink::UrLink(UrLinkSettings settings) : m_impl(std::make_unique<Impl>(std::move(settings))) {}
UrLink::~UrLink() = default;
core::Status UrLink::connect() { return m_impl->connect(); }
void UrLink::disconnect() { m_impl->disconnect(); }
core::Result<std::string> UrLink::dashboard(const std::string& command) { return m_impl->dashboard(command); }
core::Status UrLink::powerOn(std::chrono::milliseconds limit) { return m_impl->powerOn(limit); }
core::Status UrLink::sendProgram(const std::string& script) { return m_impl->sendProgram(script); }
void UrLink::stop() { m_impl->latch(StopKind::Stop); }
void UrLink::emergencyStop() { m_impl->latch(StopKind::EmergencyStop); }
core::Status UrLink::clearStop() { return m_impl->clearStop(); }
UrLinkStatus UrLink::status() const { return m_impl->status(); }
std::vector<UrLinkMessage> UrLink::takeMessages() { return m_impl->takeMessages(); }

}  // namespace multidir::hardware

#include "multidir/hardware/device_simulator.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "modbus/register_maps.h"
#include "sim/listen_socket.h"
#include "sim/modbus_tcp_frames.h"
#include "sim/simulated_devices.h"

namespace multidir::hardware {

namespace rr = regs::rotary;
namespace rb = regs::robot;
using sim::Clock;

namespace {

constexpr auto kCycle = std::chrono::milliseconds(2);  // the simulated control loop's period (at most)
constexpr int kBacklog = SOMAXCONN;             // a burst of connections waits for accept() instead of retrying SYNs
constexpr int kAcceptsPerCycle = 256;           // a burst of connections is refused within a few cycles
constexpr std::size_t kMaxUnsentBytes = 65536;  // a client that sends requests but never reads replies
constexpr std::size_t kReceiveChunk = 4096;

core::Error invalid(const std::string& field, const std::string& message) {
  return core::Error{core::ErrorCode::InvalidParameter, message, field};
}

}  // namespace

class DeviceSimulator::Impl {
 public:
  explicit Impl(SimulatorOptions options) : m_options(std::move(options)) {}
  ~Impl() { stop(); }

  core::Status start() {
    if (m_thread.joinable()) return core::Done{};
    if (!m_options.rotary && !m_options.robot)
      return invalid("devices", "the simulator needs at least one device: the rotary platform or the robot arm");
    in_addr parsed{};
    if (inet_pton(AF_INET, m_options.listenAddress.c_str(), &parsed) != 1)
      return invalid("listen address", "'" + m_options.listenAddress + "' is not an IPv4 address such as 127.0.0.1");
    if (m_options.port < 0 || m_options.port > 65535) return invalid("port", "must be between 0 and 65535");
    if (m_options.rotaryUnitId < 0 || m_options.rotaryUnitId > 255)
      return invalid("rotary unit id", "must be between 0 and 255");
    if (m_options.maxClients < 1 || m_options.maxClients > 1000)
      return invalid("maximal clients", "must be between 1 and 1000");
    if (m_options.requestTimeout.count() < 1 || m_options.requestTimeout.count() > 60000)
      return invalid("request timeout", "must be between 1 and 60000 ms");
    if (m_options.controlTimeout.count() < 1 || m_options.controlTimeout.count() > 60000)
      return invalid("control timeout", "must be between 1 and 60000 ms");

    auto listening = sim::listenTcp(m_options.listenAddress, m_options.port, kBacklog);
    if (!listening.ok()) return listening.error();
    m_listen = listening.value();
    sockaddr_in bound{};
    socklen_t length = sizeof(bound);
    if (getsockname(m_listen, reinterpret_cast<sockaddr*>(&bound), &length) == 0) m_port = ntohs(bound.sin_port);

    const Clock::time_point now = Clock::now();
    m_rotaryRegs.assign(rr::kMapSize, 0);
    m_robotRegs.assign(rb::kCount, 0);
    m_rotary.emplace(m_options, m_rotaryRegs.data(), now);
    m_robot.emplace(m_options, m_robotRegs.data(), now);
    m_stop = false;
    m_thread = std::thread([this] { run(); });
    return core::Done{};
  }

  void stop() {
    if (!m_thread.joinable()) return;
    m_stop = true;
    m_thread.join();
    std::lock_guard<std::mutex> lock(m_mutex);
    for (const Client& client : m_clients) ::close(client.fd);
    m_clients.clear();
    m_delayed.clear();
    m_connections = 0;
    if (m_listen >= 0) ::close(m_listen);
    m_listen = -1;
    m_rotary.reset();
    m_robot.reset();
  }

  bool running() const { return m_thread.joinable() && !m_stop; }
  int port() const { return m_port; }
  std::string address() const { return m_options.listenAddress + ":" + std::to_string(m_port); }

  void dropConnections(std::chrono::milliseconds refuseFor) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_dropRequested = true;
    m_refuseUntil = Clock::now() + refuseFor;
  }
  void setReplyDelay(std::chrono::milliseconds delay) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_replyDelay = delay;
  }
  void setExceptionReply(SimulatedDevice device, int code) {
    std::lock_guard<std::mutex> lock(m_mutex);
    (device == SimulatedDevice::Rotary ? m_rotaryException : m_robotException) = std::clamp(code, 0, 255);
  }
  void refuseStops(SimulatedDevice device, int code, int count) {
    std::lock_guard<std::mutex> lock(m_mutex);
    StopRefusal& refusal = device == SimulatedDevice::Rotary ? m_rotaryStopRefusal : m_robotStopRefusal;
    refusal.exception = std::clamp(code, 1, 255);
    refusal.remaining = std::max(count, 0);
  }
  void setMotorStuck(bool stuck) {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_rotary) m_rotary->setStuck(stuck);
  }
  void setHeartbeatAnswering(SimulatedDevice device, bool answering) {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (device == SimulatedDevice::Rotary) {
      if (m_rotary) m_rotary->setEchoing(answering);
    } else {
      if (m_robot) m_robot->setAnswering(answering);
    }
  }

  SimulatedRotaryState rotaryState() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_rotary ? m_rotary->state() : SimulatedRotaryState{};
  }
  SimulatedRobotState robotState() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_robot ? m_robot->state() : SimulatedRobotState{};
  }
  std::uint64_t requestCount(SimulatedDevice device) const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return device == SimulatedDevice::Rotary ? m_rotaryRequests : m_robotRequests;
  }
  std::uint64_t commandWriteCount(SimulatedDevice device) const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return device == SimulatedDevice::Rotary ? m_rotaryCommandWrites : m_robotCommandWrites;
  }
  std::vector<SimulatedCommandRecord> commandLog() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_commandLog;
  }
  int connectionCount() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_connections;
  }
  std::uint64_t refusedConnectionCount() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_refused;
  }
  std::uint64_t droppedClientCount() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_dropped;
  }

 private:
  struct Client {
    int fd = -1;
    std::uint64_t id = 0;
    std::vector<std::uint8_t> received;  // bytes of a request not complete yet
    std::vector<std::uint8_t> unsent;    // reply bytes the socket did not take yet
    Clock::time_point requestStarted{};  // when the first byte of `received` arrived
    bool closing = false;
  };
  struct StopRefusal {
    int exception = 0;
    int remaining = 0;  // stop writes still to refuse
  };
  struct DelayedRequest {
    std::uint64_t clientId;
    std::vector<std::uint8_t> frame;
    Clock::time_point due;
  };

  Client* findClient(std::uint64_t id) {
    for (Client& client : m_clients)
      if (client.id == id) return &client;
    return nullptr;
  }

  void removeClosing() {
    for (const Client& client : m_clients)
      if (client.closing) {
        ::close(client.fd);
        const std::uint64_t id = client.id;
        m_delayed.erase(std::remove_if(m_delayed.begin(), m_delayed.end(),
                                       [id](const DelayedRequest& d) { return d.clientId == id; }),
                        m_delayed.end());
      }
    m_clients.erase(std::remove_if(m_clients.begin(), m_clients.end(), [](const Client& c) { return c.closing; }),
                    m_clients.end());
    m_connections = static_cast<int>(m_clients.size());
  }

  void drop(Client& client) {
    if (client.closing) return;
    client.closing = true;
    ++m_dropped;
  }

  void run() {
    std::vector<pollfd> fds;
    while (!m_stop) {
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_dropRequested) {
          m_dropRequested = false;
          for (Client& client : m_clients) client.closing = true;
          removeClosing();
        }
        const Clock::time_point now = Clock::now();
        if (m_options.rotary) m_rotary->step(now);
        if (m_options.robot) m_robot->step(now);
        fds.clear();
        fds.push_back(pollfd{m_listen, static_cast<short>(now < m_acceptPausedUntil ? 0 : POLLIN), 0});
        for (const Client& client : m_clients)
          fds.push_back(pollfd{client.fd, static_cast<short>(POLLIN | (client.unsent.empty() ? 0 : POLLOUT)), 0});
      }
      const int ready = ::poll(fds.data(), fds.size(), static_cast<int>(kCycle.count()));
      if (ready < 0 && errno != EINTR) break;

      std::lock_guard<std::mutex> lock(m_mutex);
      const Clock::time_point now = Clock::now();
      if (ready > 0) {
        // fds[i + 1] belongs to m_clients[i]: nothing was added or removed since poll() was set up.
        for (std::size_t i = 0; i + 1 < fds.size() && i < m_clients.size(); ++i) {
          Client& client = m_clients[i];
          if ((fds[i + 1].revents & POLLOUT) != 0) flush(client);
          if ((fds[i + 1].revents & (POLLIN | POLLHUP | POLLERR)) != 0) receive(client, now);
        }
        if ((fds[0].revents & POLLIN) != 0) acceptClients(now);
      }
      for (Client& client : m_clients)
        if (!client.received.empty() && now - client.requestStarted > m_options.requestTimeout) drop(client);
      while (!m_delayed.empty() && m_delayed.front().due <= Clock::now()) {
        DelayedRequest next = std::move(m_delayed.front());
        m_delayed.pop_front();
        if (Client* client = findClient(next.clientId); client != nullptr && !client->closing)
          answer(*client, next.frame);
      }
      removeClosing();
    }
  }

  void acceptClients(Clock::time_point now) {
    for (int i = 0; i < kAcceptsPerCycle; ++i) {
      const int fd = ::accept4(m_listen, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd < 0) {
        // Out of descriptors: the pending connection stays readable, so pause accepting instead of spinning.
        if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM)
          m_acceptPausedUntil = now + std::chrono::milliseconds(50);
        return;  // EAGAIN: none left
      }
      if (now < m_refuseUntil || static_cast<int>(m_clients.size()) >= m_options.maxClients) {
        ::close(fd);
        ++m_refused;
        continue;
      }
      Client client;
      client.fd = fd;
      client.id = ++m_nextClientId;
      m_clients.push_back(std::move(client));
    }
  }

  // Reads what the socket holds and answers every complete request in it.
  void receive(Client& client, Clock::time_point now) {
    std::uint8_t chunk[kReceiveChunk];
    for (;;) {
      const ssize_t got = ::recv(client.fd, chunk, sizeof chunk, 0);
      if (got == 0) {
        client.closing = true;  // the client closed: not a drop
        return;
      }
      if (got < 0) {
        if (errno == EINTR) continue;
        if (errno != EAGAIN && errno != EWOULDBLOCK) client.closing = true;
        break;
      }
      if (client.received.empty()) client.requestStarted = now;
      client.received.insert(client.received.end(), chunk, chunk + got);
      if (!frameRequests(client)) return;
      if (static_cast<std::size_t>(got) < sizeof chunk) break;
    }
  }

  // Cuts complete requests off the front of the received bytes; false when the client was dropped.
  bool frameRequests(Client& client) {
    std::size_t used = 0;
    while (client.received.size() - used >= sim::kMbapSize) {
      const sim::MbapHeader header = sim::parseMbap(client.received.data() + used);
      if (sim::checkMbap(header) != sim::FrameProblem::None) {
        drop(client);
        return false;
      }
      const std::size_t size = sim::frameSize(header);
      if (client.received.size() - used < size) break;
      std::vector<std::uint8_t> frame(client.received.begin() + static_cast<std::ptrdiff_t>(used),
                                      client.received.begin() + static_cast<std::ptrdiff_t>(used + size));
      used += size;
      countRequest(frame);
      if (m_replyDelay.count() > 0 || !m_delayed.empty())
        m_delayed.push_back(DelayedRequest{client.id, std::move(frame), Clock::now() + m_replyDelay});
      else
        answer(client, frame);
      if (client.closing) return false;
    }
    client.received.erase(client.received.begin(), client.received.begin() + static_cast<std::ptrdiff_t>(used));
    // The rest of a request counts from now: its timeout is for the request still incomplete.
    if (used > 0 && !client.received.empty()) client.requestStarted = Clock::now();
    return true;
  }

  void flush(Client& client) {
    while (!client.unsent.empty()) {
      const ssize_t sent = ::send(client.fd, client.unsent.data(), client.unsent.size(), MSG_NOSIGNAL);
      if (sent < 0) {
        if (errno == EINTR) continue;
        if (errno != EAGAIN && errno != EWOULDBLOCK) client.closing = true;
        return;
      }
      client.unsent.erase(client.unsent.begin(), client.unsent.begin() + sent);
    }
  }

  std::optional<SimulatedDevice> deviceFor(std::uint8_t unit) const {
    if (m_options.rotary && unit == m_options.rotaryUnitId) return SimulatedDevice::Rotary;
    if (m_options.robot) return SimulatedDevice::Robot;
    return std::nullopt;
  }

  // The COMMAND register's value in a write request to `device`, or -1 when the request writes no COMMAND.
  static int commandWritten(SimulatedDevice device, const std::uint8_t* pdu, std::size_t pduSize) {
    const std::uint8_t function = pdu[0];
    if ((function != 0x06 && function != 0x10) || pduSize < 5) return -1;
    const int address = (pdu[1] << 8) | pdu[2];
    const int count = function == 0x06 ? 1 : ((pdu[3] << 8) | pdu[4]);
    const int commandRegister = device == SimulatedDevice::Rotary ? rr::kCommand : rb::kCommand;
    if (commandRegister < address || commandRegister >= address + count) return -1;
    const std::size_t at = function == 0x06 ? 3 : 6 + 2 * static_cast<std::size_t>(commandRegister - address);
    if (at + 1 >= pduSize) return -1;
    return (pdu[at] << 8) | pdu[at + 1];
  }

  static bool isStop(SimulatedDevice device, int command) {
    if (device == SimulatedDevice::Rotary) return command == rr::kCmdStop || command == rr::kCmdEStop;
    return command == rb::kCmdStop || command == rb::kCmdHalt;
  }

  void countRequest(const std::vector<std::uint8_t>& frame) {
    const sim::MbapHeader header = sim::parseMbap(frame.data());
    const auto device = deviceFor(header.unit);
    if (!device) return;
    (*device == SimulatedDevice::Rotary ? m_rotaryRequests : m_robotRequests)++;
    const std::uint8_t* pdu = frame.data() + sim::kMbapSize;
    const std::size_t pduSize = frame.size() - sim::kMbapSize;
    const std::uint8_t function = pdu[0];
    if ((function != 0x06 && function != 0x10) || pduSize < 5) return;
    const int address = (pdu[1] << 8) | pdu[2];
    const int count = function == 0x06 ? 1 : ((pdu[3] << 8) | pdu[4]);
    // The heartbeat, its timeout, the session and the claim of control are no command.
    const int heartbeatFirst = *device == SimulatedDevice::Rotary ? rr::kHeartbeat : rb::kHostHeartbeat;
    const int heartbeatLast = *device == SimulatedDevice::Rotary ? rr::kClaim : rb::kClaim;
    if (address < heartbeatFirst || address + count - 1 > heartbeatLast) {
      (*device == SimulatedDevice::Rotary ? m_rotaryCommandWrites : m_robotCommandWrites)++;
      SimulatedCommandRecord record;
      record.at = m_options.steadyNow ? m_options.steadyNow() : Clock::now();
      record.device = *device;
      record.command = commandWritten(*device, pdu, pduSize);
      m_commandLog.push_back(record);
    }
  }

  // The exception refusing this request as refuseStops() asked for, or 0.
  int injectedStopRefusal(SimulatedDevice device, const std::uint8_t* pdu, std::size_t pduSize) {
    StopRefusal& refusal = device == SimulatedDevice::Rotary ? m_rotaryStopRefusal : m_robotStopRefusal;
    if (refusal.remaining == 0 || !isStop(device, commandWritten(device, pdu, pduSize))) return 0;
    --refusal.remaining;
    return refusal.exception;
  }

  // Queues the reply to one complete request frame and tries to send it.
  void answer(Client& client, const std::vector<std::uint8_t>& frame) {
    const sim::MbapHeader header = sim::parseMbap(frame.data());
    const std::uint8_t* pdu = frame.data() + sim::kMbapSize;
    const std::size_t pduSize = frame.size() - sim::kMbapSize;
    std::vector<std::uint8_t> reply;
    const auto device = deviceFor(header.unit);
    if (!device) {
      reply = sim::exceptionPdu(pdu[0], 0x0B);  // gateway target device failed to respond
    } else {
      const bool rotary = *device == SimulatedDevice::Rotary;
      int exception = rotary ? m_rotaryException : m_robotException;
      if (exception == 0) exception = injectedStopRefusal(*device, pdu, pduSize);
      if (exception != 0) {
        reply = sim::exceptionPdu(pdu[0], static_cast<std::uint8_t>(exception));
      } else {
        sim::RegisterBlock block;
        if (rotary) {
          block = {m_rotaryRegs.data(), 0, rr::kMapSize, rr::kFirstWritable, rr::kLastWritable, nullptr};
          block.refuseWrite = [this](int address, const std::vector<std::uint16_t>& values) {
            return m_rotary->writeRefusal(address, values, Clock::now());
          };
        } else {
          block = {m_robotRegs.data(), rb::kFirst, rb::kCount, rb::kFirstHostWritable, rb::kLastHostWritable, nullptr};
        }
        sim::PduAnswer answered = sim::answerPdu(pdu, pduSize, block);
        if (answered.wrote && rotary) m_rotary->afterWrite(Clock::now());
        reply = std::move(answered.pdu);
      }
    }
    const std::vector<std::uint8_t> bytes = sim::replyFrame(header, reply);
    client.unsent.insert(client.unsent.end(), bytes.begin(), bytes.end());
    flush(client);
    if (client.unsent.size() > kMaxUnsentBytes) drop(client);
  }

  SimulatorOptions m_options;
  int m_listen = -1;
  int m_port = 0;
  std::thread m_thread;
  std::atomic<bool> m_stop{false};

  mutable std::mutex m_mutex;  // guards everything below against the public methods
  std::vector<std::uint16_t> m_rotaryRegs;  // registers 0..kMapSize-1
  std::vector<std::uint16_t> m_robotRegs;   // registers 128..255
  std::optional<sim::RotaryController> m_rotary;
  std::optional<sim::RobotProgram> m_robot;
  std::vector<Client> m_clients;
  std::deque<DelayedRequest> m_delayed;
  std::uint64_t m_nextClientId = 0;
  int m_connections = 0;
  bool m_dropRequested = false;
  Clock::time_point m_refuseUntil{};
  Clock::time_point m_acceptPausedUntil{};
  std::chrono::milliseconds m_replyDelay{0};
  int m_rotaryException = 0;
  int m_robotException = 0;
  StopRefusal m_rotaryStopRefusal;
  StopRefusal m_robotStopRefusal;
  std::uint64_t m_rotaryRequests = 0;
  std::uint64_t m_robotRequests = 0;
  std::uint64_t m_rotaryCommandWrites = 0;
  std::uint64_t m_robotCommandWrites = 0;
  std::vector<SimulatedCommandRecord> m_commandLog;
  std::uint64_t m_refused = 0;
  std::uint64_t m_dropped = 0;
};

DeviceSimulator::DeviceSimulator(SimulatorOptions options) : m_impl(std::make_unique<Impl>(std::move(options))) {}
DeviceSimulator::~DeviceSimulator() = default;
core::Status DeviceSimulator::start() { return m_impl->start(); }
void DeviceSimulator::stop() { m_impl->stop(); }
bool DeviceSimulator::running() const { return m_impl->running(); }
int DeviceSimulator::port() const { return m_impl->port(); }
std::string DeviceSimulator::address() const { return m_impl->address(); }
void DeviceSimulator::dropConnections(std::chrono::milliseconds refuseFor) { m_impl->dropConnections(refuseFor); }
void DeviceSimulator::setReplyDelay(std::chrono::milliseconds delay) { m_impl->setReplyDelay(delay); }
void DeviceSimulator::setExceptionReply(SimulatedDevice device, int code) { m_impl->setExceptionReply(device, code); }
void DeviceSimulator::refuseStops(SimulatedDevice device, int code, int count) {
  m_impl->refuseStops(device, code, count);
}
void DeviceSimulator::setMotorStuck(bool stuck) { m_impl->setMotorStuck(stuck); }
void DeviceSimulator::setHeartbeatAnswering(SimulatedDevice device, bool answering) {
  m_impl->setHeartbeatAnswering(device, answering);
}
SimulatedRotaryState DeviceSimulator::rotaryState() const { return m_impl->rotaryState(); }
SimulatedRobotState DeviceSimulator::robotState() const { return m_impl->robotState(); }
std::uint64_t DeviceSimulator::requestCount(SimulatedDevice device) const { return m_impl->requestCount(device); }
std::uint64_t DeviceSimulator::commandWriteCount(SimulatedDevice device) const {
  return m_impl->commandWriteCount(device);
}
std::vector<SimulatedCommandRecord> DeviceSimulator::commandLog() const { return m_impl->commandLog(); }
int DeviceSimulator::connectionCount() const { return m_impl->connectionCount(); }
std::uint64_t DeviceSimulator::refusedConnectionCount() const { return m_impl->refusedConnectionCount(); }
std::uint64_t DeviceSimulator::droppedClientCount() const { return m_impl->droppedClientCount(); }

}  // namespace multidir::hardware

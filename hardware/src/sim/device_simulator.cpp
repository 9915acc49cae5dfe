#include "multidir/hardware/device_simulator.h"

#include <arpa/inet.h>
#include <modbus.h>
#include <netinet/in.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "modbus/register_maps.h"
#include "sim/simulated_devices.h"

namespace multidir::hardware {

namespace rr = regs::rotary;
namespace rb = regs::robot;
using sim::Clock;

namespace {

constexpr auto kCycle = std::chrono::milliseconds(2);  // the simulated control loop's period (at most)

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

    m_context = modbus_new_tcp(m_options.listenAddress.c_str(), m_options.port);
    m_rotaryMap = modbus_mapping_new_start_address(0, 0, 0, 0, 0, rr::kMapSize, 0, 0);
    m_robotMap = modbus_mapping_new_start_address(0, 0, 0, 0, rb::kFirst, rb::kCount, 0, 0);
    if (m_context == nullptr || m_rotaryMap == nullptr || m_robotMap == nullptr) {
      release();
      return core::Error{core::ErrorCode::Internal, "the simulator could not allocate its Modbus context", "simulator"};
    }
    m_listen = modbus_tcp_listen(m_context, 16);
    if (m_listen < 0) {
      const int errnum = errno;
      release();
      return core::Error{core::ErrorCode::Internal,
                         "the simulator cannot listen on " + m_options.listenAddress + ":" +
                             std::to_string(m_options.port) + ": " + std::strerror(errnum) +
                             ": choose another port (0 picks a free one) or stop the program using it",
                         "listen address"};
    }
    sockaddr_in bound{};
    socklen_t length = sizeof(bound);
    if (getsockname(m_listen, reinterpret_cast<sockaddr*>(&bound), &length) == 0) m_port = ntohs(bound.sin_port);

    const Clock::time_point now = Clock::now();
    m_rotary.emplace(m_options, m_rotaryMap->tab_registers, now);
    m_robot.emplace(m_options, m_robotMap->tab_registers, now);
    m_stop = false;
    m_thread = std::thread([this] { run(); });
    return core::Done{};
  }

  void stop() {
    if (!m_thread.joinable()) return;
    m_stop = true;
    m_thread.join();
    for (const Client& client : m_clients) ::close(client.fd);
    m_clients.clear();
    m_delayed.clear();
    if (m_listen >= 0) ::close(m_listen);
    m_listen = -1;
    release();
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
  void setMotorStuck(bool stuck) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stuck = stuck;
    if (m_rotary) m_rotary->setStuck(stuck);
  }
  void setHeartbeatAnswering(SimulatedDevice device, bool answering) {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (device == SimulatedDevice::Rotary) {
      m_rotaryEchoing = answering;
      if (m_rotary) m_rotary->setEchoing(answering);
    } else {
      m_robotAnswering = answering;
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
  int connectionCount() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_connections;
  }

 private:
  struct Client {
    int fd;
    std::uint64_t id;
  };
  struct DelayedRequest {
    std::uint64_t clientId;
    std::vector<std::uint8_t> request;
    Clock::time_point due;
  };

  void release() {
    if (m_context != nullptr) modbus_free(m_context);
    if (m_rotaryMap != nullptr) modbus_mapping_free(m_rotaryMap);
    if (m_robotMap != nullptr) modbus_mapping_free(m_robotMap);
    m_context = nullptr;
    m_rotaryMap = nullptr;
    m_robotMap = nullptr;
    m_rotary.reset();
    m_robot.reset();
  }

  void closeClient(std::size_t index) {
    ::close(m_clients[index].fd);
    const std::uint64_t id = m_clients[index].id;
    m_clients.erase(m_clients.begin() + static_cast<std::ptrdiff_t>(index));
    m_delayed.erase(std::remove_if(m_delayed.begin(), m_delayed.end(),
                                   [id](const DelayedRequest& d) { return d.clientId == id; }),
                    m_delayed.end());
  }

  void run() {
    std::vector<std::uint8_t> query(MODBUS_TCP_MAX_ADU_LENGTH);
    while (!m_stop) {
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_dropRequested) {
          m_dropRequested = false;
          while (!m_clients.empty()) closeClient(m_clients.size() - 1);
        }
        const Clock::time_point now = Clock::now();
        if (m_options.rotary) m_rotary->step(now);
        if (m_options.robot) m_robot->step(now);
        m_connections = static_cast<int>(m_clients.size());
      }

      fd_set readable;
      FD_ZERO(&readable);
      FD_SET(m_listen, &readable);
      int highest = m_listen;
      for (const Client& client : m_clients) {
        FD_SET(client.fd, &readable);
        highest = std::max(highest, client.fd);
      }
      timeval timeout{0, static_cast<suseconds_t>(std::chrono::microseconds(kCycle).count())};
      const int ready = select(highest + 1, &readable, nullptr, nullptr, &timeout);
      if (ready < 0 && errno != EINTR) break;

      std::lock_guard<std::mutex> lock(m_mutex);
      if (ready > 0 && FD_ISSET(m_listen, &readable)) {
        int listenSocket = m_listen;
        const int fd = modbus_tcp_accept(m_context, &listenSocket);
        if (fd >= 0) {
          if (Clock::now() < m_refuseUntil)
            ::close(fd);
          else
            m_clients.push_back(Client{fd, ++m_nextClientId});
        }
      }
      if (ready > 0) {
        // Iterate over a copy of the ids: serving may close clients.
        std::vector<Client> snapshot = m_clients;
        for (const Client& client : snapshot) {
          if (!FD_ISSET(client.fd, &readable)) continue;
          modbus_set_socket(m_context, client.fd);
          const int length = modbus_receive(m_context, query.data());
          if (length < 0) {
            closeById(client.id);
            continue;
          }
          if (length == 0) continue;
          const std::vector<std::uint8_t> request(query.begin(), query.begin() + length);
          countRequest(request);
          if (m_replyDelay.count() > 0 || !m_delayed.empty()) {
            m_delayed.push_back(DelayedRequest{client.id, request, Clock::now() + m_replyDelay});
          } else if (!serve(client, request)) {
            closeById(client.id);
          }
        }
      }
      while (!m_delayed.empty() && m_delayed.front().due <= Clock::now()) {
        DelayedRequest next = std::move(m_delayed.front());
        m_delayed.pop_front();
        auto it = std::find_if(m_clients.begin(), m_clients.end(),
                               [&](const Client& c) { return c.id == next.clientId; });
        if (it == m_clients.end()) continue;
        const Client client = *it;
        if (!serve(client, next.request)) closeById(client.id);
      }
    }
  }

  void closeById(std::uint64_t id) {
    for (std::size_t i = 0; i < m_clients.size(); ++i)
      if (m_clients[i].id == id) return closeClient(i);
  }

  std::optional<SimulatedDevice> deviceFor(std::uint8_t unit) const {
    if (m_options.rotary && unit == m_options.rotaryUnitId) return SimulatedDevice::Rotary;
    if (m_options.robot) return SimulatedDevice::Robot;
    return std::nullopt;
  }

  void countRequest(const std::vector<std::uint8_t>& request) {
    const int header = modbus_get_header_length(m_context);
    const auto device = deviceFor(request[header - 1]);
    if (!device) return;
    (*device == SimulatedDevice::Rotary ? m_rotaryRequests : m_robotRequests)++;
    const std::uint8_t function = request[header];
    if (function != 0x06 && function != 0x10) return;
    const int address = (request[header + 1] << 8) | request[header + 2];
    const int count = function == 0x06 ? 1 : ((request[header + 3] << 8) | request[header + 4]);
    const int heartbeatFirst = *device == SimulatedDevice::Rotary ? rr::kHeartbeat : rb::kHostHeartbeat;
    const int heartbeatLast = *device == SimulatedDevice::Rotary ? rr::kHeartbeatTimeout : rb::kHeartbeatTimeout;
    if (address < heartbeatFirst || address + count - 1 > heartbeatLast)
      (*device == SimulatedDevice::Rotary ? m_rotaryCommandWrites : m_robotCommandWrites)++;
  }

  // Answers one request; false when the client's socket failed.
  bool serve(const Client& client, const std::vector<std::uint8_t>& request) {
    modbus_set_socket(m_context, client.fd);
    const int header = modbus_get_header_length(m_context);
    const int length = static_cast<int>(request.size());
    const auto device = deviceFor(request[header - 1]);
    if (!device) return modbus_reply_exception(m_context, request.data(), MODBUS_EXCEPTION_GATEWAY_TARGET) >= 0;
    const bool rotary = *device == SimulatedDevice::Rotary;
    const int exception = rotary ? m_rotaryException : m_robotException;
    if (exception != 0)
      return modbus_reply_exception(m_context, request.data(), static_cast<unsigned int>(exception)) >= 0;

    const std::uint8_t function = request[header];
    if (function != 0x03 && function != 0x06 && function != 0x10)
      return modbus_reply_exception(m_context, request.data(), MODBUS_EXCEPTION_ILLEGAL_FUNCTION) >= 0;
    const bool write = function != 0x03;
    if (write) {
      // Status registers belong to the device: a write there is refused as a real controller would.
      const int address = (request[header + 1] << 8) | request[header + 2];
      const int count = function == 0x06 ? 1 : ((request[header + 3] << 8) | request[header + 4]);
      const int first = rotary ? rr::kFirstWritable : rb::kFirstHostWritable;
      const int last = rotary ? rr::kLastWritable : rb::kLastHostWritable;
      if (address < first || address + count - 1 > last)
        return modbus_reply_exception(m_context, request.data(), MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS) >= 0;
    }
    const int rc = modbus_reply(m_context, request.data(), length, rotary ? m_rotaryMap : m_robotMap);
    if (write && rotary) m_rotary->afterWrite(Clock::now());
    return rc >= 0;
  }

  SimulatorOptions m_options;
  modbus_t* m_context = nullptr;
  modbus_mapping_t* m_rotaryMap = nullptr;
  modbus_mapping_t* m_robotMap = nullptr;
  int m_listen = -1;
  int m_port = 0;
  std::thread m_thread;
  std::atomic<bool> m_stop{false};

  mutable std::mutex m_mutex;  // guards everything below against the public methods
  std::optional<sim::RotaryController> m_rotary;
  std::optional<sim::RobotProgram> m_robot;
  std::vector<Client> m_clients;
  std::deque<DelayedRequest> m_delayed;
  std::uint64_t m_nextClientId = 0;
  int m_connections = 0;
  bool m_dropRequested = false;
  Clock::time_point m_refuseUntil{};
  std::chrono::milliseconds m_replyDelay{0};
  int m_rotaryException = 0;
  int m_robotException = 0;
  bool m_stuck = false;
  bool m_rotaryEchoing = true;
  bool m_robotAnswering = true;
  std::uint64_t m_rotaryRequests = 0;
  std::uint64_t m_robotRequests = 0;
  std::uint64_t m_rotaryCommandWrites = 0;
  std::uint64_t m_robotCommandWrites = 0;
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
int DeviceSimulator::connectionCount() const { return m_impl->connectionCount(); }

}  // namespace multidir::hardware

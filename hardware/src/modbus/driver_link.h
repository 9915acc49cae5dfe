#pragma once
// What every Modbus driver (rotary platform, robot arm) builds around its LinkWorker: the device's label, its
// status behind one mutex, the status callback, the heartbeat, the link-state bookkeeping and the refusals of
// commands that send nothing. A driver supplies only what is its own: the register map, how it reads its
// status (poll), what it writes after each (re)connect and which status flag says the device itself is alive.
//
// The stop latch (stop_latch.h) lives in the worker; status() reports it in StatusT::stop, so every driver's
// status has a `StopLatch stop` field.
//
// Threads: status(), update(), setStatusCallback(), refuse...(), requireLink(), latchStop(), clearStop() and
// refuseWhileStopLatched() may be called from any thread; the hooks, publish() after a poll and the port
// helpers run on the worker thread.
#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <mutex>
#include <string>
#include <utility>

#include "modbus/link_worker.h"
#include "modbus/modbus_port.h"
#include "multidir/core/common/result.h"
#include "multidir/core/search/machine.h"
#include "multidir/hardware/connection.h"

namespace multidir::hardware {

// A future that is ready at once: how a refused command answers (nothing was sent).
std::future<core::Status> readyFuture(core::Status status);

// connect()'s checks common to every driver, in this order: the connection settings, the machine profile.
core::Status validateLinkAndProfile(const ConnectionSettings& connection, const core::MachineSpec& machine);
// The device's watchdog timeout, written to a 16-bit millisecond register.
core::Status validateHeartbeatTimeout(std::chrono::milliseconds timeout);

template <typename StatusT>
class DriverLink {
 public:
  using StatusCallback = std::function<void(const StatusT&)>;

  // onConnected runs after each (re)connect, poll reads the status; both on the worker thread. heartbeatRegister
  // holds MultiDir's heartbeat, the next register its timeout. aliveFlag: the status field that says the
  // device's own program or control loop answers; it is cleared whenever the link is not up.
  DriverLink(const ConnectionSettings& connection, std::string label, int heartbeatRegister, bool StatusT::*aliveFlag,
             LinkWorker::Command onConnected, LinkWorker::Command poll)
      : m_label(std::move(label)),
        m_heartbeatRegister(heartbeatRegister),
        m_aliveFlag(aliveFlag),
        m_worker(connection, m_label, linkHooks(std::move(onConnected), std::move(poll))) {}
  ~DriverLink() { m_worker.stop(); }
  DriverLink(const DriverLink&) = delete;
  DriverLink& operator=(const DriverLink&) = delete;

  core::Status start() { return m_worker.start(); }
  void stop() { m_worker.stop(); }
  std::future<core::Status> submit(LinkWorker::Command command, bool urgent, const std::string& what) {
    return m_worker.submit(std::move(command), urgent, what);
  }

  [[nodiscard]] const std::string& name() const { return m_label; }

  [[nodiscard]] StatusT status() const {
    StatusT snapshot;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      snapshot = m_status;
    }
    snapshot.stop = m_worker.stopLatch();
    return snapshot;
  }

  // The status callback hears of a latch change from the worker thread (after the write, or at once while
  // the link is down); a cleared latch shows in the next poll.
  std::future<core::Status> latchStop(StopKind kind, LinkWorker::Command command, const std::string& what) {
    return m_worker.latchStop(kind, std::move(command), what);
  }
  core::Status clearStop() { return m_worker.clearStop(); }

  // A move (`what`: "move", "home") refused because a stop is latched; Done when none is. Checked on the
  // caller's thread and again on the worker's just before the move is written.
  [[nodiscard]] core::Status refuseWhileStopLatched(const std::string& what) const {
    const StopLatch stop = m_worker.stopLatch();
    if (!stop.latched()) return core::Done{};
    std::string message =
        "cannot " + what + ": the " + std::string(stopKindName(stop.kind)) + " the operator asked for is latched";
    message +=
        stop.confirmed ? "; clear the stop first" : " and not yet confirmed by the device (" + stop.problem + ")";
    return refuse(message);
  }

  // Runs change(status) under the status mutex; the driver keeps the fields it updates together with the
  // status behind the same mutex by touching them only in such changes.
  template <typename Change>
  void update(Change&& change) {
    std::lock_guard<std::mutex> lock(m_mutex);
    change(m_status);
  }

  void setStatusCallback(StatusCallback callback) {
    std::lock_guard<std::mutex> lock(m_callbackMutex);
    m_callback = std::move(callback);
  }

  void publish() {
    const StatusT snapshot = status();
    std::lock_guard<std::mutex> lock(m_callbackMutex);
    if (m_callback) m_callback(snapshot);
  }

  void noteError(const std::string& message) {
    update([&message](StatusT& s) { s.lastError = message; });
  }

  [[nodiscard]] core::Error refuse(const std::string& message) const {
    return core::Error{core::ErrorCode::InvalidParameter, m_label + ": " + message, m_label};
  }

  // A target the machine profile refuses (checkRotaryTarget, checkTiltTarget), told as this device's refusal.
  [[nodiscard]] core::Error refuseMove(core::Error error) const {
    error.message = m_label + " refused the move: " + error.message;
    return error;
  }

  [[nodiscard]] core::Status requireLink() const {
    const LinkState link = status().link;
    if (link == LinkState::Connected) return core::Done{};
    return refuse(std::string("not connected (") + linkStateName(link) +
                  "): nothing was sent; connect first or wait for the link to come back");
  }

  // Worker thread: a new heartbeat and the watchdog timeout in one request, as after each (re)connect.
  core::Status writeHeartbeatAndTimeout(ModbusPort& port, std::chrono::milliseconds timeout) {
    ++m_heartbeat;
    return port.writeRegisters(m_heartbeatRegister, {m_heartbeat, static_cast<std::uint16_t>(timeout.count())},
                               "the heartbeat and its timeout (registers " + std::to_string(m_heartbeatRegister) + "-" +
                                   std::to_string(m_heartbeatRegister + 1) + ")");
  }

  // Worker thread: reads the status block; a failure is noted in lastError and published before it returns.
  core::Status readStatusBlock(ModbusPort& port, int first, int count, std::uint16_t* dest, const std::string& what) {
    auto result = port.readRegisters(first, count, dest, what);
    if (!result.ok()) {
      noteError(result.error().message);
      publish();
    }
    return result;
  }

 private:
  LinkHooks linkHooks(LinkWorker::Command onConnected, LinkWorker::Command poll) {
    LinkHooks hooks;
    hooks.onConnected = std::move(onConnected);
    hooks.poll = std::move(poll);
    hooks.heartbeat = [this](ModbusPort& port) {
      ++m_heartbeat;
      auto result = port.writeRegisters(m_heartbeatRegister, {m_heartbeat},
                                        "the heartbeat (register " + std::to_string(m_heartbeatRegister) + ")");
      if (!result.ok()) noteError(result.error().message);
      return result;
    };
    hooks.stopLatchChanged = [this] { publish(); };
    hooks.linkChanged = [this](LinkState state, const std::string& problem) {
      update([&](StatusT& s) {
        s.link = state;
        if (!problem.empty()) s.lastError = problem;
        if (state != LinkState::Connected) s.*m_aliveFlag = false;
      });
      publish();
    };
    return hooks;
  }

  std::string m_label;
  int m_heartbeatRegister;
  bool StatusT::*m_aliveFlag;

  mutable std::mutex m_mutex;
  StatusT m_status;

  std::mutex m_callbackMutex;
  StatusCallback m_callback;

  std::uint16_t m_heartbeat = 0;  // worker thread only
  LinkWorker m_worker;            // last: its thread uses everything above
};

}  // namespace multidir::hardware

#pragma once
// What every Modbus driver (rotary platform, robot arm) builds around its LinkWorker: the device's label, its
// status behind one mutex, the status callback, the heartbeat, the link-state bookkeeping and the refusals of
// commands that send nothing. A driver supplies only what is its own: the register map, how it reads its
// status (poll), what it writes after each (re)connect and which status flag says the device itself is alive.
//
// The stop latch (stop_latch.h) lives in the worker; status() reports it in StatusT::stop, so every driver's
// status has a `StopLatch stop` field.
//
// The control lock (control_lock.h) is this class's too: after each (re)connect it claims the device before
// the driver's onConnected runs (a refusal fails the connect: "... is controlled by another run"), the
// heartbeat carries the session, sessionWords() gives what every command but a stop writes after its COMMAND
// (rotary) or SEQUENCE (robot), checkControl() follows OWNER in every poll, and the driver's release command
// is written when the link is stopped. status() reports it in StatusT::control.
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
#include <thread>
#include <utility>
#include <vector>

#include "modbus/link_worker.h"
#include "modbus/modbus_port.h"
#include "multidir/core/common/result.h"
#include "multidir/core/search/machine.h"
#include "multidir/hardware/connection.h"
#include "multidir/hardware/control_lock.h"

namespace multidir::hardware {

// A future that is ready at once: how a refused command answers (nothing was sent).
std::future<core::Status> readyFuture(core::Status status);

// connect()'s checks common to every driver, in this order: the connection settings, the machine profile.
core::Status validateLinkAndProfile(const ConnectionSettings& connection, const core::MachineSpec& machine);
// The device's watchdog timeout, written to a 16-bit millisecond register.
core::Status validateHeartbeatTimeout(std::chrono::milliseconds timeout);

// The registers of the control lock in a device's map: HEARTBEAT (HEARTBEAT_TIMEOUT, SESSION and CLAIM follow
// it) and OWNER, which the device writes.
struct ControlRegisters {
  int heartbeat = 0;
  int owner = 0;
};

// The refusal of a device another session controls: "... is controlled by another run (session 1a2b) ...".
core::Error controlledByAnotherRun(const std::string& label, std::uint16_t owner);

template <typename StatusT>
class DriverLink {
 public:
  using StatusCallback = std::function<void(const StatusT&)>;

  // onConnected runs after each (re)connect, once the device is claimed; poll reads the status; release
  // gives the device back when the link is stopped (it writes the driver's release command with
  // sessionWords()); all on the worker thread. heartbeatTimeout is written to HEARTBEAT_TIMEOUT with every
  // heartbeat. aliveFlag: the status field that says the device's own program or control loop answers; it is
  // cleared whenever the link is not up.
  DriverLink(const ConnectionSettings& connection, std::string label, ControlRegisters registers,
             std::chrono::milliseconds heartbeatTimeout, bool StatusT::*aliveFlag, LinkWorker::Command onConnected,
             LinkWorker::Command poll, LinkWorker::Command release)
      : m_label(std::move(label)),
        m_registers(registers),
        m_heartbeatTimeout(static_cast<std::uint16_t>(heartbeatTimeout.count())),
        m_responseTimeout(connection.responseTimeout),
        m_aliveFlag(aliveFlag),
        m_release(std::move(release)),
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
    snapshot.control.session = m_session;
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

  // Worker thread: what every command but a stop writes right after its COMMAND (rotary) or SEQUENCE
  // (robot), in the same request: a new heartbeat, the watchdog timeout and the session, so that the device
  // knows the command comes from the session in control.
  std::vector<std::uint16_t> sessionWords() {
    ++m_heartbeat;
    return {m_heartbeat, m_heartbeatTimeout, m_session};
  }

  // Worker thread: OWNER as the poll read it. Done while this driver holds the device; claims it again when
  // nobody does (the device restarted, or freed itself after a silence); when another session took it, an
  // error that has the link rebuilt (and claimed again) and nothing more written meanwhile.
  core::Status checkControl(ModbusPort& port, std::uint16_t owner) {
    update([owner](StatusT& s) { s.control.owner = owner; });
    if (owner == m_session) return core::Done{};
    m_inControl = false;
    if (owner == 0) {
      core::Status claimed = claimControl(port);
      if (claimed.ok() || port.lastFailureBreaksLink()) return claimed;
      noteError(claimed.error().message);
      return port.abandon(claimed.error());
    }
    core::Error lost = controlledByAnotherRun(m_label, owner);
    lost.message = "MultiDir lost control: " + lost.message;
    noteError(lost.message);
    return port.abandon(lost);
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
  // How long the device may take to take a claim (its control loop or program reads CLAIM every cycle).
  static constexpr std::chrono::milliseconds kClaimWait{1000};
  static constexpr int kClaimAttempts = 3;

  [[nodiscard]] std::string registerText(int address) const { return "register " + std::to_string(address); }

  // Worker thread: writes the session to CLAIM and reads CLAIM..OWNER until the device took the claim
  // (CLAIM reads 0); Done when OWNER is then this session.
  core::Status claimControl(ModbusPort& port) {
    const int claim = m_registers.heartbeat + 3;
    const int count = m_registers.owner - claim + 1;
    std::vector<std::uint16_t> block(static_cast<std::size_t>(count));
    for (int attempt = 0; attempt < kClaimAttempts; ++attempt) {
      auto written = port.writeRegisters(claim, {m_session}, "the claim of control (" + registerText(claim) + ")");
      if (!written.ok()) {
        constexpr int kIllegalDataAddress = 2;  // what a device without the register answers
        if (port.lastExceptionCode() != kIllegalDataAddress) return written;
        core::Error refused = written.error();
        refused.message += ". The device does not know MultiDir's control lock (docs/hardware.md, \"One controller "
                           "at a time\"): update its firmware or program to this version";
        return refused;
      }
      const std::chrono::milliseconds wait = std::max(kClaimWait, 2 * m_responseTimeout);
      const auto deadline = std::chrono::steady_clock::now() + wait;
      for (;;) {
        auto read = port.readRegisters(claim, count, block.data(),
                                       "the claim and its owner (registers " + std::to_string(claim) + "-" +
                                           std::to_string(m_registers.owner) + ")");
        if (!read.ok()) return read;
        if (block.front() != m_session) break;  // taken (cleared), or another claim came after ours
        if (std::chrono::steady_clock::now() >= deadline)
          return core::Error{core::ErrorCode::DeviceFault,
                             m_label + " did not take MultiDir's claim of control (" + registerText(claim) +
                                 " still holds it after " + std::to_string(wait.count()) +
                                 " ms): its control loop or program does not run, or does not know the control lock "
                                 "of docs/hardware.md; start or update it",
                             m_label};
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
      const std::uint16_t owner = block.back();
      update([owner](StatusT& s) { s.control.owner = owner; });
      if (owner == m_session) {
        m_inControl = true;
        return core::Done{};
      }
      if (owner != 0) return controlledByAnotherRun(m_label, owner);
    }
    return core::Error{core::ErrorCode::DeviceFault,
                       m_label + " cleared MultiDir's claim of control " + std::to_string(kClaimAttempts) +
                           " times without giving it control (OWNER, " + registerText(m_registers.owner) +
                           ", stays 0): its firmware or program does not follow docs/hardware.md; update it",
                       m_label};
  }

  LinkHooks linkHooks(LinkWorker::Command onConnected, LinkWorker::Command poll) {
    LinkHooks hooks;
    // Claimed before anything else is written (a latched stop excepted: stops are taken from anyone), so
    // that a second run never configures, let alone moves, a device another run controls.
    hooks.onConnected = [this, onConnected = std::move(onConnected)](ModbusPort& port) {
      m_inControl = false;
      if (auto claimed = claimControl(port); !claimed.ok()) return claimed;
      const std::vector<std::uint16_t> words = sessionWords();
      auto result = port.writeRegisters(m_registers.heartbeat, words,
                                        "the heartbeat, its timeout and the session (registers " +
                                            std::to_string(m_registers.heartbeat) + "-" +
                                            std::to_string(m_registers.heartbeat + 2) + ")");
      if (!result.ok()) return result;
      return onConnected(port);
    };
    hooks.poll = std::move(poll);
    hooks.heartbeat = [this](ModbusPort& port) {
      auto result = port.writeRegisters(m_registers.heartbeat, sessionWords(),
                                        "the heartbeat (registers " + std::to_string(m_registers.heartbeat) + "-" +
                                            std::to_string(m_registers.heartbeat + 2) + ")");
      if (!result.ok()) noteError(result.error().message);
      return result;
    };
    // Best effort: when it cannot be written, the device frees itself after its lock timeout.
    hooks.beforeClose = [this](ModbusPort& port) {
      if (m_inControl && m_release) (void)m_release(port);
      m_inControl = false;
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
  ControlRegisters m_registers;
  std::uint16_t m_heartbeatTimeout;
  std::chrono::milliseconds m_responseTimeout;
  bool StatusT::*m_aliveFlag;
  LinkWorker::Command m_release;
  const std::uint16_t m_session = newControlSession();

  mutable std::mutex m_mutex;
  StatusT m_status;

  std::mutex m_callbackMutex;
  StatusCallback m_callback;

  std::uint16_t m_heartbeat = 0;  // worker thread only
  bool m_inControl = false;       // worker thread only: the device gave this session control since the connect
  LinkWorker m_worker;            // last: its thread uses everything above
};

}  // namespace multidir::hardware

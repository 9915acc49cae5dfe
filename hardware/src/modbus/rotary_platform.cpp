#include "multidir/hardware/rotary_platform.h"

#include <cmath>
#include <utility>
#include <vector>

#include "degrees_text.h"
#include "modbus/driver_link.h"
#include "modbus/register_maps.h"
#include "multidir/hardware/motion_limits.h"

namespace multidir::hardware {

namespace rr = regs::rotary;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kProgressDegrees = 0.05;  // less than this in stallTimeout is no progress

RotaryFault faultFromCode(int code) {
  switch (code) {
    case rr::kFaultNone: return RotaryFault::None;
    case rr::kFaultStall: return RotaryFault::Stall;
    case rr::kFaultHeartbeat: return RotaryFault::HeartbeatLost;
    case rr::kFaultLimitSwitch: return RotaryFault::LimitSwitch;
    case rr::kFaultRejected: return RotaryFault::RejectedCommand;
    case rr::kFaultEStop: return RotaryFault::EmergencyStop;
    default: return RotaryFault::Unknown;
  }
}

}  // namespace

const char* rotaryFaultName(RotaryFault fault) {
  switch (fault) {
    case RotaryFault::None: return "none";
    case RotaryFault::Stall: return "stall";
    case RotaryFault::HeartbeatLost: return "heartbeat lost";
    case RotaryFault::LimitSwitch: return "limit switch";
    case RotaryFault::RejectedCommand: return "rejected command";
    case RotaryFault::EmergencyStop: return "emergency stop";
    case RotaryFault::Unknown: return "unknown";
  }
  return "?";
}

class RotaryPlatform::Impl {
 public:
  explicit Impl(RotaryPlatformOptions options)
      : m_options(std::move(options)),
        m_link(m_options.connection, "rotary platform at " + describe(m_options.connection),
               ControlRegisters{rr::kHeartbeat, rr::kOwner}, m_options.controllerHeartbeatTimeout,
               &RotaryStatus::controllerAlive, [this](ModbusPort& port) { return onConnected(port); },
               [this](ModbusPort& port) { return poll(port); },
               [this](ModbusPort& port) { return writeCommand(port, rr::kCmdRelease, "release control"); }) {}

  core::Status connect() {
    if (auto valid = validateLinkAndProfile(m_options.connection, m_options.machine); !valid.ok()) return valid;
    if (m_options.machine.kind != core::MachineKind::RotaryPlatform)
      return m_link.refuse("the machine profile is not a rotary platform (4dof): load the platform's profile");
    if (!(m_options.speedDegreesPerSecond > 0 && m_options.speedDegreesPerSecond <= 655))
      return core::Error{core::ErrorCode::InvalidParameter, "speed must be above 0 and at most 655 degrees/s", "speed"};
    if (auto valid = validateHeartbeatTimeout(m_options.controllerHeartbeatTimeout); !valid.ok()) return valid;
    return m_link.start();
  }

  void disconnect() { m_link.stop(); }

  std::future<core::Status> enable() {
    if (auto ok = m_link.requireLink(); !ok.ok()) return readyFuture(ok);
    return command(rr::kCmdEnable, "enable", false);
  }
  std::future<core::Status> disable() {
    if (auto ok = m_link.requireLink(); !ok.ok()) return readyFuture(ok);
    return command(rr::kCmdDisable, "disable", false);
  }
  std::future<core::Status> clearFault() {
    if (auto ok = m_link.requireLink(); !ok.ok()) return readyFuture(ok);
    m_link.update([this](RotaryStatus&) { m_hostStall = false; });
    return command(rr::kCmdClearFault, "clear fault", false);
  }

  std::future<core::Status> home() {
    const RotaryStatus now = status();
    if (auto ok = m_link.requireLink(); !ok.ok()) return readyFuture(ok);
    if (now.fault != RotaryFault::None)
      return readyFuture(m_link.refuse(std::string("cannot home while in fault (") + rotaryFaultName(now.fault) +
                                       "): clear the fault first"));
    if (!now.enabled) return readyFuture(m_link.refuse("cannot home: the drive is not enabled; enable it first"));
    if (auto ok = m_link.refuseWhileStopLatched("home"); !ok.ok()) return readyFuture(ok);
    return m_link.submit(
        [this](ModbusPort& port) {
          if (auto ok = m_link.refuseWhileStopLatched("home"); !ok.ok()) return ok;
          auto result = writeCommand(port, rr::kCmdHome, "home");
          if (result.ok()) expectMotion(0.0);
          return result;
        },
        false, "home");
  }

  std::future<core::Status> moveTo(double angleDegrees) {
    if (auto ok = checkRotaryTarget(m_options.machine, angleDegrees); !ok.ok())
      return readyFuture(m_link.refuseMove(ok.error()));
    if (auto ok = m_link.requireLink(); !ok.ok()) return readyFuture(ok);
    const RotaryStatus now = status();
    if (now.fault != RotaryFault::None)
      return readyFuture(m_link.refuse(std::string("cannot move while in fault (") + rotaryFaultName(now.fault) +
                                       "): clear the fault, enable and home again"));
    if (!now.homed || now.homing)
      return readyFuture(
          m_link.refuse("cannot move: the platform is not homed; home it first so angles mean something"));
    if (!now.enabled) return readyFuture(m_link.refuse("cannot move: the drive is not enabled; enable it first"));
    if (auto ok = m_link.refuseWhileStopLatched("move"); !ok.ok()) return readyFuture(ok);
    if (!now.controllerAlive)
      return readyFuture(m_link.refuse("cannot move: the controller does not echo the heartbeat, so it could not "
                                       "stop on its own if MultiDir went silent; power-cycle it"));
    std::vector<std::uint16_t> values(4);
    regs::putInt32(regs::degreesToCounts(angleDegrees), values.data());
    values[2] = regs::degreesPerSecondToRegister(m_options.speedDegreesPerSecond);
    values[3] = rr::kCmdMove;
    return m_link.submit(
        [this, values, angleDegrees](ModbusPort& port) mutable {
          if (auto ok = m_link.refuseWhileStopLatched("move"); !ok.ok()) return ok;
          const std::vector<std::uint16_t> session = m_link.sessionWords();
          values.insert(values.end(), session.begin(), session.end());
          auto result = port.writeRegisters(rr::kTargetAngle, values, "the move to " + degreesText(angleDegrees) +
                                                                          " degrees (registers 0-6)");
          if (result.ok()) expectMotion(angleDegrees);
          return result;
        },
        false, "move to " + degreesText(angleDegrees) + " degrees");
  }

  std::future<core::Status> stop() { return latch(StopKind::Stop, rr::kCmdStop, "stop"); }
  std::future<core::Status> emergencyStop() { return latch(StopKind::EmergencyStop, rr::kCmdEStop, "emergency stop"); }
  core::Status clearStop() { return m_link.clearStop(); }

  RotaryStatus status() const { return m_link.status(); }

  bool reached(double angleDegrees) const {
    const RotaryStatus now = status();
    const double tolerance = m_options.positionToleranceDegrees;
    return now.link == LinkState::Connected && now.fault == RotaryFault::None && !now.moving && !now.homing &&
           now.atTarget && std::abs(now.targetAngleDegrees - angleDegrees) <= tolerance &&
           std::abs(now.angleDegrees - angleDegrees) <= tolerance;
  }

  void setStatusCallback(StatusCallback callback) { m_link.setStatusCallback(std::move(callback)); }

  const std::string& name() const { return m_link.name(); }
  const RotaryPlatformOptions& options() const { return m_options; }

 private:
  std::future<core::Status> command(std::uint16_t code, const std::string& what, bool isUrgent) {
    return m_link.submit([this, code, what](ModbusPort& port) { return writeCommand(port, code, what); }, isUrgent,
                         what);
  }

  // Worker thread: a command but a stop, with the session that says it comes from the controller in charge.
  core::Status writeCommand(ModbusPort& port, std::uint16_t code, const std::string& what) {
    std::vector<std::uint16_t> values{code};
    const std::vector<std::uint16_t> session = m_link.sessionWords();
    values.insert(values.end(), session.begin(), session.end());
    return port.writeRegisters(rr::kCommand, values, "the " + what + " command (registers 3-6)");
  }

  // A stop is COMMAND alone, without the session: the controller takes stops from anyone.
  std::future<core::Status> latch(StopKind kind, std::uint16_t code, const std::string& what) {
    m_link.update([this](RotaryStatus&) { m_motionExpected = false; });
    return m_link.latchStop(
        kind,
        [code, what](ModbusPort& port) {
          return port.writeRegisters(rr::kCommand, {code}, "the " + what + " command (register 3)");
        },
        what);
  }

  // Worker thread.
  void expectMotion(double targetDegrees) {
    m_link.update([&](RotaryStatus& s) {
      m_motionExpected = true;
      m_expectedTarget = targetDegrees;
      m_progressAngle = s.angleDegrees;
      m_progressTime = Clock::now();
    });
  }

  core::Status onConnected(ModbusPort&) {
    m_link.update([this](RotaryStatus& s) {
      s.polls = 0;
      m_echoChanged = Clock::now();
      m_haveEcho = false;
    });
    return core::Done{};
  }

  core::Status poll(ModbusPort& port) {
    std::uint16_t r[rr::kStatusBlockCount] = {};
    auto result =
        m_link.readStatusBlock(port, rr::kStatusBlockFirst, rr::kStatusBlockCount, r, "the status (registers 0-13)");
    if (!result.ok()) return result;
    if (auto control = m_link.checkControl(port, r[rr::kOwner]); !control.ok()) {
      m_link.publish();
      return control;
    }
    bool stall = false;
    double stallAngle = 0.0;
    double stallTarget = 0.0;
    m_link.update([&](RotaryStatus& s) {
      const Clock::time_point now = Clock::now();
      const std::uint16_t bits = r[rr::kStatus];
      s.targetAngleDegrees = regs::countsToDegrees(regs::getInt32(&r[rr::kTargetAngle]));
      s.angleDegrees = regs::countsToDegrees(regs::getInt32(&r[rr::kActualAngle]));
      s.enabled = (bits & rr::kEnabled) != 0;
      s.homed = (bits & rr::kHomed) != 0;
      s.moving = (bits & rr::kMoving) != 0;
      s.homing = (bits & rr::kHoming) != 0;
      s.atTarget = (bits & rr::kAtTarget) != 0;
      s.faultCode = r[rr::kFaultCode];
      s.fault = faultFromCode(s.faultCode);
      if ((bits & rr::kFault) != 0 && s.fault == RotaryFault::None) s.fault = RotaryFault::Unknown;
      if (m_hostStall && s.fault == RotaryFault::None) s.fault = RotaryFault::Stall;
      s.stallDetectedByHost = m_hostStall;

      const std::uint16_t echo = r[rr::kHeartbeatEcho];
      if (!m_haveEcho || echo != m_lastEcho) {
        m_haveEcho = true;
        m_lastEcho = echo;
        if (echo != 0) m_echoChanged = now;
      }
      const auto aliveWindow = 3 * m_options.connection.heartbeatInterval + 2 * m_options.connection.pollInterval;
      const bool alive = now - m_echoChanged <= aliveWindow;
      if (s.controllerAlive && !alive)
        s.lastError = name() + " answers Modbus but its control loop stopped echoing the heartbeat (register 12 "
                      "unchanged for " + std::to_string(aliveWindow.count()) +
                      " ms): it may not stop on its own; power-cycle the controller";
      s.controllerAlive = alive;
      ++s.polls;

      // Stall: a move or homing under way whose angle does not change.
      if ((m_motionExpected || s.homing) && s.fault == RotaryFault::None) {
        if (!s.homing && !s.moving && s.atTarget) {
          m_motionExpected = false;
        } else if (std::abs(s.angleDegrees - m_progressAngle) > kProgressDegrees) {
          m_progressAngle = s.angleDegrees;
          m_progressTime = now;
        } else if (now - m_progressTime > m_options.stallTimeout) {
          stall = true;
          stallAngle = s.angleDegrees;
          stallTarget = s.homing ? 0.0 : m_expectedTarget;
          m_hostStall = true;
          m_motionExpected = false;
          s.fault = RotaryFault::Stall;
          s.stallDetectedByHost = true;
          s.lastError = name() + " did not move for " + std::to_string(m_options.stallTimeout.count()) +
                        " ms while turning to " + degreesText(stallTarget) + " degrees (stuck at " +
                        degreesText(stallAngle) +
                        "): the motor may be stalled or the platform blocked. MultiDir stopped it; remove the "
                        "obstruction, clear the fault and home again";
        }
      } else if (!m_motionExpected) {
        m_progressAngle = s.angleDegrees;
        m_progressTime = now;
      }
    });
    // Latched like the operator's stop (issue 28): written first on the worker's next turn and again every
    // reconnectInitialDelay while the controller refuses it (busy...), and after every reconnect, until it takes
    // it. A single write the controller refused left the stuck motor driven. The future is not waited for: the
    // latch's state (status().stop) tells when the controller confirmed it.
    if (stall) (void)latch(StopKind::Stop, rr::kCmdStop, "stop");
    m_link.publish();
    return core::Done{};
  }

  RotaryPlatformOptions m_options;

  // Guarded by m_link's status mutex: touched only inside m_link.update().
  bool m_motionExpected = false;
  double m_expectedTarget = 0.0;
  double m_progressAngle = 0.0;
  Clock::time_point m_progressTime{};
  bool m_hostStall = false;
  Clock::time_point m_echoChanged{};
  std::uint16_t m_lastEcho = 0;
  bool m_haveEcho = false;

  DriverLink<RotaryStatus> m_link;  // last: its worker thread uses everything above
};

RotaryPlatform::RotaryPlatform(RotaryPlatformOptions options) : m_impl(std::make_unique<Impl>(std::move(options))) {}
RotaryPlatform::~RotaryPlatform() = default;
core::Status RotaryPlatform::connect() { return m_impl->connect(); }
void RotaryPlatform::disconnect() { m_impl->disconnect(); }
std::future<core::Status> RotaryPlatform::enable() { return m_impl->enable(); }
std::future<core::Status> RotaryPlatform::disable() { return m_impl->disable(); }
std::future<core::Status> RotaryPlatform::home() { return m_impl->home(); }
std::future<core::Status> RotaryPlatform::moveTo(double angleDegrees) { return m_impl->moveTo(angleDegrees); }
std::future<core::Status> RotaryPlatform::stop() { return m_impl->stop(); }
std::future<core::Status> RotaryPlatform::emergencyStop() { return m_impl->emergencyStop(); }
core::Status RotaryPlatform::clearStop() { return m_impl->clearStop(); }
std::future<core::Status> RotaryPlatform::clearFault() { return m_impl->clearFault(); }
RotaryStatus RotaryPlatform::status() const { return m_impl->status(); }
bool RotaryPlatform::reached(double angleDegrees) const { return m_impl->reached(angleDegrees); }
void RotaryPlatform::setStatusCallback(StatusCallback callback) { m_impl->setStatusCallback(std::move(callback)); }
std::string RotaryPlatform::name() const { return m_impl->name(); }
const RotaryPlatformOptions& RotaryPlatform::options() const { return m_impl->options(); }

}  // namespace multidir::hardware

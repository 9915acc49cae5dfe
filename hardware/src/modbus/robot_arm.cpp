#include "multidir/hardware/robot_arm.h"

#include <cmath>
#include <utility>
#include <vector>

#include "degrees_text.h"
#include "modbus/driver_link.h"
#include "modbus/register_maps.h"
#include "multidir/hardware/motion_limits.h"

namespace multidir::hardware {

namespace rb = regs::robot;
using Clock = std::chrono::steady_clock;

namespace {

RobotProgramState stateFromRegister(std::uint16_t value) {
  switch (value) {
    case rb::kStateNotRunning: return RobotProgramState::NotRunning;
    case rb::kStateIdle: return RobotProgramState::Idle;
    case rb::kStateMoving: return RobotProgramState::Moving;
    case rb::kStateReached: return RobotProgramState::Reached;
    case rb::kStateStopped: return RobotProgramState::Stopped;
    case rb::kStateHalted: return RobotProgramState::Halted;
    default: return RobotProgramState::Fault;
  }
}

// (-180, 180]
double normalizedAzimuth(double degreesIn) {
  double a = std::fmod(degreesIn, 360.0);
  if (a <= -180.0) a += 360.0;
  if (a > 180.0) a -= 360.0;
  return a;
}

double azimuthDifference(double a, double b) { return std::abs(normalizedAzimuth(a - b)); }

}  // namespace

const char* robotProgramStateName(RobotProgramState state) {
  switch (state) {
    case RobotProgramState::NotRunning: return "not running";
    case RobotProgramState::Idle: return "idle";
    case RobotProgramState::Moving: return "moving";
    case RobotProgramState::Reached: return "reached";
    case RobotProgramState::Stopped: return "stopped";
    case RobotProgramState::Halted: return "halted";
    case RobotProgramState::Fault: return "fault";
  }
  return "?";
}

class RobotArm::Impl {
 public:
  explicit Impl(RobotArmOptions options)
      : m_options(std::move(options)),
        m_link(m_options.connection, "robot arm at " + describe(m_options.connection),
               ControlRegisters{rb::kHostHeartbeat, rb::kOwner}, m_options.programHeartbeatTimeout,
               &RobotStatus::programAlive, [this](ModbusPort& port) { return onConnected(port); },
               [this](ModbusPort& port) { return poll(port); },
               [this](ModbusPort& port) {
                 return sendCommand(port, rb::kCmdRelease, {}, "the release of control (registers 131-135)");
               }) {}

  core::Status connect() {
    if (m_options.connection.transport != Transport::Tcp)
      return core::Error{core::ErrorCode::InvalidParameter,
                         "the robot arm is reached over Modbus TCP only (its controller's server on port 502)",
                         "transport"};
    if (auto valid = validateLinkAndProfile(m_options.connection, m_options.machine); !valid.ok()) return valid;
    if (m_options.machine.kind != core::MachineKind::TiltRotate)
      return core::Error{core::ErrorCode::InvalidParameter,
                         "the machine profile is not a tilting arm (5dof): load the robot's profile", "machine"};
    if (m_options.speedPercent < 1 || m_options.speedPercent > 100)
      return core::Error{core::ErrorCode::InvalidParameter, "speed must be between 1 and 100 %", "speed"};
    if (auto valid = validateHeartbeatTimeout(m_options.programHeartbeatTimeout); !valid.ok()) return valid;
    return m_link.start();
  }

  void disconnect() { m_link.stop(); }

  std::future<core::Status> moveTo(double tiltDegrees, double azimuthDegrees) {
    if (auto ok = checkTiltTarget(m_options.machine, tiltDegrees, azimuthDegrees); !ok.ok())
      return readyFuture(m_link.refuseMove(ok.error()));
    const double azimuth = normalizedAzimuth(azimuthDegrees);
    if (auto ok = m_link.requireLink(); !ok.ok()) return readyFuture(ok);
    const RobotStatus now = status();
    if (!now.programAlive || now.state == RobotProgramState::NotRunning)
      return readyFuture(m_link.refuse("cannot move: the URScript program multidir_platform.script is not running "
                                       "(its heartbeat, register 146, does not change); load it on the teach "
                                       "pendant and press Play"));
    if (now.state == RobotProgramState::Halted || now.state == RobotProgramState::Fault)
      return readyFuture(m_link.refuse(std::string("cannot move: the program is ") +
                                       robotProgramStateName(now.state) + " (fault code " +
                                       std::to_string(now.faultCode) + "); clear the fault first"));
    if (auto ok = m_link.refuseWhileStopLatched("move"); !ok.ok()) return readyFuture(ok);
    const std::uint16_t speed = static_cast<std::uint16_t>(m_options.speedPercent);
    const std::uint16_t tilt = regs::degreesToInt16Register(tiltDegrees);
    const std::uint16_t az = regs::degreesToInt16Register(azimuth);
    return m_link.submit(
        [this, tilt, az, speed, tiltDegrees, azimuth](ModbusPort& port) {
          if (auto ok = m_link.refuseWhileStopLatched("move"); !ok.ok()) return ok;
          return sendCommand(port, rb::kCmdMove, {tilt, az, speed},
                             "the move to tilt " + degreesText(tiltDegrees) + ", azimuth " + degreesText(azimuth) +
                                 " degrees (registers 128-135)");
        },
        false, "move to tilt " + degreesText(tiltDegrees) + ", azimuth " + degreesText(azimuth) + " degrees");
  }

  std::future<core::Status> stop() { return latch(StopKind::Stop, rb::kCmdStop, "stop"); }
  std::future<core::Status> emergencyStop() { return latch(StopKind::EmergencyStop, rb::kCmdHalt, "emergency stop"); }
  core::Status clearStop() { return m_link.clearStop(); }
  std::future<core::Status> clearFault() { return simple(rb::kCmdReset, "reset", false); }

  RobotStatus status() const { return m_link.status(); }

  bool reached(double tiltDegrees, double azimuthDegrees) const {
    const RobotStatus s = status();
    const double tol = m_options.orientationToleranceDegrees;
    // At tilt 0 every azimuth is the same orientation.
    const bool azimuthOk = [&] {
      if (tiltDegrees <= tol) return true;
      return azimuthDifference(s.targetAzimuthDegrees, azimuthDegrees) <= 0.011 &&
             azimuthDifference(s.azimuthDegrees, azimuthDegrees) <= tol;
    }();
    return s.link == LinkState::Connected && s.programAlive && s.state == RobotProgramState::Reached &&
           s.acknowledgedSequence == s.sentSequence && s.sentSequence != 0 &&
           std::abs(s.targetTiltDegrees - tiltDegrees) <= 0.011 && std::abs(s.tiltDegrees - tiltDegrees) <= tol &&
           azimuthOk;
  }

  void setStatusCallback(StatusCallback callback) { m_link.setStatusCallback(std::move(callback)); }

  const std::string& name() const { return m_link.name(); }
  const RobotArmOptions& options() const { return m_options; }

 private:
  std::future<core::Status> simple(std::uint16_t code, const std::string& what, bool isUrgent) {
    if (auto ok = m_link.requireLink(); !ok.ok()) return readyFuture(ok);
    return m_link.submit(
        [this, code, what](ModbusPort& port) {
          return sendCommand(port, code, {}, "the " + what + " command (registers 131-135)");
        },
        isUrgent, what);
  }

  // The latched command reads the sequence the program holds first (the program may have restarted while
  // the link was down), so that the stop is a new command to it.
  std::future<core::Status> latch(StopKind kind, std::uint16_t code, const std::string& what) {
    return m_link.latchStop(
        kind,
        [this, code, what](ModbusPort& port) {
          std::uint16_t seq = 0;
          auto result = port.readRegisters(rb::kSequence, 1, &seq, "the command sequence (register 132)");
          if (!result.ok()) return result;
          m_sequence = seq;
          return sendCommand(port, code, {}, "the " + what + " command (registers 131-132)");
        },
        what);
  }

  // Worker thread: writes the request values (from register 128), the command, a new sequence number and
  // (but for a stop or halt, which the program takes from anyone) the session in one request, so the program
  // never sees half a command.
  core::Status sendCommand(ModbusPort& port, std::uint16_t code, const std::vector<std::uint16_t>& request,
                           const std::string& what) {
    std::uint16_t sequence = static_cast<std::uint16_t>(m_sequence + 1);
    if (sequence == 0) sequence = 1;
    std::vector<std::uint16_t> values;
    int first = rb::kCommand;
    if (!request.empty()) {
      values = request;
      first = rb::kRequestTilt;
    }
    values.push_back(code);
    values.push_back(sequence);
    if (code != rb::kCmdStop && code != rb::kCmdHalt) {
      const std::vector<std::uint16_t> session = m_link.sessionWords();
      values.insert(values.end(), session.begin(), session.end());
    }
    auto result = port.writeRegisters(first, values, what);
    if (!result.ok()) {
      m_link.noteError(result.error().message);
      return result;
    }
    m_sequence = sequence;
    m_link.update([&](RobotStatus& s) {
      s.sentSequence = sequence;
      m_sentAt = Clock::now();
      m_ackOverdueReported = false;
    });
    return core::Done{};
  }

  core::Status onConnected(ModbusPort& port) {
    // Continue the sequence the robot holds, so the next command is new to the program.
    std::uint16_t seq = 0;
    auto result = port.readRegisters(rb::kSequence, 1, &seq, "the command sequence (register 132)");
    if (!result.ok()) return result;
    m_sequence = seq;
    m_link.update([&](RobotStatus& s) {
      s.sentSequence = seq;
      s.polls = 0;
      m_programChanged = Clock::now();
      m_haveProgramHeartbeat = false;
    });
    return core::Done{};
  }

  core::Status poll(ModbusPort& port) {
    std::uint16_t r[rb::kStatusBlockCount] = {};
    auto result = m_link.readStatusBlock(port, rb::kStatusBlockFirst, rb::kStatusBlockCount, r,
                                         "the status (registers 128-150)");
    if (!result.ok()) return result;
    auto at = [&r](int address) { return r[address - rb::kStatusBlockFirst]; };
    if (auto control = m_link.checkControl(port, at(rb::kOwner)); !control.ok()) {
      m_link.publish();
      return control;
    }
    m_link.update([&](RobotStatus& s) {
      const Clock::time_point now = Clock::now();
      s.state = stateFromRegister(at(rb::kState));
      s.acknowledgedSequence = at(rb::kAckSequence);
      s.faultCode = at(rb::kFaultCode);
      s.tiltDegrees = regs::int16RegisterToDegrees(at(rb::kActualTilt));
      s.azimuthDegrees = regs::int16RegisterToDegrees(at(rb::kActualAzimuth));
      s.targetTiltDegrees = regs::int16RegisterToDegrees(at(rb::kRequestTilt));
      s.targetAzimuthDegrees = regs::int16RegisterToDegrees(at(rb::kRequestAzimuth));
      const std::uint16_t beat = at(rb::kProgramHeartbeat);
      if (!m_haveProgramHeartbeat || beat != m_lastProgramHeartbeat) {
        m_haveProgramHeartbeat = true;
        m_lastProgramHeartbeat = beat;
        if (beat != 0 || s.state != RobotProgramState::NotRunning) m_programChanged = now;
      }
      const auto window = m_options.programHeartbeatTimeout + 2 * m_options.connection.pollInterval;
      const bool alive = s.state != RobotProgramState::NotRunning && now - m_programChanged <= window;
      if (s.programAlive && !alive)
        s.lastError = name() + ": the URScript program stopped (its heartbeat, register 146, unchanged for " +
                      std::to_string(window.count()) + " ms): check the teach pendant for a protective stop or a "
                      "program error, then start multidir_platform.script again";
      s.programAlive = alive;
      if (s.sentSequence != s.acknowledgedSequence && !m_ackOverdueReported &&
          now - m_sentAt > m_options.acknowledgeTimeout) {
        m_ackOverdueReported = true;
        s.lastError = name() + ": the program did not acknowledge command " + std::to_string(s.sentSequence) +
                      " within " + std::to_string(m_options.acknowledgeTimeout.count()) +
                      " ms: check that multidir_platform.script is running and not paused";
      }
      ++s.polls;
    });
    m_link.publish();
    return core::Done{};
  }

  RobotArmOptions m_options;

  // Guarded by m_link's status mutex: touched only inside m_link.update().
  Clock::time_point m_programChanged{};
  std::uint16_t m_lastProgramHeartbeat = 0;
  bool m_haveProgramHeartbeat = false;
  Clock::time_point m_sentAt{};
  bool m_ackOverdueReported = false;

  std::uint16_t m_sequence = 0;  // worker thread only
  DriverLink<RobotStatus> m_link;  // last: its worker thread uses everything above
};

RobotArm::RobotArm(RobotArmOptions options) : m_impl(std::make_unique<Impl>(std::move(options))) {}
RobotArm::~RobotArm() = default;
core::Status RobotArm::connect() { return m_impl->connect(); }
void RobotArm::disconnect() { m_impl->disconnect(); }
std::future<core::Status> RobotArm::moveTo(double tiltDegrees, double azimuthDegrees) {
  return m_impl->moveTo(tiltDegrees, azimuthDegrees);
}
std::future<core::Status> RobotArm::stop() { return m_impl->stop(); }
std::future<core::Status> RobotArm::emergencyStop() { return m_impl->emergencyStop(); }
core::Status RobotArm::clearStop() { return m_impl->clearStop(); }
std::future<core::Status> RobotArm::clearFault() { return m_impl->clearFault(); }
RobotStatus RobotArm::status() const { return m_impl->status(); }
bool RobotArm::reached(double tiltDegrees, double azimuthDegrees) const {
  return m_impl->reached(tiltDegrees, azimuthDegrees);
}
void RobotArm::setStatusCallback(StatusCallback callback) { m_impl->setStatusCallback(std::move(callback)); }
std::string RobotArm::name() const { return m_impl->name(); }
const RobotArmOptions& RobotArm::options() const { return m_impl->options(); }

}  // namespace multidir::hardware

#include "sim/simulated_devices.h"

#include <algorithm>
#include <cmath>

#include "modbus/register_maps.h"
#include "sim/platform_kinematics.h"

namespace multidir::hardware::sim {

namespace rr = regs::rotary;
namespace rb = regs::robot;

namespace {

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

// ---- Rotary controller -------------------------------------------------------------------------------------

RotaryController::RotaryController(const SimulatorOptions& options, std::uint16_t* regs, Clock::time_point now)
    : m_options(options), m_regs(regs), m_angle(options.rotaryInitialAngleDegrees), m_lastLife(now), m_lastStep(now) {
  regs::putInt32(regs::degreesToCounts(m_angle), &m_regs[rr::kTargetAngle]);
  m_regs[rr::kSpeed] = regs::degreesPerSecondToRegister(10.0);
  m_regs[rr::kHeartbeatTimeout] = 0;
  publish();
}

void RotaryController::lapseControl(Clock::time_point now) {
  if (m_owner != 0 && now - m_ownerLife > m_options.controlTimeout) m_owner = 0;
}

int RotaryController::writeRefusal(int address, const std::vector<std::uint16_t>& values, Clock::time_point now) {
  constexpr int kWrongState = 1;  // Modbus exception 1: not in the device's present state
  lapseControl(now);
  const int last = address + static_cast<int>(values.size()) - 1;
  const auto touches = [&](int reg) { return address <= reg && reg <= last; };
  const auto value = [&](int reg) { return values[static_cast<std::size_t>(reg - address)]; };
  if (m_owner == 0 || address == rr::kClaim) return 0;  // CLAIM is the last writable register
  if (touches(rr::kSession) && value(rr::kSession) == m_owner) {
    m_ownerLife = now;
    return 0;
  }
  const bool stopAlone = address == rr::kCommand && last == rr::kCommand &&
                         (value(rr::kCommand) == rr::kCmdStop || value(rr::kCommand) == rr::kCmdEStop);
  return stopAlone ? 0 : kWrongState;
}

void RotaryController::afterWrite(Clock::time_point now) {
  const std::uint16_t claim = m_regs[rr::kClaim];
  if (claim != 0) {
    m_regs[rr::kClaim] = 0;
    lapseControl(now);
    if (m_owner == 0 || m_owner == claim) {
      m_owner = claim;
      m_ownerLife = now;
    }
  }
  const std::uint16_t code = m_regs[rr::kCommand];
  if (code == rr::kCmdNone) {
    publish();
    return;
  }
  m_regs[rr::kCommand] = rr::kCmdNone;
  m_lastLife = now;  // a command is a sign of life too
  command(code, now);
  publish();
}

void RotaryController::command(std::uint16_t code, Clock::time_point) {
  switch (code) {
    case rr::kCmdEnable:
      if (m_fault == 0) m_enabled = true;
      break;
    case rr::kCmdDisable:
      m_enabled = false;
      m_moving = false;
      m_homing = false;
      break;
    case rr::kCmdHome:
      if (!m_enabled || m_fault != 0) return reject();
      m_homing = true;
      m_homed = false;
      m_moving = true;
      m_target = 0.0;
      break;
    case rr::kCmdMove: {
      const double target = regs::countsToDegrees(regs::getInt32(&m_regs[rr::kTargetAngle]));
      if (!m_enabled || !m_homed || m_fault != 0 || target < m_options.rotaryMinAngleDegrees ||
          target > m_options.rotaryMaxAngleDegrees)
        return reject();
      m_target = target;
      m_moving = std::abs(m_target - m_angle) > 1e-9;
      break;
    }
    case rr::kCmdStop:
      m_moving = false;
      m_homing = false;
      break;
    case rr::kCmdEStop:
      m_enabled = false;
      m_moving = false;
      m_homing = false;
      m_homed = false;  // the power stage was cut: the position is no longer trusted
      m_fault = rr::kFaultEStop;
      break;
    case rr::kCmdClearFault:
      m_fault = 0;
      break;
    case rr::kCmdRelease:  // writeRefusal took it only with the holder's session, or while nobody holds it
      m_owner = 0;
      break;
    default:
      reject();
      break;
  }
}

void RotaryController::step(Clock::time_point now) {
  const double dt = seconds(now - m_lastStep);
  m_lastStep = now;
  lapseControl(now);
  const std::uint16_t heartbeat = m_regs[rr::kHeartbeat];
  if (heartbeat != m_lastHeartbeat) {
    m_lastHeartbeat = heartbeat;
    m_lastLife = now;
  }
  const std::uint16_t timeoutMs = m_regs[rr::kHeartbeatTimeout];
  if (timeoutMs > 0 && (m_moving || m_homing) && now - m_lastLife > std::chrono::milliseconds(timeoutMs)) {
    m_moving = false;
    m_homing = false;
    m_fault = rr::kFaultHeartbeat;
  }
  if (m_moving && !m_stuck && dt > 0) {
    const double speed = m_homing ? m_options.rotaryHomingSpeedDegreesPerSecond
                                  : regs::registerToDegreesPerSecond(m_regs[rr::kSpeed]);
    const double remaining = m_target - m_angle;
    const double advance = speed * dt;
    if (std::abs(remaining) <= advance) {
      m_angle = m_target;
      m_moving = false;
      if (m_homing) {
        m_homing = false;
        m_homed = true;
        regs::putInt32(0, &m_regs[rr::kTargetAngle]);
      }
    } else {
      m_angle += remaining > 0 ? advance : -advance;
    }
  }
  publish();
}

void RotaryController::publish() {
  regs::putInt32(regs::degreesToCounts(m_angle), &m_regs[rr::kActualAngle]);
  std::uint16_t bits = 0;
  if (m_enabled) bits |= rr::kEnabled;
  if (m_homed) bits |= rr::kHomed;
  if (m_moving) bits |= rr::kMoving;
  if (m_homing) bits |= rr::kHoming;
  if (!m_moving && !m_homing && m_homed && std::abs(m_angle - m_target) < 1e-9) bits |= rr::kAtTarget;
  if (m_fault != 0) bits |= rr::kFault;
  m_regs[rr::kStatus] = bits;
  m_regs[rr::kFaultCode] = m_fault;
  if (m_echoing) m_regs[rr::kHeartbeatEcho] = m_regs[rr::kHeartbeat];
  m_regs[rr::kOwner] = m_owner;
}

SimulatedRotaryState RotaryController::state() const {
  SimulatedRotaryState s;
  s.angleDegrees = m_angle;
  s.platformOrientation = rotaryShaftOrientation(m_angle, m_options.rotaryShaftAxis);
  s.targetAngleDegrees = m_target;
  s.enabled = m_enabled;
  s.homed = m_homed;
  s.homing = m_homing;
  s.moving = m_moving;
  s.faultCode = m_fault;
  s.controlOwner = m_owner;
  return s;
}

// ---- Robot program ---------------------------------------------------------------------------------------

RobotProgram::RobotProgram(const SimulatorOptions& options, std::uint16_t* regs, Clock::time_point now)
    : m_options(options), m_regs(regs), m_lastLife(now), m_lastStep(now) {
  publish();
}

void RobotProgram::command(std::uint16_t code, std::uint16_t session) {
  switch (code) {
    case rb::kCmdMove: {
      if (m_state == rb::kStateHalted || m_state == rb::kStateFault) return;  // needs a reset first
      const double tilt = regs::int16RegisterToDegrees(reg(rb::kRequestTilt));
      const double azimuth = regs::int16RegisterToDegrees(reg(rb::kRequestAzimuth));
      if (tilt < 0.0 || tilt > m_options.robotMaxTiltDegrees || std::abs(azimuth) > 180.0) {
        m_state = rb::kStateFault;
        m_fault = rb::kFaultBeyondLimits;
        return;
      }
      m_target = urscriptTargetOrientation(tilt, azimuth);
      m_state = rb::kStateMoving;
      break;
    }
    case rb::kCmdStop:
      if (m_state == rb::kStateMoving) m_state = rb::kStateStopped;
      break;
    case rb::kCmdHalt:
      m_state = rb::kStateHalted;
      break;
    case rb::kCmdReset:
      m_fault = 0;
      m_state = rb::kStateIdle;
      break;
    case rb::kCmdRelease:
      if (session == m_owner) m_owner = 0;
      break;
    default:
      m_state = rb::kStateFault;
      m_fault = rb::kFaultUnknownCommand;
      break;
  }
}

void RobotProgram::step(Clock::time_point now) {
  const double dt = seconds(now - m_lastStep);
  m_lastStep = now;
  if (!m_answering) return;  // the program hangs: nothing moves, nothing is written
  ++m_heartbeat;
  if (m_heartbeat == 0) m_heartbeat = 1;

  followControl(now);
  // A heartbeat or a command counts as life only from the session in control (or anyone while nobody is).
  const std::uint16_t session = reg(rb::kSession);
  const bool fromController = m_owner == 0 || session == m_owner;
  const std::uint16_t hostBeat = reg(rb::kHostHeartbeat);
  if (hostBeat != m_lastHostHeartbeat) {
    m_lastHostHeartbeat = hostBeat;
    if (fromController) {
      m_lastLife = now;
      m_ownerLife = now;
    }
  }
  // A new SEQUENCE is a new command: taken (and acknowledged) from the controller, a stop or halt from
  // anyone; another session's other commands are ignored, and ACK_SEQUENCE does not follow them.
  const std::uint16_t sequence = reg(rb::kSequence);
  if (sequence != m_lastSequence) {
    m_lastSequence = sequence;
    const std::uint16_t code = reg(rb::kCommand);
    if (fromController || code == rb::kCmdStop || code == rb::kCmdHalt) {
      m_ack = sequence;
      if (fromController) {
        m_lastLife = now;
        m_ownerLife = now;
      }
      command(code, session);
    }
  }
  const std::uint16_t timeoutMs = reg(rb::kHeartbeatTimeout);
  if (timeoutMs > 0 && m_state == rb::kStateMoving && now - m_lastLife > std::chrono::milliseconds(timeoutMs)) {
    m_state = rb::kStateFault;
    m_fault = rb::kFaultHeartbeat;
  }
  if (m_state == rb::kStateMoving && dt > 0) {
    const std::uint16_t percent = std::clamp<std::uint16_t>(reg(rb::kRequestSpeed), 1, 100);
    const double advance = m_options.robotMaxSpeedDegreesPerSecond * percent / 100.0 * dt * M_PI / 180.0;
    m_orientation = turnedTowards(m_orientation, m_target, advance);
    // The movel has ended: the TCP stands at the target orientation.
    if (angleBetween(m_orientation, m_target) < 1e-12) m_state = rb::kStateReached;
  }
  publish();
}

// Takes a claim from CLAIM (and clears it) and frees the lock when its holder fell silent.
void RobotProgram::followControl(Clock::time_point now) {
  if (m_owner != 0 && now - m_ownerLife > m_options.controlTimeout) m_owner = 0;
  const std::uint16_t claim = reg(rb::kClaim);
  if (claim == 0) return;
  reg(rb::kClaim) = 0;
  if (m_owner == 0 || m_owner == claim) {
    m_owner = claim;
    m_ownerLife = now;
  }
}

void RobotProgram::publish() {
  reg(rb::kState) = m_state;
  reg(rb::kOwner) = m_owner;
  reg(rb::kAckSequence) = m_ack;
  reg(rb::kProgramHeartbeat) = m_heartbeat;
  reg(rb::kFaultCode) = m_fault;
  const ReportedTilt actual = urscriptReportedTilt(m_orientation);
  reg(rb::kActualTilt) = regs::degreesToInt16Register(actual.tiltDegrees);
  reg(rb::kActualAzimuth) = regs::degreesToInt16Register(actual.azimuthDegrees);
}

SimulatedRobotState RobotProgram::state() const {
  SimulatedRobotState s;
  const ReportedTilt actual = urscriptReportedTilt(m_orientation);
  s.tiltDegrees = actual.tiltDegrees;
  s.azimuthDegrees = actual.azimuthDegrees;
  s.platformOrientation = m_orientation;
  s.programState = m_state;
  s.faultCode = m_fault;
  s.acknowledgedSequence = m_ack;
  s.controlOwner = m_owner;
  return s;
}

}  // namespace multidir::hardware::sim

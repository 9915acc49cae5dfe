#include "sim/ur_controller.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace multidir::hardware::sim {
namespace {

using ur::UrProgramState;
using ur::UrRobotMode;
using ur::UrSafetyMode;
using Kind = ur::UrRobotMessage::Kind;

const char* const kJointNames[6] = {"base", "shoulder", "elbow", "wrist 1", "wrist 2", "wrist 3"};

// UR's error codes as the simulator numbers them (docs/hardware.md): C153 protective stop (A = the joint),
// C150 emergency stop.
constexpr int kCodeProtectiveStop = 153;
constexpr int kCodeEmergencyStop = 150;

std::string lowered(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string number(double value, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace

Eigen::Isometry3d urPoseToIsometry(const std::array<double, 6>& p) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(p[0], p[1], p[2]) * 1000.0;
  const Eigen::Vector3d r(p[3], p[4], p[5]);
  const double angle = r.norm();
  if (angle > 0.0) pose.linear() = Eigen::AngleAxisd(angle, r / angle).toRotationMatrix();
  return pose;
}

std::array<double, 6> isometryToUrPose(const Eigen::Isometry3d& pose) {
  const Eigen::AngleAxisd aa(pose.linear());
  const Eigen::Vector3d r = aa.axis() * aa.angle();
  const Eigen::Vector3d t = pose.translation() / 1000.0;
  return {t.x(), t.y(), t.z(), r.x(), r.y(), r.z()};
}

double UrController::Profile::at(double t) const {
  t = std::clamp(t, 0.0, duration());
  if (t <= accelTime) return 0.5 * acceleration * t * t;
  const double accelDistance = 0.5 * acceleration * accelTime * accelTime;
  if (t <= accelTime + cruiseTime) return accelDistance + peak * (t - accelTime);
  const double left = duration() - t;
  return distance - 0.5 * acceleration * left * left;
}

UrController::Profile UrController::profile(double distance, double speed, double acceleration) {
  Profile p;
  p.distance = distance;
  p.acceleration = acceleration;
  if (distance * acceleration >= speed * speed) {  // reaches the commanded speed
    p.peak = speed;
    p.accelTime = speed / acceleration;
    p.cruiseTime = (distance - speed * speed / acceleration) / speed;
  } else {  // a triangle: accelerates halfway, brakes the rest
    p.accelTime = std::sqrt(distance / acceleration);
    p.peak = acceleration * p.accelTime;
    p.cruiseTime = 0.0;
  }
  return p;
}

UrController::UrController(robot::ArmModel arm, const robot::Joints& initial)
    : m_arm(std::move(arm)), m_q(initial), m_qTarget(initial) {}

std::array<double, 6> UrController::tcpPose(const robot::Joints& q) const {
  const Eigen::Isometry3d pose = robot::forwardKinematics(m_arm, q) * m_tcp;
  std::array<double, 6> p = isometryToUrPose(pose);
  for (int i = 0; i < 3; ++i) p[static_cast<std::size_t>(i)] *= 1000.0;
  return p;
}

int UrController::currentLine() const {
  if (!m_program || m_pc >= m_program->statements.size()) return 0;
  return m_program->statements[m_pc].line;
}

bool UrController::atRest() const {
  if (m_activity == Activity::Braking || m_activity == Activity::MoveJ || m_activity == Activity::MoveL) return false;
  return std::all_of(m_qd.begin(), m_qd.end(), [](double v) { return v == 0.0; });
}

void UrController::message(Kind kind, const std::string& text, int line, int column, int code, int argument) {
  ur::UrRobotMessage m;
  m.kind = kind;
  m.timestampUs = static_cast<std::uint64_t>(std::llround(m_time * 1e6));
  m.text = text;
  m.line = line;
  m.column = column;
  m.code = code;
  m.argument = argument;
  m_messages.push_back(std::move(m));
}

std::vector<ur::UrRobotMessage> UrController::takeMessages() {
  std::vector<ur::UrRobotMessage> taken;
  taken.swap(m_messages);
  return taken;
}

std::vector<UrTraceSample> UrController::takeTrace() {
  std::vector<UrTraceSample> taken;
  taken.swap(m_trace);
  return taken;
}

void UrController::watchCollisions(const robot::Cell& cell) { m_collisionWatch.emplace(cell); }

void UrController::tick() {
  m_time += kUrTickSeconds;
  const robot::Joints before = m_q;
  // A program that ends within this tick still owns the tick's motion in the trace.
  m_tickProgram = m_programState == UrProgramState::Playing ? m_programName : std::string();
  if (m_robotMode == UrRobotMode::PowerOn && m_time - m_poweredOnAt >= kPowerOnSeconds - 1e-9)
    m_robotMode = UrRobotMode::Idle;
  // A set point below the room's temperature is the heater off: the nozzle cools to the room, not below it.
  const double setPoint = std::max(m_analogOut[1] * kNozzleFullScaleC, kAmbientC);
  m_nozzleC +=
      std::clamp(setPoint - m_nozzleC, -kNozzleCoolingCPerS * kUrTickSeconds, kNozzleHeatingCPerS * kUrTickSeconds);
  if (m_activity == Activity::Braking)
    advanceActivity(kUrTickSeconds);
  else if (m_programState == UrProgramState::Playing)
    runProgram();
  // The joint speed limits hold for each tick's whole change (a tick can end one move and begin the next): a
  // tick that would exceed one is not taken, and the arm brakes from the last tick's speeds.
  if (m_activity != Activity::Braking) checkSpeeds(before);
  // The way the arm took this tick, against the cell's bodies and table: a contact is a protective stop, as a
  // real arm's collision detection makes one (the arm then brakes from this tick's speeds).
  if (m_collisionWatch && m_safetyMode == UrSafetyMode::Normal && m_q != before) {
    const std::string contact = m_collisionWatch->firstContact(before, m_q);
    if (!contact.empty()) {
      std::string joints;
      for (std::size_t i = 0; i < 6; ++i) joints += (i ? ", " : "") + number(m_q[i] * 180.0 / M_PI, 1);
      fault(UrSafetyMode::ProtectiveStop,
            "Protective stop: collision: " + contact + " (joints " + joints + " deg" +
                (m_programName.empty() ? std::string() : ", program " + m_programName + " line " +
                                                             std::to_string(currentLine())) + ")",
            kCodeProtectiveStop);
    }
  }
  // A stop that began this tick brakes from the last tick's speeds (kept) from the next tick on.
  const bool brakingBegan = m_activity == Activity::Braking && m_elapsed == 0.0;
  if (!brakingBegan)
    for (std::size_t i = 0; i < 6; ++i) m_qd[i] = (m_q[i] - before[i]) / kUrTickSeconds;
  m_qTarget = m_q;
  if (m_nextProgram && m_activity == Activity::None) {
    m_program = std::move(m_nextProgram);
    m_nextProgram.reset();
    m_programName = m_program->name;
    m_pc = 0;
    m_programState = UrProgramState::Playing;
  }
  record();
}

void UrController::record() {
  const bool moving = !atRest();
  const bool running = m_programState == UrProgramState::Playing || m_programState == UrProgramState::Paused;
  if (!moving && !running && m_tickProgram.empty()) return;
  UrTraceSample sample;
  sample.time = m_time;
  sample.q = m_q;
  sample.tcp = tcpPose(m_q);
  sample.analogOut0 = m_analogOut[0];
  sample.analogOut1 = m_analogOut[1];
  sample.nozzleC = m_nozzleC;
  sample.program = running ? m_programName : m_tickProgram;
  sample.line = running ? currentLine() : 0;
  m_trace.push_back(std::move(sample));
}

void UrController::runProgram() {
  // Statements that take no time run in the tick that reaches them; those that take time share the tick: what
  // one leaves of it when it ends goes to the next, so a program's time is not rounded up to ticks per move.
  double budget = kUrTickSeconds;
  while (m_programState == UrProgramState::Playing && m_program && budget > 1e-12) {
    if (m_activity == Activity::None) {
      if (m_pc >= m_program->statements.size()) {
        m_programState = UrProgramState::Stopped;
        ++m_programsFinished;
        m_program.reset();
        return;
      }
      if (!startStatement(m_program->statements[m_pc])) {
        if (m_programState == UrProgramState::Playing) ++m_pc;
        continue;
      }
    }
    budget = advanceActivity(budget);
  }
}

bool UrController::startStatement(const ur::UrStatement& s) {
  m_elapsed = 0.0;
  switch (s.kind) {
    case ur::UrStatementKind::SetTcp:
      m_tcp = urPoseToIsometry(s.pose);
      return false;
    case ur::UrStatementKind::SetAnalogOut:
      m_analogOut[static_cast<std::size_t>(s.index)] = s.value;
      return false;
    case ur::UrStatementKind::SetDigitalOut:
      if (s.flag)
        m_digitalOut |= 1u << s.index;
      else
        m_digitalOut &= ~(1u << s.index);
      return false;
    case ur::UrStatementKind::TextMsg:
      message(Kind::Text, s.text);
      return false;
    case ur::UrStatementKind::WriteIntRegister:
      m_outputIntRegisters[static_cast<std::size_t>(s.index)] = s.integer;
      return false;
    case ur::UrStatementKind::Sleep:
      if (s.value <= 0.0) return false;
      m_activity = Activity::Sleep;
      return true;
    case ur::UrStatementKind::WaitAnalogInBelow:
      m_waitBelow = s.value;
      m_activity = Activity::Wait;
      return true;
    case ur::UrStatementKind::MoveJ: {
      robot::Joints target{};
      std::copy(s.pose.begin(), s.pose.end(), target.begin());
      double longest = 0.0;
      for (std::size_t i = 0; i < 6; ++i) longest = std::max(longest, std::abs(target[i] - m_q[i]));
      if (!checkLimits(target)) return false;
      if (longest == 0.0) return false;
      m_fromQ = m_q;
      m_toQ = target;
      m_profile = profile(longest, s.v, s.a);
      m_activity = Activity::MoveJ;
      return true;
    }
    case ur::UrStatementKind::MoveL: {
      m_fromPose = robot::forwardKinematics(m_arm, m_q) * m_tcp;
      m_toPose = urPoseToIsometry(s.pose);
      const double length = (m_toPose.translation() - m_fromPose.translation()).norm();
      const double angle = Eigen::AngleAxisd(m_fromPose.linear().transpose() * m_toPose.linear()).angle();
      // A move with no translation turns the tool at a and v read as rad/s^2 and rad/s, as UR does.
      if (length > 1e-9)
        m_profile = profile(length, s.v * 1000.0, s.a * 1000.0);
      else if (angle > 1e-12)
        m_profile = profile(angle, s.v, s.a);
      else
        return false;
      m_activity = Activity::MoveL;
      return true;
    }
  }
  return false;
}

bool UrController::checkLimits(const robot::Joints& next) {
  for (std::size_t i = 0; i < 6; ++i) {
    const robot::JointLimits& limit = m_arm.limits[i];
    if (next[i] < limit.minRad - 1e-12 || next[i] > limit.maxRad + 1e-12) {
      fault(UrSafetyMode::ProtectiveStop,
            "Protective stop: Joint Position Limit violated: joint " + std::to_string(i + 1) + " (" + kJointNames[i] +
                ") would reach " + number(next[i] * 180.0 / M_PI, 2) + " deg, outside its limits " +
                number(limit.minRad * 180.0 / M_PI, 1) + " to " + number(limit.maxRad * 180.0 / M_PI, 1) + " deg",
            kCodeProtectiveStop, static_cast<int>(i + 1));
      return false;
    }
  }
  return true;
}

bool UrController::checkSpeeds(const robot::Joints& before) {
  for (std::size_t i = 0; i < 6; ++i) {
    const double speed = std::abs(m_q[i] - before[i]) / kUrTickSeconds;
    const double limit = m_arm.limits[i].maxSpeedRadPerS;
    if (speed > limit * (1.0 + 1e-9)) {
      m_q = before;  // the tick is not taken
      fault(UrSafetyMode::ProtectiveStop,
            "Protective stop: Joint Speed Limit violated: joint " + std::to_string(i + 1) + " (" + kJointNames[i] +
                ") would turn at " + number(speed, 3) + " rad/s, above its limit of " + number(limit, 3) + " rad/s",
            kCodeProtectiveStop, static_cast<int>(i + 1));
      return false;
    }
  }
  return true;
}

double UrController::advanceActivity(double budget) {
  m_elapsed += budget;
  // What is left of the budget once an activity of `duration` ends.
  const auto finish = [&](double duration) {
    m_activity = Activity::None;
    ++m_pc;
    return std::max(0.0, m_elapsed - duration);
  };
  switch (m_activity) {
    case Activity::None:
      return budget;
    case Activity::Sleep: {
      const double duration = m_program->statements[m_pc].value;
      return m_elapsed >= duration - 1e-12 ? finish(duration) : 0.0;
    }
    case Activity::Wait:
      // The loop's condition is read as the tick reaches it; sync() ends the tick while it holds.
      if (m_nozzleC / kNozzleFullScaleC >= m_waitBelow) {
        m_activity = Activity::None;
        ++m_pc;
        return budget;
      }
      return 0.0;
    case Activity::MoveJ: {
      const double t = std::min(m_elapsed, m_profile.duration());
      const double fraction = m_profile.at(t) / m_profile.distance;
      robot::Joints next{};
      for (std::size_t i = 0; i < 6; ++i) next[i] = m_fromQ[i] + fraction * (m_toQ[i] - m_fromQ[i]);
      if (m_elapsed >= m_profile.duration()) next = m_toQ;
      if (!checkLimits(next)) return 0.0;
      m_q = next;
      return m_elapsed >= m_profile.duration() ? finish(m_profile.duration()) : 0.0;
    }
    case Activity::MoveL: {
      const double t = std::min(m_elapsed, m_profile.duration());
      const double fraction = m_profile.at(t) / m_profile.distance;
      const Eigen::AngleAxisd turn(m_fromPose.linear().transpose() * m_toPose.linear());
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation() = m_fromPose.translation() + fraction * (m_toPose.translation() - m_fromPose.translation());
      pose.linear() = m_fromPose.linear() * Eigen::AngleAxisd(fraction * turn.angle(), turn.axis()).toRotationMatrix();
      if (m_elapsed >= m_profile.duration()) pose = m_toPose;
      const std::vector<robot::IkSolution> solutions = robot::inverseKinematics(m_arm, pose * m_tcp.inverse());
      if (solutions.empty()) {
        fault(UrSafetyMode::ProtectiveStop,
              "Protective stop: no inverse kinematics solution: the movel's path leaves the arm's reach at line " +
                  std::to_string(currentLine()),
              kCodeProtectiveStop, 0);
        return 0.0;
      }
      const std::optional<robot::Joints> next = robot::nearestWithinLimits(m_arm, solutions, m_q);
      if (!next) {
        fault(UrSafetyMode::ProtectiveStop,
              "Protective stop: Joint Position Limit violated: every joint solution of the movel's pose at line " +
                  std::to_string(currentLine()) + " is outside the joint limits",
              kCodeProtectiveStop, 0);
        return 0.0;
      }
      m_q = *next;
      return m_elapsed >= m_profile.duration() ? finish(m_profile.duration()) : 0.0;
    }
    case Activity::Braking: {
      const double t = std::min(m_elapsed, m_brakeDuration);
      for (std::size_t i = 0; i < 6; ++i) {
        const double q = m_brakeFromQ[i] + m_brakeFromQd[i] * (t - t * t / (2.0 * m_brakeDuration));
        m_q[i] = std::clamp(q, m_arm.limits[i].minRad, m_arm.limits[i].maxRad);
      }
      if (m_elapsed >= m_brakeDuration) {
        m_activity = Activity::None;
        if (m_powerOffAfterBraking) {
          m_robotMode = UrRobotMode::PowerOff;
          m_powerOffAfterBraking = false;
        }
      }
      return 0.0;
    }
  }
  return 0.0;
}

void UrController::beginBraking() {
  m_brakeFromQ = m_q;
  m_brakeFromQd = m_qd;
  m_brakeDuration = 0.0;
  for (std::size_t i = 0; i < 6; ++i)
    m_brakeDuration = std::max(m_brakeDuration, std::abs(m_qd[i]) / kStopDecelerationRadPerS2);
  m_elapsed = 0.0;
  if (m_brakeDuration <= 0.0) {
    m_activity = Activity::None;
    m_qd = robot::Joints{};
    if (m_powerOffAfterBraking) {
      m_robotMode = UrRobotMode::PowerOff;
      m_powerOffAfterBraking = false;
    }
    return;
  }
  m_activity = Activity::Braking;
}

void UrController::haltProgram(UrProgramState state) {
  const bool wasActive = m_programState == UrProgramState::Playing || m_programState == UrProgramState::Paused;
  if (m_activity != Activity::Braking) beginBraking();
  if (!wasActive) return;
  m_programState = state;
  if (state == UrProgramState::Stopped) m_program.reset();
}

void UrController::fault(UrSafetyMode mode, const std::string& words, int code, int argument) {
  m_safetyMode = mode;
  m_lastFault = words;
  if (mode == UrSafetyMode::ProtectiveStop) m_protectiveStopAt = m_time;
  message(Kind::ErrorCode, words, 0, 0, code, argument);
  haltProgram(UrProgramState::Stopped);
}

void UrController::protectiveStop(const std::string& reason) {
  fault(UrSafetyMode::ProtectiveStop, "Protective stop: " + reason, kCodeProtectiveStop);
}

void UrController::pressEmergencyStop() {
  m_emergencyPressed = true;
  m_powerOffAfterBraking = m_robotMode != UrRobotMode::PowerOff;
  fault(UrSafetyMode::RobotEmergencyStop, "Emergency stop: the robot's emergency stop button is pressed",
        kCodeEmergencyStop);
}

void UrController::releaseEmergencyStop() {
  m_emergencyPressed = false;
  if (m_safetyMode == UrSafetyMode::RobotEmergencyStop) m_safetyMode = UrSafetyMode::Normal;
}

void UrController::programError(const std::string& text) {
  if (m_programState != UrProgramState::Playing && m_programState != UrProgramState::Paused) return;
  const int line = currentLine();
  m_lastFault = "Runtime error in line " + std::to_string(line) + ": " + text;
  message(Kind::RuntimeException, text, line, 1);
  haltProgram(UrProgramState::Stopped);
}

void UrController::receiveProgram(const std::string& text) {
  if (text.size() > m_maxProgramBytes) {
    // Refused before it is compiled, as a compile error on the program's first line: UR documents no bound and
    // no words for it, so these name what the controller was given and what it takes.
    const std::string words = "the program is " + std::to_string(text.size()) + " bytes, above the " +
                              std::to_string(m_maxProgramBytes) + " bytes this controller compiles";
    m_lastFault = "Compile error in line 1, column 1: " + words;
    message(Kind::RuntimeException, "Compile error: " + words, 1, 1);
    return;
  }
  ur::UrScriptParse parsed = ur::parseUrScript(text);
  if (!parsed.program) {
    m_lastFault = "Compile error in line " + std::to_string(parsed.error.line) + ", column " +
                  std::to_string(parsed.error.column) + ": " + parsed.error.message;
    message(Kind::RuntimeException, "Compile error: " + parsed.error.message, parsed.error.line, parsed.error.column);
    return;
  }
  if (m_robotMode != UrRobotMode::Running || m_safetyMode != UrSafetyMode::Normal) {
    m_lastFault = "Cannot start program " + parsed.program->name + ": robot mode " + urRobotModeName(m_robotMode) +
                  ", safety mode " + urSafetyModeName(m_safetyMode) +
                  " (a program runs in robot mode RUNNING with safety mode NORMAL)";
    message(Kind::ErrorCode, m_lastFault, 0, 0, 0, 0);
    return;
  }
  // A new program replaces the running one, as on the controller: the running one stops first.
  if (m_programState == UrProgramState::Playing || m_programState == UrProgramState::Paused)
    haltProgram(UrProgramState::Stopped);
  m_nextProgram = std::move(parsed.program);
  if (m_activity == Activity::None) {
    m_program = std::move(m_nextProgram);
    m_nextProgram.reset();
    m_programName = m_program->name;
    m_pc = 0;
    m_programState = UrProgramState::Playing;
  }
}

std::string UrController::dashboard(const std::string& commandLine, bool& quit) {
  quit = false;
  std::string command = commandLine;
  while (!command.empty() && std::isspace(static_cast<unsigned char>(command.back()))) command.pop_back();
  while (!command.empty() && std::isspace(static_cast<unsigned char>(command.front()))) command.erase(0, 1);
  const std::string c = lowered(command);
  const bool active = m_programState == UrProgramState::Playing || m_programState == UrProgramState::Paused;
  if (c == "power on") {
    if (m_emergencyPressed || m_safetyMode != UrSafetyMode::Normal) return "Failed to execute: power on";
    if (m_robotMode == UrRobotMode::PowerOff) {
      m_robotMode = UrRobotMode::PowerOn;
      m_poweredOnAt = m_time;
    }
    return "Powering on";
  }
  if (c == "power off") {
    m_powerOffAfterBraking = m_robotMode != UrRobotMode::PowerOff;
    haltProgram(UrProgramState::Stopped);
    return "Powering off";
  }
  if (c == "brake release") {
    if (m_robotMode == UrRobotMode::Idle) m_robotMode = UrRobotMode::Running;
    return "Brake releasing";
  }
  if (c == "play") {
    if (m_programState == UrProgramState::Paused && m_safetyMode == UrSafetyMode::Normal &&
        m_robotMode == UrRobotMode::Running && m_activity == Activity::None) {
      m_programState = UrProgramState::Playing;
      return "Starting program";
    }
    return "Failed to execute: play";
  }
  if (c == "stop") {
    if (!active) return "Failed to execute: stop";
    haltProgram(UrProgramState::Stopped);
    return "Stopped";
  }
  if (c == "pause") {
    if (m_programState != UrProgramState::Playing) return "Failed to execute: pause";
    haltProgram(UrProgramState::Paused);
    return "Pausing program";
  }
  if (c == "programstate")
    return std::string(urProgramStateName(m_programState)) + " " +
           (m_programName.empty() ? std::string("<unnamed>") : m_programName);
  if (c == "running") return std::string("Program running: ") + (active ? "true" : "false");
  if (c == "robotmode") return std::string("Robotmode: ") + urRobotModeName(m_robotMode);
  if (c == "safetymode") return std::string("Safetymode: ") + urSafetyModeName(m_safetyMode);
  if (c == "safetystatus") return std::string("Safetystatus: ") + urSafetyModeName(m_safetyMode);
  if (c == "unlock protective stop") {
    if (m_safetyMode == UrSafetyMode::ProtectiveStop) {
      if (m_time - m_protectiveStopAt < kProtectiveStopUnlockSeconds)
        return "Cannot unlock protective stop until 5s after occurrence. Always inspect cause of protective stop "
               "before unlocking";
      m_safetyMode = UrSafetyMode::Normal;
    }
    return "Protective stop releasing";
  }
  if (c == "close safety popup") return "closing safety popup";
  if (c == "quit") {
    quit = true;
    return "Disconnected";
  }
  return "could not understand: '" + command + "'";
}

ur::UrRealtimeState UrController::realtime() const {
  ur::UrRealtimeState s;
  s.time = m_time;
  s.qTarget = m_qTarget;
  s.qdTarget = m_qd;
  s.qActual = m_q;
  s.qdActual = m_qd;
  std::array<double, 6> tool = tcpPose(m_q);
  for (std::size_t i = 0; i < 3; ++i) tool[i] /= 1000.0;
  s.toolVectorActual = tool;
  s.toolVectorTarget = tool;
  s.robotMode = m_robotMode;
  const double jointMode = m_robotMode == UrRobotMode::Running    ? ur::kJointModeRunning
                           : m_robotMode == UrRobotMode::PowerOff ? ur::kJointModePowerOff
                                                                  : ur::kJointModeIdle;
  s.jointModes.fill(jointMode);
  s.safetyMode = m_safetyMode;
  s.digitalOutputs = static_cast<double>(m_digitalOut);
  s.programState = m_programState;
  return s;
}

}  // namespace multidir::hardware::sim

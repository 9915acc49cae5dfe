#pragma once
// UR's binary formats as MultiDir's simulator writes them and its link reads them (docs/hardware.md,
// "UR controller"): every number big-endian, as UR's Client Interface documentation specifies.
//
// Real-time interface (port 30003): one package per control tick (125 Hz on e-Series, 8 ms), 1108 bytes: an
// int32 message size, then 138 doubles in UR's order (time, q target, qd target, qdd target, I target, M target,
// q actual, qd actual, I actual, I control, tool vector actual, TCP speed actual, TCP force, tool vector target,
// TCP speed target, digital input bits, motor temperatures, controller timer, test value, robot mode, joint modes,
// safety mode, 6 reserved, tool accelerometer, 6 reserved, speed scaling, linear momentum norm, 2 reserved,
// V main, V robot, I robot, V actual, digital outputs, program state, elbow position, elbow velocity). Newer
// controllers append fields: the reader takes any package of at least 1108 bytes and reads these offsets.
//
// Primary/secondary interface (port 30002), from the controller: packages of an int32 size (the whole
// package), a uint8 type; robot messages (type 20) carry a uint64 timestamp (microseconds), an int8 source and a
// uint8 message type: 0 text, 3 version, 6 error code, 10 runtime exception.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace multidir::hardware::ur {

constexpr std::size_t kRealtimePackageBytes = 1108;

// UR's robot modes (real-time "Robot Mode", dashboard "robotmode").
enum class UrRobotMode : int {
  Disconnected = 0,
  ConfirmSafety = 1,
  Booting = 2,
  PowerOff = 3,
  PowerOn = 4,
  Idle = 5,
  Backdrive = 6,
  Running = 7
};
// UR's safety modes (real-time "Safety Mode", dashboard "safetymode").
enum class UrSafetyMode : int {
  Normal = 1,
  Reduced = 2,
  ProtectiveStop = 3,
  Recovery = 4,
  SafeguardStop = 5,
  SystemEmergencyStop = 6,
  RobotEmergencyStop = 7,
  Violation = 8,
  Fault = 9
};
// The program's state as RTDE's runtime_state numbers it (real-time "Program state").
enum class UrProgramState : int { Stopping = 0, Stopped = 1, Playing = 2, Pausing = 3, Paused = 4, Resuming = 5 };
// UR's joint modes: 253 running, 239 power off, 255 idle (brakes on, powered).
constexpr double kJointModeRunning = 253.0;
constexpr double kJointModePowerOff = 239.0;
constexpr double kJointModeIdle = 255.0;

const char* urRobotModeName(UrRobotMode mode);         // "RUNNING", as the dashboard says it
const char* urSafetyModeName(UrSafetyMode mode);       // "PROTECTIVE_STOP"
const char* urProgramStateName(UrProgramState state);  // "PLAYING" (the dashboard's word; Stopping is "STOPPED")

struct UrRealtimeState {
  double time = 0.0;  // seconds since the controller started
  std::array<double, 6> qTarget{}, qdTarget{}, qddTarget{};
  std::array<double, 6> qActual{}, qdActual{};
  std::array<double, 6> toolVectorActual{};  // TCP pose: x, y, z (m), rotation vector (rad)
  std::array<double, 6> tcpSpeedActual{};
  std::array<double, 6> toolVectorTarget{};
  std::array<double, 6> tcpSpeedTarget{};
  double digitalInputBits = 0.0;
  UrRobotMode robotMode = UrRobotMode::PowerOff;
  std::array<double, 6> jointModes{};
  UrSafetyMode safetyMode = UrSafetyMode::Normal;
  double speedScaling = 1.0;
  double digitalOutputs = 0.0;  // bit i = standard digital output i
  UrProgramState programState = UrProgramState::Stopped;
};

std::vector<std::uint8_t> encodeRealtime(const UrRealtimeState& state);
// The state in a package of at least kRealtimePackageBytes bytes whose size field says its length; nullopt
// for anything else.
std::optional<UrRealtimeState> decodeRealtime(const std::uint8_t* bytes, std::size_t size);

// A robot message (package type 20).
struct UrRobotMessage {
  enum class Kind : std::uint8_t { Text = 0, Version = 3, ErrorCode = 6, RuntimeException = 10 };
  Kind kind = Kind::Text;
  std::uint64_t timestampUs = 0;
  std::int8_t source = -2;
  std::string text;               // text, error code text, runtime exception text; version: project name
  std::int32_t line = 0;          // runtime exception: script line
  std::int32_t column = 0;        // runtime exception: script column
  std::int32_t code = 0;          // error code: UR's code (the C number)
  std::int32_t argument = 0;      // error code: its argument (A number)
  std::int32_t reportLevel = 3;   // error code: 3 violation, 4 fault
  std::uint8_t versionMajor = 5;  // version
  std::uint8_t versionMinor = 9;
};

std::vector<std::uint8_t> encodeRobotMessage(const UrRobotMessage& message);
// One package's robot message; nullopt when the package is not a robot message of these kinds (the reader
// skips it by its size).
std::optional<UrRobotMessage> decodeRobotMessage(const std::uint8_t* bytes, std::size_t size);

// The int32 size at the start of a package (0 when fewer than 4 bytes).
std::uint32_t packageSize(const std::uint8_t* bytes, std::size_t available);

}  // namespace multidir::hardware::ur

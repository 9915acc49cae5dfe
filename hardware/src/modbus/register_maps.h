#pragma once
// The register maps of docs/hardware.md, and the only place where register values are scaled.
// Holding registers (function codes 03 read, 06/16 write), 0-based protocol addresses, 16 bits each.
// 32-bit values span two registers, high word first (at the lower address), signed two's complement.
#include <cmath>
#include <cstdint>

namespace multidir::hardware::regs {

// ---- Rotary platform controller -------------------------------------------------------------------------
namespace rotary {
constexpr int kTargetAngle = 0;       // int32, 0.01 degree, RW (2 registers: 0 high word, 1 low word)
constexpr int kSpeed = 2;             // uint16, 0.01 degree/s, RW
constexpr int kCommand = 3;           // uint16, W; reads 0 once the controller has taken the command
constexpr int kHeartbeat = 4;         // uint16, RW: MultiDir writes a new value every heartbeat interval
constexpr int kHeartbeatTimeout = 5;  // uint16, ms, RW: 0 switches the watchdog off
constexpr int kSession = 6;           // uint16, W: the writer's session token, in every request but a stop's
constexpr int kClaim = 7;             // uint16, W: a session token claiming control; reads 0 once taken
constexpr int kActualAngle = 8;       // int32, 0.01 degree, R (8 high word, 9 low word)
constexpr int kStatus = 10;           // uint16 bit field, R
constexpr int kFaultCode = 11;        // uint16, R
constexpr int kHeartbeatEcho = 12;    // uint16, R: the last HEARTBEAT value the control loop saw
constexpr int kOwner = 13;            // uint16, R: the session in control, 0 when nobody is
constexpr int kFirstWritable = 0;
constexpr int kLastWritable = 7;
constexpr int kMapSize = 16;          // registers 0..15 exist; 14 and 15 are reserved and read 0
constexpr int kStatusBlockFirst = 0;  // one read of 0..13 gives everything
constexpr int kStatusBlockCount = 14;

enum Command : std::uint16_t {
  kCmdNone = 0, kCmdEnable = 1, kCmdDisable = 2, kCmdHome = 3, kCmdMove = 4, kCmdStop = 5, kCmdEStop = 6,
  kCmdClearFault = 7, kCmdRelease = 8
};
enum StatusBit : std::uint16_t {
  kEnabled = 1u << 0, kHomed = 1u << 1, kMoving = 1u << 2, kHoming = 1u << 3, kAtTarget = 1u << 4,
  kFault = 1u << 5,
};
enum FaultCode : std::uint16_t {
  kFaultNone = 0, kFaultStall = 1, kFaultHeartbeat = 2, kFaultLimitSwitch = 3, kFaultRejected = 4,
  kFaultEStop = 5,
};
}  // namespace rotary

// ---- Universal Robots arm: general-purpose registers of the robot's Modbus server ----------------------
namespace robot {
constexpr int kRequestTilt = 128;       // int16, 0.01 degree, [0, 18000], written by MultiDir
constexpr int kRequestAzimuth = 129;    // int16, 0.01 degree, [-18000, 18000], written by MultiDir
constexpr int kRequestSpeed = 130;      // uint16, percent of the program's maximal joint speed, 1..100
constexpr int kCommand = 131;           // uint16, written by MultiDir
constexpr int kSequence = 132;          // uint16, written by MultiDir: a new number (1..65535) per command
constexpr int kHostHeartbeat = 133;     // uint16, written by MultiDir every heartbeat interval
constexpr int kHeartbeatTimeout = 134;  // uint16, ms, written by MultiDir; 0 switches the watchdog off
constexpr int kSession = 135;           // uint16, written by MultiDir with every command (but stops) and heartbeat
constexpr int kClaim = 136;             // uint16, written by MultiDir to claim control; the program clears it
constexpr int kState = 144;             // uint16, written by the program
constexpr int kAckSequence = 145;       // uint16, written by the program: the SEQUENCE it took last
constexpr int kProgramHeartbeat = 146;  // uint16, written by the program every cycle
constexpr int kFaultCode = 147;         // uint16, written by the program
constexpr int kActualTilt = 148;        // int16, 0.01 degree, written by the program
constexpr int kActualAzimuth = 149;     // int16, 0.01 degree, written by the program
constexpr int kOwner = 150;             // uint16, written by the program: the session in control, 0 nobody
constexpr int kFirst = 128;             // the general-purpose range 128..255
constexpr int kCount = 128;
constexpr int kFirstHostWritable = 128;
constexpr int kLastHostWritable = 136;
constexpr int kStatusBlockFirst = 128;  // one read of 128..150 gives everything
constexpr int kStatusBlockCount = 23;

enum Command : std::uint16_t {
  kCmdNone = 0, kCmdMove = 1, kCmdStop = 2, kCmdHalt = 3, kCmdReset = 4, kCmdRelease = 5
};
enum State : std::uint16_t {
  kStateNotRunning = 0, kStateIdle = 1, kStateMoving = 2, kStateReached = 3, kStateStopped = 4, kStateHalted = 5,
  kStateFault = 6,
};
enum FaultCode : std::uint16_t { kFaultNone = 0, kFaultBeyondLimits = 1, kFaultHeartbeat = 2, kFaultUnknownCommand = 3 };
}  // namespace robot

// ---- One controller at a time (both maps) ------------------------------------------------------------------
// HEARTBEAT, HEARTBEAT_TIMEOUT, SESSION and CLAIM follow each other in both maps; every command but a stop
// writes HEARTBEAT, HEARTBEAT_TIMEOUT and SESSION right after COMMAND (rotary) or SEQUENCE (robot).
static_assert(rotary::kSession == rotary::kHeartbeat + 2 && rotary::kClaim == rotary::kHeartbeat + 3);
static_assert(robot::kSession == robot::kHostHeartbeat + 2 && robot::kClaim == robot::kHostHeartbeat + 3);
static_assert(rotary::kHeartbeat == rotary::kCommand + 1 && robot::kHostHeartbeat == robot::kSequence + 1);

// ---- Scaling ----------------------------------------------------------------------------------------------
constexpr double kDegreesPerCount = 0.01;

inline std::int32_t degreesToCounts(double degrees) {
  return static_cast<std::int32_t>(std::lround(degrees / kDegreesPerCount));
}
inline double countsToDegrees(std::int32_t counts) { return counts * kDegreesPerCount; }

// int32 across two registers, high word first.
inline void putInt32(std::int32_t value, std::uint16_t* dest) {
  const auto bits = static_cast<std::uint32_t>(value);
  dest[0] = static_cast<std::uint16_t>(bits >> 16);
  dest[1] = static_cast<std::uint16_t>(bits & 0xFFFFu);
}
inline std::int32_t getInt32(const std::uint16_t* src) {
  const std::uint32_t bits = (static_cast<std::uint32_t>(src[0]) << 16) | src[1];
  return static_cast<std::int32_t>(bits);
}
// int16 in one register, two's complement.
inline std::uint16_t fromInt16(std::int16_t value) { return static_cast<std::uint16_t>(value); }
inline std::int16_t toInt16(std::uint16_t reg) { return static_cast<std::int16_t>(reg); }

inline std::uint16_t degreesToInt16Register(double degrees) {
  return fromInt16(static_cast<std::int16_t>(degreesToCounts(degrees)));
}
inline double int16RegisterToDegrees(std::uint16_t reg) { return countsToDegrees(toInt16(reg)); }
// Speeds in 0.01 degree/s, clamped to the register's range.
inline std::uint16_t degreesPerSecondToRegister(double speed) {
  const long counts = std::lround(speed / kDegreesPerCount);
  return static_cast<std::uint16_t>(counts < 1 ? 1 : (counts > 65535 ? 65535 : counts));
}
inline double registerToDegreesPerSecond(std::uint16_t reg) { return reg * kDegreesPerCount; }

}  // namespace multidir::hardware::regs

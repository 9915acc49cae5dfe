#pragma once
// The subset of UR's RTDE protocol (Real-Time Data Exchange, port 30004; protocol version 2) that MultiDir's
// link and simulator speak (docs/hardware.md, "UR controller"): the client asks for protocol version 2, sets up
// one output recipe (its frequency and the variables' names), starts, and from then on the controller sends one
// data package per control tick (at most the recipe's frequency) with the recipe's variables in order.
//
// Every package: a uint16 size (the whole package, header included) and a uint8 type, then its payload; every
// number big-endian. Payloads: request protocol version 'V': uint16 version; its reply: uint8 accepted. Setup
// outputs 'O': double frequency (Hz), then the names joined by ','; its reply: uint8 recipe id, then the types
// joined by ',' ("NOT_FOUND" for a name the controller does not know). Start 'S' and pause 'P': nothing; their
// reply: uint8 accepted. Data package 'U': uint8 recipe id, then each variable (INT32, UINT32: 4 bytes; DOUBLE:
// 8; VECTOR6D: 6 doubles).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace multidir::hardware::ur {

enum class RtdeType : std::uint8_t {
  RequestProtocolVersion = 86,  // 'V'
  TextMessage = 77,             // 'M'
  DataPackage = 85,             // 'U'
  SetupOutputs = 79,            // 'O'
  SetupInputs = 73,             // 'I'
  Start = 83,                   // 'S'
  Pause = 80,                   // 'P'
};

constexpr std::uint16_t kRtdeProtocolVersion = 2;

struct RtdePackage {
  RtdeType type = RtdeType::DataPackage;
  std::vector<std::uint8_t> payload;
};

// One package of `type` with `payload`.
std::vector<std::uint8_t> encodeRtde(RtdeType type, const std::vector<std::uint8_t>& payload);
// The package at the start of `bytes` when it is whole; `used` its size. nullopt and used = 0 when more bytes
// are needed; nullopt and used = SIZE_MAX when the size field is below the header's 3 bytes.
std::optional<RtdePackage> decodeRtde(const std::uint8_t* bytes, std::size_t size, std::size_t& used);

// Payload writers and readers (big-endian).
void putU16(std::vector<std::uint8_t>& out, std::uint16_t value);
void putU32(std::vector<std::uint8_t>& out, std::uint32_t value);
void putDouble(std::vector<std::uint8_t>& out, double value);
std::uint32_t getU32(const std::uint8_t* bytes);
double getDouble(const std::uint8_t* bytes);

// The RTDE type name of an output variable the simulator serves: "timestamp" DOUBLE, "actual_TCP_pose" VECTOR6D,
// "runtime_state" UINT32, "output_int_register_N" (N 0..47) INT32; "NOT_FOUND" for anything else.
std::string rtdeOutputType(const std::string& name);
// Bytes of one value of an RTDE type (0 for an unknown one).
std::size_t rtdeTypeBytes(const std::string& type);

}  // namespace multidir::hardware::ur

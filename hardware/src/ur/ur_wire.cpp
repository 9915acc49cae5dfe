#include "ur/ur_wire.h"

#include <cstring>

namespace multidir::hardware::ur {
namespace {

// The doubles' positions after the size field (UR's Client Interface, real-time package).
constexpr int kTime = 0, kQTarget = 1, kQdTarget = 7, kQddTarget = 13, kQActual = 31, kQdActual = 37,
              kToolVectorActual = 55, kTcpSpeedActual = 61, kToolVectorTarget = 73, kTcpSpeedTarget = 79,
              kDigitalInputs = 85, kControllerTimer = 92, kRobotMode = 94, kJointModes = 95, kSafetyMode = 101,
              kSpeedScaling = 117, kDigitalOutputs = 130, kProgramState = 131, kDoubles = 138;
static_assert(4 + 8 * kDoubles == kRealtimePackageBytes, "the real-time package is 1108 bytes");

void putU32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}
void putU64(std::vector<std::uint8_t>& out, std::uint64_t value) {
  for (int shift = 56; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}
std::uint32_t getU32(const std::uint8_t* at) {
  return (std::uint32_t{at[0]} << 24) | (std::uint32_t{at[1]} << 16) | (std::uint32_t{at[2]} << 8) | at[3];
}
std::uint64_t getU64(const std::uint8_t* at) {
  std::uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value = (value << 8) | at[i];
  return value;
}
void putDouble(std::uint8_t* at, double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int i = 0; i < 8; ++i) at[i] = static_cast<std::uint8_t>(bits >> (56 - 8 * i));
}
double getDouble(const std::uint8_t* at) {
  const std::uint64_t bits = getU64(at);
  double value = 0.0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace

const char* urRobotModeName(UrRobotMode mode) {
  switch (mode) {
    case UrRobotMode::Disconnected:
      return "DISCONNECTED";
    case UrRobotMode::ConfirmSafety:
      return "CONFIRM_SAFETY";
    case UrRobotMode::Booting:
      return "BOOTING";
    case UrRobotMode::PowerOff:
      return "POWER_OFF";
    case UrRobotMode::PowerOn:
      return "POWER_ON";
    case UrRobotMode::Idle:
      return "IDLE";
    case UrRobotMode::Backdrive:
      return "BACKDRIVE";
    case UrRobotMode::Running:
      return "RUNNING";
  }
  return "UNKNOWN";
}

const char* urSafetyModeName(UrSafetyMode mode) {
  switch (mode) {
    case UrSafetyMode::Normal:
      return "NORMAL";
    case UrSafetyMode::Reduced:
      return "REDUCED";
    case UrSafetyMode::ProtectiveStop:
      return "PROTECTIVE_STOP";
    case UrSafetyMode::Recovery:
      return "RECOVERY";
    case UrSafetyMode::SafeguardStop:
      return "SAFEGUARD_STOP";
    case UrSafetyMode::SystemEmergencyStop:
      return "SYSTEM_EMERGENCY_STOP";
    case UrSafetyMode::RobotEmergencyStop:
      return "ROBOT_EMERGENCY_STOP";
    case UrSafetyMode::Violation:
      return "VIOLATION";
    case UrSafetyMode::Fault:
      return "FAULT";
  }
  return "UNDEFINED_SAFETY_MODE";
}

const char* urProgramStateName(UrProgramState state) {
  switch (state) {
    case UrProgramState::Playing:
    case UrProgramState::Resuming:
      return "PLAYING";
    case UrProgramState::Pausing:
    case UrProgramState::Paused:
      return "PAUSED";
    case UrProgramState::Stopping:
    case UrProgramState::Stopped:
      return "STOPPED";
  }
  return "STOPPED";
}

std::uint32_t packageSize(const std::uint8_t* bytes, std::size_t available) {
  return available < 4 ? 0 : getU32(bytes);
}

std::vector<std::uint8_t> encodeRealtime(const UrRealtimeState& s) {
  std::vector<std::uint8_t> out;
  out.reserve(kRealtimePackageBytes);
  putU32(out, static_cast<std::uint32_t>(kRealtimePackageBytes));
  out.resize(kRealtimePackageBytes, 0);
  std::uint8_t* doubles = out.data() + 4;
  const auto put = [&](int index, double value) { putDouble(doubles + 8 * index, value); };
  const auto put6 = [&](int index, const std::array<double, 6>& values) {
    for (int i = 0; i < 6; ++i) put(index + i, values[static_cast<std::size_t>(i)]);
  };
  put(kTime, s.time);
  put6(kQTarget, s.qTarget);
  put6(kQdTarget, s.qdTarget);
  put6(kQddTarget, s.qddTarget);
  put6(kQActual, s.qActual);
  put6(kQdActual, s.qdActual);
  put6(kToolVectorActual, s.toolVectorActual);
  put6(kTcpSpeedActual, s.tcpSpeedActual);
  put6(kToolVectorTarget, s.toolVectorTarget);
  put6(kTcpSpeedTarget, s.tcpSpeedTarget);
  put(kDigitalInputs, s.digitalInputBits);
  put(kControllerTimer, s.time);
  put(kRobotMode, static_cast<double>(static_cast<int>(s.robotMode)));
  put6(kJointModes, s.jointModes);
  put(kSafetyMode, static_cast<double>(static_cast<int>(s.safetyMode)));
  put(kSpeedScaling, s.speedScaling);
  put(kDigitalOutputs, s.digitalOutputs);
  put(kProgramState, static_cast<double>(static_cast<int>(s.programState)));
  return out;
}

std::optional<UrRealtimeState> decodeRealtime(const std::uint8_t* bytes, std::size_t size) {
  if (size < kRealtimePackageBytes || packageSize(bytes, size) != size) return std::nullopt;
  const std::uint8_t* doubles = bytes + 4;
  const auto get = [&](int index) { return getDouble(doubles + 8 * index); };
  const auto get6 = [&](int index) {
    std::array<double, 6> values{};
    for (int i = 0; i < 6; ++i) values[static_cast<std::size_t>(i)] = get(index + i);
    return values;
  };
  UrRealtimeState s;
  s.time = get(kTime);
  s.qTarget = get6(kQTarget);
  s.qdTarget = get6(kQdTarget);
  s.qddTarget = get6(kQddTarget);
  s.qActual = get6(kQActual);
  s.qdActual = get6(kQdActual);
  s.toolVectorActual = get6(kToolVectorActual);
  s.tcpSpeedActual = get6(kTcpSpeedActual);
  s.toolVectorTarget = get6(kToolVectorTarget);
  s.tcpSpeedTarget = get6(kTcpSpeedTarget);
  s.digitalInputBits = get(kDigitalInputs);
  s.robotMode = static_cast<UrRobotMode>(static_cast<int>(get(kRobotMode)));
  s.jointModes = get6(kJointModes);
  s.safetyMode = static_cast<UrSafetyMode>(static_cast<int>(get(kSafetyMode)));
  s.speedScaling = get(kSpeedScaling);
  s.digitalOutputs = get(kDigitalOutputs);
  s.programState = static_cast<UrProgramState>(static_cast<int>(get(kProgramState)));
  return s;
}

std::vector<std::uint8_t> encodeRobotMessage(const UrRobotMessage& m) {
  std::vector<std::uint8_t> out;
  putU32(out, 0);  // the size, filled in below
  out.push_back(20);
  putU64(out, m.timestampUs);
  out.push_back(static_cast<std::uint8_t>(m.source));
  out.push_back(static_cast<std::uint8_t>(m.kind));
  switch (m.kind) {
    case UrRobotMessage::Kind::Text:
      break;
    case UrRobotMessage::Kind::Version:
      out.push_back(static_cast<std::uint8_t>(m.text.size()));
      out.insert(out.end(), m.text.begin(), m.text.end());
      out.push_back(m.versionMajor);
      out.push_back(m.versionMinor);
      putU32(out, 0);  // bugfix
      putU32(out, 0);  // build
      break;
    case UrRobotMessage::Kind::ErrorCode:
      putU32(out, static_cast<std::uint32_t>(m.code));
      putU32(out, static_cast<std::uint32_t>(m.argument));
      putU32(out, static_cast<std::uint32_t>(m.reportLevel));
      out.push_back(0);  // data type: none
      putU32(out, 0);    // data
      break;
    case UrRobotMessage::Kind::RuntimeException:
      putU32(out, static_cast<std::uint32_t>(m.line));
      putU32(out, static_cast<std::uint32_t>(m.column));
      break;
  }
  // The version message's remainder is its build date; every other kind's is its text.
  const std::string tail = m.kind == UrRobotMessage::Kind::Version ? std::string("simulated") : m.text;
  out.insert(out.end(), tail.begin(), tail.end());
  const std::uint32_t size = static_cast<std::uint32_t>(out.size());
  for (int i = 0; i < 4; ++i) out[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(size >> (24 - 8 * i));
  return out;
}

std::optional<UrRobotMessage> decodeRobotMessage(const std::uint8_t* bytes, std::size_t size) {
  constexpr std::size_t kHeader = 4 + 1 + 8 + 1 + 1;
  if (size < kHeader || packageSize(bytes, size) != size || bytes[4] != 20) return std::nullopt;
  UrRobotMessage m;
  m.timestampUs = getU64(bytes + 5);
  m.source = static_cast<std::int8_t>(bytes[13]);
  const std::uint8_t kind = bytes[14];
  const std::uint8_t* at = bytes + kHeader;
  const std::uint8_t* end = bytes + size;
  const auto remainder = [&](const std::uint8_t* from) { return std::string(from, end); };
  switch (kind) {
    case 0:
      m.kind = UrRobotMessage::Kind::Text;
      m.text = remainder(at);
      return m;
    case 3: {
      m.kind = UrRobotMessage::Kind::Version;
      if (end - at < 1) return std::nullopt;
      const std::size_t length = at[0];
      if (static_cast<std::size_t>(end - at) < 1 + length + 2) return std::nullopt;
      m.text = std::string(at + 1, at + 1 + length);
      m.versionMajor = at[1 + length];
      m.versionMinor = at[2 + length];
      return m;
    }
    case 6:
      m.kind = UrRobotMessage::Kind::ErrorCode;
      if (end - at < 17) return std::nullopt;
      m.code = static_cast<std::int32_t>(getU32(at));
      m.argument = static_cast<std::int32_t>(getU32(at + 4));
      m.reportLevel = static_cast<std::int32_t>(getU32(at + 8));
      m.text = remainder(at + 17);
      return m;
    case 10:
      m.kind = UrRobotMessage::Kind::RuntimeException;
      if (end - at < 8) return std::nullopt;
      m.line = static_cast<std::int32_t>(getU32(at));
      m.column = static_cast<std::int32_t>(getU32(at + 4));
      m.text = remainder(at + 8);
      return m;
    default:
      return std::nullopt;
  }
}

}  // namespace multidir::hardware::ur

#include "ur/rtde_wire.h"

#include <cstring>
#include <limits>

namespace multidir::hardware::ur {

void putU16(std::vector<std::uint8_t>& out, std::uint16_t value) {
  out.push_back(static_cast<std::uint8_t>(value >> 8));
  out.push_back(static_cast<std::uint8_t>(value));
}

void putU32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

void putDouble(std::vector<std::uint8_t>& out, double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int shift = 56; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(bits >> shift));
}

std::uint32_t getU32(const std::uint8_t* bytes) {
  return (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) | (std::uint32_t{bytes[2]} << 8) |
         std::uint32_t{bytes[3]};
}

double getDouble(const std::uint8_t* bytes) {
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits = (bits << 8) | bytes[i];
  double value = 0.0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

std::vector<std::uint8_t> encodeRtde(RtdeType type, const std::vector<std::uint8_t>& payload) {
  std::vector<std::uint8_t> out;
  out.reserve(payload.size() + 3);
  putU16(out, static_cast<std::uint16_t>(payload.size() + 3));
  out.push_back(static_cast<std::uint8_t>(type));
  out.insert(out.end(), payload.begin(), payload.end());
  return out;
}

std::optional<RtdePackage> decodeRtde(const std::uint8_t* bytes, std::size_t size, std::size_t& used) {
  used = 0;
  if (size < 3) return std::nullopt;
  const std::size_t length = (std::size_t{bytes[0]} << 8) | bytes[1];
  if (length < 3) {
    used = std::numeric_limits<std::size_t>::max();
    return std::nullopt;
  }
  if (size < length) return std::nullopt;
  used = length;
  RtdePackage package;
  package.type = static_cast<RtdeType>(bytes[2]);
  package.payload.assign(bytes + 3, bytes + length);
  return package;
}

std::string rtdeOutputType(const std::string& name) {
  if (name == "timestamp") return "DOUBLE";
  if (name == "actual_TCP_pose") return "VECTOR6D";
  if (name == "runtime_state") return "UINT32";
  const std::string prefix = "output_int_register_";
  if (name.rfind(prefix, 0) == 0 && name.size() > prefix.size() && name.size() <= prefix.size() + 2) {
    int index = 0;
    for (std::size_t i = prefix.size(); i < name.size(); ++i) {
      if (name[i] < '0' || name[i] > '9') return "NOT_FOUND";
      index = index * 10 + (name[i] - '0');
    }
    if (index <= 47 && !(name.size() == prefix.size() + 2 && name[prefix.size()] == '0')) return "INT32";
  }
  return "NOT_FOUND";
}

std::size_t rtdeTypeBytes(const std::string& type) {
  if (type == "INT32" || type == "UINT32") return 4;
  if (type == "DOUBLE") return 8;
  if (type == "VECTOR6D") return 48;
  return 0;
}

}  // namespace multidir::hardware::ur

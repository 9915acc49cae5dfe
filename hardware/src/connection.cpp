#include "multidir/hardware/connection.h"

#include <arpa/inet.h>

namespace multidir::hardware {
namespace {

core::Error bad(const std::string& field, const std::string& rule) {
  return core::Error{core::ErrorCode::InvalidParameter, field + " " + rule, field};
}

bool inRange(std::chrono::milliseconds value, long long low, long long high) {
  return value.count() >= low && value.count() <= high;
}

}  // namespace

core::Status validate(const ConnectionSettings& s) {
  if (s.transport == Transport::Tcp) {
    in_addr parsed{};
    if (inet_pton(AF_INET, s.tcp.host.c_str(), &parsed) != 1)
      return bad("host", "'" + s.tcp.host + "' is not an IPv4 address (such as 192.168.0.10)");
    if (s.tcp.port < 1 || s.tcp.port > 65535) return bad("port", "must be between 1 and 65535");
    if (s.slaveId < 0 || s.slaveId > 255) return bad("unit id", "must be between 0 and 255");
  } else {
    if (s.rtu.device.empty()) return bad("serial device", "must name a device such as /dev/ttyUSB0");
    if (s.rtu.baud < 300 || s.rtu.baud > 4000000) return bad("baud rate", "must be between 300 and 4000000");
    if (s.rtu.dataBits < 5 || s.rtu.dataBits > 8) return bad("data bits", "must be between 5 and 8");
    if (s.rtu.stopBits != 1 && s.rtu.stopBits != 2) return bad("stop bits", "must be 1 or 2");
    if (s.slaveId < 1 || s.slaveId > 247) return bad("slave id", "must be between 1 and 247");
  }
  if (!inRange(s.responseTimeout, 1, 60000)) return bad("response timeout", "must be between 1 and 60000 ms");
  if (!inRange(s.byteTimeout, 1, 60000)) return bad("byte timeout", "must be between 1 and 60000 ms");
  if (!inRange(s.pollInterval, 1, 60000)) return bad("poll interval", "must be between 1 and 60000 ms");
  if (!inRange(s.heartbeatInterval, 1, 60000)) return bad("heartbeat interval", "must be between 1 and 60000 ms");
  if (!inRange(s.reconnectInitialDelay, 1, 600000))
    return bad("reconnect delay", "must be between 1 and 600000 ms");
  if (s.reconnectMaxDelay < s.reconnectInitialDelay || s.reconnectMaxDelay.count() > 600000)
    return bad("maximal reconnect delay", "must be at least the first reconnect delay and at most 600000 ms");
  return core::Done{};
}

std::string describe(const ConnectionSettings& s) {
  if (s.transport == Transport::Tcp)
    return s.tcp.host + ":" + std::to_string(s.tcp.port) + " (unit " + std::to_string(s.slaveId) + ")";
  const char parity = s.rtu.parity == Parity::None ? 'N' : (s.rtu.parity == Parity::Even ? 'E' : 'O');
  return s.rtu.device + " at " + std::to_string(s.rtu.baud) + " baud " + std::to_string(s.rtu.dataBits) + parity +
         std::to_string(s.rtu.stopBits) + " (slave " + std::to_string(s.slaveId) + ")";
}

const char* linkStateName(LinkState state) {
  switch (state) {
    case LinkState::Disconnected: return "disconnected";
    case LinkState::Connecting: return "connecting";
    case LinkState::Connected: return "connected";
    case LinkState::Reconnecting: return "reconnecting";
  }
  return "?";
}

}  // namespace multidir::hardware

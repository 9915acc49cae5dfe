#pragma once
// How MultiDir reaches a Modbus device: serial RTU (RS-485 or a USB adapter) or TCP, with the timeouts and
// the cadence of the link's worker thread. Plain values: no libmodbus type appears here.
#include <chrono>
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::hardware {

enum class Transport { Tcp, Rtu };
enum class Parity { None, Even, Odd };

struct TcpSettings {
  std::string host = "127.0.0.1";  // an IPv4 address
  int port = 502;                  // 1..65535
};

struct RtuSettings {
  std::string device = "/dev/ttyUSB0";
  int baud = 115200;
  Parity parity = Parity::None;
  int dataBits = 8;  // 5..8
  int stopBits = 1;  // 1 or 2
};

struct ConnectionSettings {
  Transport transport = Transport::Tcp;
  TcpSettings tcp;
  RtuSettings rtu;
  int slaveId = 1;  // RTU slave address 1..247; TCP unit id 0..255 (255 when the device ignores it)

  // libmodbus timeouts: how long to wait for the first byte of a reply (and for a TCP connect), and between
  // two bytes of one reply.
  std::chrono::milliseconds responseTimeout{500};
  std::chrono::milliseconds byteTimeout{100};

  // The worker thread reads the status every pollInterval and writes the heartbeat every heartbeatInterval.
  std::chrono::milliseconds pollInterval{50};
  std::chrono::milliseconds heartbeatInterval{200};

  // After a lost link the worker retries after reconnectInitialDelay, doubling up to reconnectMaxDelay.
  std::chrono::milliseconds reconnectInitialDelay{100};
  std::chrono::milliseconds reconnectMaxDelay{5000};
};

// Names the first setting out of its range (InvalidParameter) with the range it must lie in.
core::Status validate(const ConnectionSettings& settings);

// "127.0.0.1:1502 (unit 1)" or "/dev/ttyUSB0 at 115200 baud 8N1 (slave 1)", for messages.
std::string describe(const ConnectionSettings& settings);

// The state of a driver's link, as its status snapshots report it.
//  Disconnected --connect()--> Connecting --ok--> Connected --failure--> Reconnecting --ok--> Connected
//  any --disconnect()--> Disconnected; Connecting --failure--> Reconnecting (the worker keeps trying).
enum class LinkState { Disconnected, Connecting, Connected, Reconnecting };

// "disconnected", "connecting", "connected", "reconnecting".
const char* linkStateName(LinkState state);

}  // namespace multidir::hardware

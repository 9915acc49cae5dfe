#pragma once
// One libmodbus context (RTU or TCP) with errors turned into messages a technician can act on. Not
// thread-safe, like the context it owns: only the link worker's thread touches it.
#include <cstdint>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/connection.h"

typedef struct _modbus modbus_t;

namespace multidir::hardware {

// Why the last operation failed, which decides whether the link must be rebuilt.
enum class PortFailure {
  None,
  ConnectFailed,   // could not open the serial device or connect the socket
  Timeout,         // no (complete) reply in time: the stream may hold a late reply, so the link is rebuilt
  ConnectionLost,  // the peer closed the connection or the socket failed
  BadReply,        // a reply that does not fit the request (CRC, transaction id, length)
  Exception,       // the device answered with a Modbus exception: the link itself is fine
  ControlLost,     // the driver's own reason (another run took control of the device): rebuilt to claim again
};

class ModbusPort {
 public:
  ModbusPort(ConnectionSettings settings, std::string deviceLabel);
  ~ModbusPort();
  ModbusPort(const ModbusPort&) = delete;
  ModbusPort& operator=(const ModbusPort&) = delete;

  core::Status open();
  void close();
  [[nodiscard]] bool isOpen() const { return m_open; }

  // `what` names the data for messages ("the status (registers 0-12)").
  core::Status readRegisters(int address, int count, std::uint16_t* dest, const std::string& what);
  core::Status writeRegisters(int address, const std::vector<std::uint16_t>& values, const std::string& what);

  // Has the worker rebuild the link for a reason the device's answers gave the driver (ControlLost);
  // returns `why`.
  core::Status abandon(core::Error why);

  [[nodiscard]] PortFailure lastFailure() const { return m_lastFailure; }
  // The Modbus exception code of the last failure when it was PortFailure::Exception, else 0.
  [[nodiscard]] int lastExceptionCode() const { return m_lastException; }
  // A failure after which the link must be closed and reopened.
  [[nodiscard]] bool lastFailureBreaksLink() const;

 private:
  core::Status failure(int errnum, const std::string& action);

  ConnectionSettings m_settings;
  std::string m_label;
  modbus_t* m_context = nullptr;
  bool m_open = false;
  PortFailure m_lastFailure = PortFailure::None;
  int m_lastException = 0;
};

}  // namespace multidir::hardware

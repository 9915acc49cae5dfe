#include "modbus/modbus_port.h"

#include <modbus.h>

#include <cerrno>
#include <cstdint>
#include <utility>

namespace multidir::hardware {
namespace {

void splitMilliseconds(std::chrono::milliseconds ms, std::uint32_t& sec, std::uint32_t& usec) {
  sec = static_cast<std::uint32_t>(ms.count() / 1000);
  usec = static_cast<std::uint32_t>((ms.count() % 1000) * 1000);
}

std::string exceptionAdvice(int code) {
  switch (code) {
    case MODBUS_EXCEPTION_ILLEGAL_FUNCTION:
      return "the device does not support this function, or not in its present state (another MultiDir run "
             "controls it: see its OWNER register): check that it is the device docs/hardware.md describes and "
             "that no other run uses it";
    case MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS:
      return "the device has no such register: its register map does not match docs/hardware.md (check the "
             "firmware version, or the unit id if several devices share the bus)";
    case MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE:
      return "the device refused the value: check the limits configured on the device";
    case MODBUS_EXCEPTION_SLAVE_OR_SERVER_FAILURE:
      return "the device reported an internal failure: look at its display or fault LED and power-cycle it";
    case MODBUS_EXCEPTION_SLAVE_OR_SERVER_BUSY:
      return "the device is busy: retry in a moment";
    case MODBUS_EXCEPTION_GATEWAY_PATH:
    case MODBUS_EXCEPTION_GATEWAY_TARGET:
      return "the gateway could not reach the device: check the unit id and the wiring behind the gateway";
    default:
      return "see the device's manual for this exception code";
  }
}

}  // namespace

ModbusPort::ModbusPort(ConnectionSettings settings, std::string deviceLabel)
    : m_settings(std::move(settings)), m_label(std::move(deviceLabel)) {}

ModbusPort::~ModbusPort() { close(); }

core::Status ModbusPort::open() {
  close();
  if (m_settings.transport == Transport::Tcp) {
    m_context = modbus_new_tcp(m_settings.tcp.host.c_str(), m_settings.tcp.port);
  } else {
    const char parity = m_settings.rtu.parity == Parity::None ? 'N' : (m_settings.rtu.parity == Parity::Even ? 'E' : 'O');
    m_context = modbus_new_rtu(m_settings.rtu.device.c_str(), m_settings.rtu.baud, parity, m_settings.rtu.dataBits,
                               m_settings.rtu.stopBits);
  }
  if (m_context == nullptr) {
    m_lastFailure = PortFailure::ConnectFailed;
    return core::Error{core::ErrorCode::InvalidParameter,
                       "cannot set up the link to " + m_label + ": " + modbus_strerror(errno) +
                           ": check the connection settings",
                       m_label};
  }
  std::uint32_t sec = 0;
  std::uint32_t usec = 0;
  splitMilliseconds(m_settings.responseTimeout, sec, usec);
  modbus_set_response_timeout(m_context, sec, usec);
  splitMilliseconds(m_settings.byteTimeout, sec, usec);
  modbus_set_byte_timeout(m_context, sec, usec);
  // The worker decides about reconnecting; libmodbus's own recovery would sleep and retry inside a call.
  modbus_set_error_recovery(m_context, MODBUS_ERROR_RECOVERY_NONE);
  modbus_set_slave(m_context, m_settings.slaveId);
  if (modbus_connect(m_context) != 0) {
    const int errnum = errno;
    modbus_free(m_context);
    m_context = nullptr;
    m_lastFailure = PortFailure::ConnectFailed;
    std::string advice =
        m_settings.transport == Transport::Tcp
            ? "check that the device is powered and on the network, its address and port, and that no other "
              "program holds its only connection"
            : "check that the USB/RS-485 adapter is plugged in, the device name, and that you may open it (group "
              "dialout)";
    return core::Error{core::ErrorCode::DeviceUnreachable,
                       "cannot connect to " + m_label + ": " + modbus_strerror(errnum) + ": " + advice, m_label};
  }
  m_open = true;
  m_lastFailure = PortFailure::None;
  return core::Done{};
}

void ModbusPort::close() {
  if (m_context != nullptr) {
    modbus_close(m_context);
    modbus_free(m_context);
    m_context = nullptr;
  }
  m_open = false;
}

bool ModbusPort::lastFailureBreaksLink() const {
  return m_lastFailure == PortFailure::Timeout || m_lastFailure == PortFailure::ConnectionLost ||
         m_lastFailure == PortFailure::BadReply || m_lastFailure == PortFailure::ConnectFailed ||
         m_lastFailure == PortFailure::ControlLost;
}

core::Status ModbusPort::abandon(core::Error why) {
  m_lastFailure = PortFailure::ControlLost;
  return why;
}

core::Status ModbusPort::failure(int errnum, const std::string& action) {
  const long long timeoutMs = static_cast<long long>(m_settings.responseTimeout.count());
  std::string message;
  m_lastException = 0;
  if (errnum == ETIMEDOUT || errnum == EAGAIN) {
    m_lastFailure = PortFailure::Timeout;
    message = m_label + " did not answer within " + std::to_string(timeoutMs) + " ms while " + action +
              ": check the cable and power, and that the controller's Modbus id is " +
              std::to_string(m_settings.slaveId);
  } else if (errnum >= EMBXILFUN && errnum <= EMBXGTAR) {
    m_lastFailure = PortFailure::Exception;
    const int code = errnum - MODBUS_ENOBASE;
    m_lastException = code;
    message = m_label + " answered " + action + " with Modbus exception " + std::to_string(code) + " (" +
              modbus_strerror(errnum) + "): " + exceptionAdvice(code);
  } else if (errnum == EMBBADCRC || errnum == EMBBADDATA || errnum == EMBBADEXC || errnum == EMBUNKEXC ||
             errnum == EMBMDATA || errnum == EMBBADSLAVE) {
    m_lastFailure = PortFailure::BadReply;
    message = m_label + " sent a malformed reply while " + action + " (" + modbus_strerror(errnum) +
              "): check for electrical noise, a second master on the bus, or a wrong unit id";
  } else {
    m_lastFailure = PortFailure::ConnectionLost;
    message = "the connection to " + m_label + " was lost while " + action + " (" + modbus_strerror(errnum) +
              "): MultiDir reconnects on its own; if this repeats, check the cable or network";
  }
  const core::ErrorCode code =
      m_lastFailure == PortFailure::Exception ? core::ErrorCode::DeviceFault : core::ErrorCode::DeviceUnreachable;
  return core::Error{code, message, m_label};
}

core::Status ModbusPort::readRegisters(int address, int count, std::uint16_t* dest, const std::string& what) {
  if (!m_open) {
    m_lastFailure = PortFailure::ConnectionLost;
    return core::Error{core::ErrorCode::DeviceUnreachable, m_label + " is not connected", m_label};
  }
  const int rc = modbus_read_registers(m_context, address, count, dest);
  if (rc == count) {
    m_lastFailure = PortFailure::None;
    return core::Done{};
  }
  if (rc >= 0) return failure(EMBMDATA, "reading " + what);
  return failure(errno, "reading " + what);
}

core::Status ModbusPort::writeRegisters(int address, const std::vector<std::uint16_t>& values, const std::string& what) {
  if (!m_open) {
    m_lastFailure = PortFailure::ConnectionLost;
    return core::Error{core::ErrorCode::DeviceUnreachable, m_label + " is not connected", m_label};
  }
  const int count = static_cast<int>(values.size());
  const int rc = count == 1 ? modbus_write_register(m_context, address, values[0])
                            : modbus_write_registers(m_context, address, count, values.data());
  if (rc == count) {
    m_lastFailure = PortFailure::None;
    return core::Done{};
  }
  if (rc >= 0) return failure(EMBMDATA, "writing " + what);
  return failure(errno, "writing " + what);
}

}  // namespace multidir::hardware

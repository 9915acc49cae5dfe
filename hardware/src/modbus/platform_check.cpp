#include "multidir/hardware/platform_check.h"

#include <cctype>
#include <cstdint>
#include <string>

#include "modbus/modbus_port.h"
#include "modbus/register_maps.h"

namespace multidir::hardware {

namespace {

struct BlockRead {
  core::Status status = core::Done{};
  PortFailure failure = PortFailure::None;
};

// One read of a status block at `unit`, on a connection of its own that is closed again at once.
BlockRead readBlock(ConnectionSettings connection, int unit, int first, int count, const std::string& label,
                    const std::string& what) {
  connection.slaveId = unit;
  ModbusPort port(connection, label);
  BlockRead read;
  read.status = port.open();
  if (read.status.ok()) {
    std::uint16_t registers[32] = {};
    read.status = port.readRegisters(first, count, registers, what);
  }
  read.failure = port.lastFailure();
  port.close();
  return read;
}

// "Modbus exception 2, illegal data address" out of a ModbusPort failure message ("... with Modbus exception 2
// (Illegal data address): ..."), or the whole message.
std::string exceptionOf(const std::string& message) {
  const std::size_t at = message.find("Modbus exception");
  const std::size_t open = message.find(" (", at);
  const std::size_t close = message.find(')', at);
  if (at == std::string::npos || open == std::string::npos || close == std::string::npos || close < open)
    return message;
  std::string meaning = message.substr(open + 2, close - open - 2);
  if (!meaning.empty()) meaning[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(meaning[0])));
  return message.substr(at, open - at) + ", " + meaning;
}

std::string blockText(int first, int count, int unit) {
  return "registers " + std::to_string(first) + "-" + std::to_string(first + count - 1) + " at unit " +
         std::to_string(unit);
}
std::string rotaryBlock(int unit) {
  return blockText(regs::rotary::kStatusBlockFirst, regs::rotary::kStatusBlockCount, unit);
}
std::string robotBlock(int unit) {
  return blockText(regs::robot::kStatusBlockFirst, regs::robot::kStatusBlockCount, unit);
}

}  // namespace

core::Status checkPlatformFor(core::MachineKind kind, ConnectionSettings connection, int rotaryUnitId,
                              int robotUnitId) {
  const bool wantsRotary = kind == core::MachineKind::RotaryPlatform;
  if (!wantsRotary && kind != core::MachineKind::TiltRotate) return core::Done{};
  namespace rr = regs::rotary;
  namespace rb = regs::robot;
  const std::string address = connection.transport == Transport::Tcp
                                  ? connection.tcp.host + ":" + std::to_string(connection.tcp.port)
                                  : connection.rtu.device;
  const BlockRead wanted =
      wantsRotary ? readBlock(connection, rotaryUnitId, rr::kStatusBlockFirst, rr::kStatusBlockCount,
                              "rotary platform at " + address, "the status (" + rotaryBlock(rotaryUnitId) + ")")
                  : readBlock(connection, robotUnitId, rb::kStatusBlockFirst, rb::kStatusBlockCount,
                              "robot arm at " + address, "the program's status (" + robotBlock(robotUnitId) + ")");
  if (wanted.status.ok() || wanted.failure != PortFailure::Exception) return core::Done{};
  const BlockRead other = wantsRotary ? readBlock(connection, robotUnitId, rb::kStatusBlockFirst, rb::kStatusBlockCount,
                                                  "robot arm at " + address, "the program's status")
                                      : readBlock(connection, rotaryUnitId, rr::kStatusBlockFirst,
                                                  rr::kStatusBlockCount, "rotary platform at " + address, "the status");
  if (!other.status.ok()) return core::Done{};
  const std::string needs = wantsRotary ? "a 4-DOF rotary platform" : "a 5-DOF robot arm";
  const std::string answers = wantsRotary
                                  ? "a robot arm: the rotary controller's " + rotaryBlock(rotaryUnitId) +
                                        " are refused (" + exceptionOf(wanted.status.error().message) +
                                        ") and the robot program's " + robotBlock(robotUnitId) + " read"
                                  : "a rotary platform controller: the robot program's " + robotBlock(robotUnitId) +
                                        " are refused (" + exceptionOf(wanted.status.error().message) +
                                        ") and the rotary controller's " + rotaryBlock(rotaryUnitId) + " read";
  const std::string todo =
      wantsRotary
          ? "connect the rotary platform's controller and run the job against its address, or print a job made for the "
            "robot arm (multidir decompose --machine 5dof, then export and slice it)"
          : "connect the robot arm and run the job against its Modbus server (port 502 on the robot), or "
            "print a job made for the rotary platform (multidir decompose --machine 4dof, then export and "
            "slice it)";
  return core::Error{core::ErrorCode::InvalidParameter,
                     "this job needs " + needs + ", but the device at " + address + " answers as " + answers +
                         "; nothing was written to it: " + todo,
                     "platform check"};
}

}  // namespace multidir::hardware

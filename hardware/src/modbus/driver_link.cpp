#include "modbus/driver_link.h"

namespace multidir::hardware {

std::future<core::Status> readyFuture(core::Status status) {
  std::promise<core::Status> promise;
  promise.set_value(std::move(status));
  return promise.get_future();
}

core::Status validateLinkAndProfile(const ConnectionSettings& connection, const core::MachineSpec& machine) {
  if (auto valid = validate(connection); !valid.ok()) return valid;
  return core::validate(machine);
}

core::Status validateHeartbeatTimeout(std::chrono::milliseconds timeout) {
  if (timeout.count() < 0 || timeout.count() > 65535)
    return core::Error{core::ErrorCode::InvalidParameter, "heartbeat timeout must be between 0 and 65535 ms",
                       "heartbeat timeout"};
  return core::Done{};
}

core::Error controlledByAnotherRun(const std::string& label, std::uint16_t owner) {
  return core::Error{core::ErrorCode::DeviceFault,
                     label + " is controlled by another run (" + controlSessionText(owner) +
                         "); stop that run first (a run that died without giving it back frees it a few seconds "
                         "after its last heartbeat)",
                     label};
}

}  // namespace multidir::hardware

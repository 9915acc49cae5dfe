#pragma once
// A stop or e-stop the operator asked for, held by the driver until the operator clears it. A stop that
// cannot be written at once (the link is down or reconnecting) is not dropped: the driver writes it as soon
// as it can, and again first thing after every reconnect (before the heartbeat, the status read or any
// queued command), and refuses every move until the operator clears it with clearStop(). Clearing is refused
// until the device has confirmed the stop, so a stop can never be cleared before it took effect.
#include <cstdint>
#include <string>

namespace multidir::hardware {

enum class StopKind {
  None,           // no stop latched: moves are accepted
  Stop,           // decelerate and hold
  EmergencyStop,  // the device's e-stop (rotary: cut the power stage; robot: halt); never downgraded to Stop
};

// "none", "stop", "emergency stop".
const char* stopKindName(StopKind kind);

struct StopLatch {
  StopKind kind = StopKind::None;
  // The device acknowledged the latest stop request (its Modbus write was answered). False while the stop
  // waits for the link; the driver keeps trying.
  bool confirmed = false;
  std::uint64_t writes = 0;  // writes the device answered (once, plus once per reconnect while latched)
  std::string problem;       // why it is not confirmed yet ("" once confirmed)

  [[nodiscard]] bool latched() const { return kind != StopKind::None; }
};

}  // namespace multidir::hardware

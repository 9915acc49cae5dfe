#pragma once
// Driver of the 4-DOF rotary platform's controller (a stepper turning the platform about one axis), over
// Modbus RTU or TCP. Register map: docs/hardware.md, "Rotary platform controller".
//
// Thread model: one worker thread per driver owns the libmodbus context. Commands are checked on the
// caller's thread against the machine profile and the last status (refused ones send nothing), then queued;
// stop() and emergencyStop() jump ahead of the queue and cancel what was queued. The worker polls the status,
// writes the heartbeat and reconnects with backoff on its own. Every public method may be called from any
// thread; the status callback runs on the worker thread and must not block.
//
// Errors: a refused command is InvalidParameter (out of the profile's range, not homed, not connected, in
// fault); a command cancelled by stop/e-stop is Cancelled; a failure at the device or on the link (timeout,
// lost connection, Modbus exception) is Internal with a message that names the device and what to check.
#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/core/search/machine.h"
#include "multidir/hardware/connection.h"
#include "multidir/hardware/control_lock.h"
#include "multidir/hardware/stop_latch.h"

namespace multidir::hardware {

enum class RotaryFault {
  None,
  Stall,            // no progress while a move or homing was under way (controller's or MultiDir's detection)
  HeartbeatLost,    // the controller stopped itself: MultiDir's heartbeat did not arrive in time
  LimitSwitch,      // a limit switch was hit
  RejectedCommand,  // the controller refused a command (move before homing, target beyond its own limits)
  EmergencyStop,    // the power stage was cut by an e-stop
  Unknown,          // a fault code this version does not know (see faultCode)
};

// "none", "stall", "heartbeat lost", "limit switch", "rejected command", "emergency stop", "unknown".
const char* rotaryFaultName(RotaryFault fault);

struct RotaryStatus {
  LinkState link = LinkState::Disconnected;
  bool enabled = false;
  bool homed = false;
  bool homing = false;
  bool moving = false;
  bool atTarget = false;          // the controller reports the target reached
  double angleDegrees = 0.0;      // the platform's angle now
  double targetAngleDegrees = 0.0;  // the target the controller holds
  RotaryFault fault = RotaryFault::None;
  int faultCode = 0;              // the raw code (register FAULT_CODE), 0 when MultiDir detected the fault itself
  bool stallDetectedByHost = false;  // MultiDir saw no progress and stopped the platform
  bool controllerAlive = false;   // the controller's heartbeat echo follows MultiDir's heartbeat
  std::string lastError;          // the latest link or device problem, for the operator ("" when none)
  std::uint64_t polls = 0;        // status reads since connect(); grows while the link works
  StopLatch stop;                 // the stop or e-stop held until clearStop(): moves and homing are refused
  ControlLock control;            // this driver's session and who controls the device (control_lock.h)
};

struct RotaryPlatformOptions {
  ConnectionSettings connection;
  core::MachineSpec machine;  // must be MachineKind::RotaryPlatform: its angle range and step are the soft limits
  double speedDegreesPerSecond = 20.0;  // (0, 655]
  // Written to the controller's HEARTBEAT_TIMEOUT: it stops on its own when MultiDir is silent this long.
  std::chrono::milliseconds controllerHeartbeatTimeout{1000};
  double positionToleranceDegrees = 0.02;  // reached() when within this of the target
  // A move or homing with no progress (> 0.05 degree) for this long is a stall: MultiDir stops the platform.
  std::chrono::milliseconds stallTimeout{1000};
};

class RotaryPlatform {
 public:
  using StatusCallback = std::function<void(const RotaryStatus&)>;

  explicit RotaryPlatform(RotaryPlatformOptions options);
  ~RotaryPlatform();  // disconnects (leaves the device as it is: its heartbeat watchdog stops it)
  RotaryPlatform(const RotaryPlatform&) = delete;
  RotaryPlatform& operator=(const RotaryPlatform&) = delete;

  // Starts the worker and waits for the first connection attempt (at most about twice the response
  // timeout). Done once connected, the controller claimed for this driver's session (control_lock.h) and the
  // status read; otherwise the attempt's error (DeviceFault "... is controlled by another run (session
  // 1a2b); stop that run first" while another driver holds it), and the worker keeps retrying with backoff in
  // the background: a latched stop or e-stop is written on each attempt all the same. InvalidParameter for
  // bad options (nothing started).
  core::Status connect();
  // Gives control back (the release command) when it holds it, stops the worker and closes the link,
  // without stopping the device (its heartbeat watchdog does).
  void disconnect();

  // Commands. Each returns a future that is ready at once with the refusal, or once the worker has written
  // the command (Done) or failed to (the device's or link's error, or Cancelled by stop/e-stop).
  std::future<core::Status> enable();
  std::future<core::Status> disable();
  std::future<core::Status> home();                          // requires enabled; finds the home switch (0 degrees)
  std::future<core::Status> moveTo(double angleDegrees);     // requires homed; checked with checkRotaryTarget
  // Stop and e-stop are latched (stop_latch.h): they jump the queue, are written as soon as the link allows
  // and again first after every reconnect, and every move or homing is refused until clearStop(). The
  // future ends once the device answered the write (not when the link is down: it then waits for the link).
  std::future<core::Status> stop();           // decelerates
  std::future<core::Status> emergencyStop();  // cuts the power stage
  // The operator allows moves again; refused (InvalidParameter) until the device confirmed the stop. After
  // an e-stop the controller also needs clearFault(), enable() and home().
  core::Status clearStop();
  std::future<core::Status> clearFault();                    // then enable and home again

  [[nodiscard]] RotaryStatus status() const;
  // At the commanded angle: link up, no fault, not moving, controller says at target, within tolerance.
  [[nodiscard]] bool reached(double angleDegrees) const;
  // Called on the worker thread after every status read and link change. Replaces the previous callback.
  void setStatusCallback(StatusCallback callback);
  // "rotary platform at 127.0.0.1:1502 (unit 1)".
  [[nodiscard]] std::string name() const;
  [[nodiscard]] const RotaryPlatformOptions& options() const;

 private:
  class Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace multidir::hardware

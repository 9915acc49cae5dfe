#pragma once
// Driver of the Universal Robots arm that holds the platform (5-DOF: tilt and azimuth), through the robot's
// Modbus TCP server (port 502, general-purpose registers 128-255) and the URScript program MultiDir ships in
// resources/urscript/multidir_platform.script. Register map: docs/hardware.md, "Robot arm".
//
// Thread model, errors and command futures as in rotary_platform.h: commands are checked against the
// machine profile (tilt limit, forbidden cones) and the last status before anything is sent.
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

// What the URScript program reports in its STATE register.
enum class RobotProgramState {
  NotRunning,  // the program has never written its state (0): not started on the teach pendant
  Idle,        // running, no move requested yet
  Moving,
  Reached,     // at the requested orientation
  Stopped,     // stopped by a stop command
  Halted,      // e-stop command: refuses moves until reset (clearFault)
  Fault,       // see faultCode: target beyond the program's limits, heartbeat lost, unknown command
};

// "not running", "idle", "moving", "reached", "stopped", "halted", "fault".
const char* robotProgramStateName(RobotProgramState state);

struct RobotStatus {
  LinkState link = LinkState::Disconnected;
  RobotProgramState state = RobotProgramState::NotRunning;
  bool programAlive = false;        // the program's heartbeat register keeps changing
  std::uint16_t sentSequence = 0;   // the last command number MultiDir wrote
  std::uint16_t acknowledgedSequence = 0;  // the last command number the program took
  double tiltDegrees = 0.0;         // the orientation now
  double azimuthDegrees = 0.0;
  double targetTiltDegrees = 0.0;   // the orientation requested in the registers
  double targetAzimuthDegrees = 0.0;
  int faultCode = 0;                // the program's FAULT_CODE (0 none, 1 beyond limits, 2 heartbeat lost, 3 unknown command)
  std::string lastError;
  std::uint64_t polls = 0;
  StopLatch stop;  // the stop or e-stop held until clearStop(): moves are refused
  ControlLock control;  // this driver's session and who controls the device (control_lock.h)
};

struct RobotArmOptions {
  RobotArmOptions() {
    connection.tcp.port = 502;
    connection.slaveId = 255;  // UR's server answers any unit id; 255 is the customary one
    machine.kind = core::MachineKind::TiltRotate;
  }
  ConnectionSettings connection;
  core::MachineSpec machine;  // must be MachineKind::TiltRotate: maxTiltDegrees and forbiddenCones apply
  int speedPercent = 50;      // of the program's maximal joint speed, 1..100
  std::chrono::milliseconds programHeartbeatTimeout{1000};  // written to HEARTBEAT_TIMEOUT
  double orientationToleranceDegrees = 0.05;
  // A command the program has not acknowledged after this long is reported in lastError.
  std::chrono::milliseconds acknowledgeTimeout{1000};
};

class RobotArm {
 public:
  using StatusCallback = std::function<void(const RobotStatus&)>;

  explicit RobotArm(RobotArmOptions options);
  ~RobotArm();
  RobotArm(const RobotArm&) = delete;
  RobotArm& operator=(const RobotArm&) = delete;

  core::Status connect();  // as RotaryPlatform::connect: claims the program's control lock too
  void disconnect();       // as RotaryPlatform::disconnect

  // Requires the program alive and not halted or faulted; azimuth is taken modulo 360.
  std::future<core::Status> moveTo(double tiltDegrees, double azimuthDegrees);
  // Stop and e-stop are latched as in rotary_platform.h: written as soon as the link allows and again first
  // after every reconnect; moves are refused until clearStop().
  std::future<core::Status> stop();
  std::future<core::Status> emergencyStop();  // halts the program (stopj at maximal deceleration)
  core::Status clearStop();                   // refused until the program confirmed the stop
  std::future<core::Status> clearFault();     // reset after a halt or fault

  [[nodiscard]] RobotStatus status() const;
  // The program acknowledged MultiDir's last command, reports Reached, and the orientation is within tolerance.
  [[nodiscard]] bool reached(double tiltDegrees, double azimuthDegrees) const;
  void setStatusCallback(StatusCallback callback);
  [[nodiscard]] std::string name() const;  // "robot arm at 192.168.0.10:502 (unit 255)"
  [[nodiscard]] const RobotArmOptions& options() const;

 private:
  class Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace multidir::hardware

#pragma once
// A Universal Robots controller on loopback, for tests, demos and `multidir simulate --ur MODEL`: the three
// client interfaces MultiDir's robot cell uses, in UR's formats (docs/hardware.md, "UR controller"):
//   - the dashboard server (UR's port 29999): text lines, greeted with "Connected: Universal Robots Dashboard
//     Server"; power on/off, brake release, play, stop, pause, programState, robotmode, safetymode,
//     safetystatus, unlock protective stop, close safety popup, running, quit, with UR's reply texts;
//   - the secondary interface (30002): a URScript program sent as text runs once its top-level `end` arrives
//     (the subset MultiDir's programs use; anything else is refused with a runtime exception naming the line);
//     the controller sends robot messages (version on connect, textmsg texts, runtime exceptions, error codes);
//   - the real-time interface (30003): the 1108-byte state package every control tick (125 Hz);
//   - RTDE (30004, protocol version 2, outputs only): timestamp, actual_TCP_pose, runtime_state and the output
//     integer registers output_int_register_0..47 (what the programs' write_output_integer_register set).
// The arm moves by the kinematic model of MultiDir's robot library (sim/ur_controller.h), `speed` times
// faster than real time on the injectable clock. Every tick in which a program runs or the arm moves is traced
// (joints, TCP pose, analog outputs, nozzle temperature), kept for tests and/or written as CSV.
//
// Every method may be called from any thread.
#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"

namespace multidir::hardware {

enum class UrSimulatorFault { None, ProtectiveStop, EmergencyStop, LinkDrop, ProgramError };

// "none", "protective-stop", "emergency-stop", "link-drop", "program-error".
const char* urSimulatorFaultName(UrSimulatorFault fault);
core::Result<UrSimulatorFault> parseUrSimulatorFault(const std::string& name);

struct UrSimulatorOptions {
  std::string model = "ur5";                // one of robot::armModelNames()
  std::string listenAddress = "127.0.0.1";  // an IPv4 address
  int dashboardPort = 0;                    // 0: a free port (UR's: 29999)
  int secondaryPort = 0;                    // (UR's: 30002)
  int realtimePort = 0;                     // (UR's: 30003)
  int rtdePort = 0;                         // (UR's: 30004)
  double speed = 1.0;                       // simulated seconds per real second, (0, 100000]
  // A robot cell file (docs/robot-cell.md): the arm gets the cell's joint limits and starts at its home
  // joints; its robot must be `model`. "" for the model's own limits and initialJoints.
  std::string cellPath;
  // The largest program the controller compiles (a larger one is refused with a compile error); 0: the cell's
  // maxProgramBytes with a cell, else robot::kDefaultMaxProgramBytes.
  std::size_t maxProgramBytes = 0;
  // The joints at power-up (rad); UR's "home" pose with the arm upright is {0, -pi/2, 0, -pi/2, 0, 0}.
  std::array<double, 6> initialJoints{0.0, -1.5707963267948966, 0.0, -1.5707963267948966, 0.0, 0.0};
  // The clock the simulated time follows; the system's steady clock unless a test injects one.
  std::function<std::chrono::steady_clock::time_point()> steadyNow;
  bool keepTrace = false;  // keep every traced tick for trace()
  std::string tracePath;   // write every traced tick as CSV to this file ("" none)
  // A fault injected once: at `faultAtSeconds` simulated seconds after the first program started (>= 0), or
  // when a program reaches line `faultAtLine` (> 0). A link drop closes every connection and refuses new ones
  // for `linkDropSeconds` real seconds.
  UrSimulatorFault fault = UrSimulatorFault::None;
  double faultAtSeconds = -1.0;
  int faultAtLine = 0;
  double linkDropSeconds = 3.0;
};

// One tick the simulator traced.
struct UrTraceRecord {
  double time = 0.0;               // simulated seconds since start
  std::array<double, 6> joints{};  // rad
  std::array<double, 6> tcp{};     // x, y, z (mm), rotation vector (rad), base frame
  double analogOut0 = 0.0;         // extruder speed (fraction)
  double analogOut1 = 0.0;         // nozzle set point (fraction of 300 C)
  double nozzleC = 0.0;
  std::string program;  // running program ("" while the arm brakes after it)
  int line = 0;
  // With a cell (UrSimulatorOptions::cellPath): the fixed nozzle's tip in the platform's frame (the TCP's,
  // mm: where the nozzle is on the part) and the filament speed analog out 0 commands (mm/s).
  bool hasCell = false;
  std::array<double, 3> nozzleInPlatform{};
  double filamentMmPerS = 0.0;
};

struct UrDashboardRecord {
  double time = 0.0;  // simulated seconds when it arrived
  std::string command;
  std::string reply;
};

struct UrSimulatorState {
  double time = 0.0;
  std::string robotMode;     // "POWER_OFF", "IDLE", "RUNNING", ...
  std::string safetyMode;    // "NORMAL", "PROTECTIVE_STOP", "ROBOT_EMERGENCY_STOP", ...
  std::string programState;  // "STOPPED", "PLAYING", "PAUSED"
  std::string programName;
  int line = 0;
  std::array<double, 6> joints{};
  bool atRest = true;
  double nozzleC = 0.0;
  std::array<double, 2> analogOut{};
  unsigned digitalOut = 0;
  std::string lastFault;  // UR's words for the latest fault or refused program ("" none)
  std::size_t programsReceived = 0;
  std::size_t programsFinished = 0;
  bool linkDropped = false;
  int connections = 0;
};

class UrSimulator {
 public:
  explicit UrSimulator(UrSimulatorOptions options = {});
  ~UrSimulator();  // stops
  UrSimulator(const UrSimulator&) = delete;
  UrSimulator& operator=(const UrSimulator&) = delete;

  // Binds the four ports and starts. InvalidParameter for bad options (an unknown model names the known
  // ones); Internal when a port cannot be bound, saying why.
  core::Status start();
  void stop();
  [[nodiscard]] int dashboardPort() const;
  [[nodiscard]] int secondaryPort() const;
  [[nodiscard]] int realtimePort() const;
  [[nodiscard]] int rtdePort() const;

  // Faults, now.
  void protectiveStop(const std::string& reason);
  void pressEmergencyStop();
  void releaseEmergencyStop();
  void programError(const std::string& text);
  void dropLinks();  // closes every connection and refuses new ones until restoreLinks()
  void restoreLinks();

  // Observation.
  [[nodiscard]] UrSimulatorState state() const;
  [[nodiscard]] std::vector<UrTraceRecord> trace() const;  // with keepTrace
  [[nodiscard]] std::vector<UrDashboardRecord> dashboardLog() const;
  [[nodiscard]] std::vector<std::string> programsReceived() const;  // texts, in order
  // Waits (real time) until the simulated time reaches `seconds` (the injected clock must have passed it);
  // false when `limit` passes first.
  bool waitForSimulatedTime(double seconds, std::chrono::milliseconds limit = std::chrono::milliseconds(5000)) const;

 private:
  class Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace multidir::hardware

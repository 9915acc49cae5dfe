#pragma once
// The print-run sequencer: turns the platform to each region's orientation, waits until it has settled, asks
// the operator (or an external signal) to print the region, waits for "region done", and goes on.
//
// Driven by calls, not by its own thread: the owner calls tick() regularly (a GUI timer, the CLI loop, a
// test) and forwards operator events (start, pause, resume, abort, regionDone). Time comes from an
// injectable clock, so tests run without waiting. Not thread-safe: call every method from one thread.
//
// States and transitions (anything not listed is refused with InvalidParameter and changes nothing):
//
//   from      | event / condition (tick)                    | to        | action
//   ----------+---------------------------------------------+-----------+-----------------------------------
//   Idle      | start()                                     | Moving    | startMove(step 0)
//   Moving    | tick: positioner reached the target         | Settling  |
//   Moving    | tick: fault, link down, move timeout        | Faulted   | stopMotion()
//   Moving    | start of move refused                       | Faulted   |
//   Settling  | tick: reached for settleTime                | Printing  | print request callback(step)
//   Settling  | tick: no longer reached                     | Moving    | (waits again, same target)
//   Settling  | tick: fault, link down                      | Faulted   | stopMotion()
//   Moving,   | pause()                                     | Paused    | stopMotion()
//   Settling  |   ... the stop is refused                   | Faulted   | (pause() returns the refusal)
//   Printing  | pause()                                     | Printing  | pause pending: no motion while printing
//   Printing  | regionDone(i), i current, more steps        | Moving    | startMove(step i+1)
//             |   ... with a pause pending                  | Paused    | (step i+1 not started)
//   Printing  | regionDone(i), i the last step              | Completed |
//   Paused    | resume()                                    | Moving    | clearStop(), startMove(current step)
//   Faulted   | resume() (retry the current step)           | Moving    | clearStop(), startMove(current step)
//   Paused,   | resume() while the device has not confirmed | (same)    | refused: the stop has not reached the
//   Faulted   |   the stop (clearStop refused)              |           | device yet
//   any but   | abort()                                     | Aborted   | stopMotion() unless Printing (the
//   Completed,|                                             |           | operator stops the printer)
//   Aborted   |                                             |           |
//
// A stop is only requested by stopMotion(); "motion stopped" is logged when a later tick() sees the device's
// confirmation (PositionerSnapshot::stopConfirmed), in whatever state the run is then (ticks keep watching
// for it in Paused, Faulted and Aborted); a stop not confirmed after a second is logged once as a warning. A
// refused stop is logged at once and says to use the E-STOP.
//
// While Printing no move is ever commanded; device faults seen while printing are logged and taken up
// after regionDone. Completed and Aborted are final.
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"

namespace multidir::hardware {

class RotaryPlatform;
class RobotArm;

// A platform orientation: a 4-DOF angle, or a 5-DOF tilt and azimuth (degrees).
struct PlatformOrientation {
  enum class Kind { Rotary, TiltAzimuth };
  Kind kind = Kind::Rotary;
  double rotaryDegrees = 0.0;
  double tiltDegrees = 0.0;
  double azimuthDegrees = 0.0;

  static PlatformOrientation rotary(double angleDegrees);
  static PlatformOrientation tiltAzimuth(double tiltDegrees, double azimuthDegrees);
  std::string describe() const;  // "rotary 30.00 deg" / "tilt 45.00 deg, azimuth -90.00 deg"
};

struct PrintStep {
  PlatformOrientation orientation;
  std::string regionFile;  // the region's G-code or mesh, shown to the operator
};

// What the sequencer needs to know of the device that orients the platform.
struct PositionerSnapshot {
  bool linkUp = false;
  bool moving = false;
  bool reached = false;   // at the orientation of the last startMove, at rest
  bool faulted = false;
  std::string problem;    // why faulted (or the link is down), for the log
  bool stopLatched = false;    // a stop is held by the device's driver: moves are refused until clearStop()
  bool stopConfirmed = false;  // ... and the device confirmed it
};

// The device behind the sequencer: the real drivers (makePositioner) or a test double.
class Positioner {
 public:
  virtual ~Positioner() = default;
  // Starts a move and returns without waiting for it; a refusal comes back at once.
  virtual core::Status startMove(const PlatformOrientation& target) = 0;
  // Latches a stop and returns without waiting for it: a refusal comes back at once; Done means asked for,
  // not done (snapshot().stopConfirmed tells when the device took it).
  virtual core::Status stopMotion() = 0;
  // Allows moves again after stopMotion(); refused while the device has not confirmed the stop.
  virtual core::Status clearStop() = 0;
  [[nodiscard]] virtual PositionerSnapshot snapshot() const = 0;
  [[nodiscard]] virtual std::string name() const = 0;
};

// Adapters over the drivers (which must outlive them). A rotary positioner refuses tilt/azimuth targets and
// vice versa.
std::unique_ptr<Positioner> makePositioner(RotaryPlatform& platform);
std::unique_ptr<Positioner> makePositioner(RobotArm& arm);

enum class PrintRunState { Idle, Moving, Settling, Printing, Paused, Completed, Aborted, Faulted };

// "idle", "moving", "settling", "printing", "paused", "completed", "aborted", "faulted".
const char* printRunStateName(PrintRunState state);

struct PrintRunLogEntry {
  std::chrono::system_clock::time_point wallTime;  // when, for the operator's log
  std::chrono::milliseconds elapsed{0};            // since start()
  std::size_t step = 0;                            // the current step's index
  PrintRunState state = PrintRunState::Idle;       // the state after the event
  std::string message;                             // "step 2/5 (region_2.gcode): tilt 30.00 deg ... reached"
};

struct PrintRunOptions {
  std::chrono::milliseconds settleTime{500};     // reached this long before printing starts
  std::chrono::milliseconds moveTimeout{120000};  // a move not reached by then is a fault
  // Clocks; the defaults are the system's. Tests inject their own.
  std::function<std::chrono::steady_clock::time_point()> steadyNow;
  std::function<std::chrono::system_clock::time_point()> wallNow;
};

class PrintRun {
 public:
  using LogCallback = std::function<void(const PrintRunLogEntry&)>;
  // Called when region `step` may be printed: the operator or the printer starts it and later calls
  // regionDone(step).
  using PrintRequestCallback = std::function<void(std::size_t step, const PrintStep&)>;

  PrintRun(Positioner& positioner, std::vector<PrintStep> steps, PrintRunOptions options = {});

  core::Status start();
  core::Status pause();
  core::Status resume();
  core::Status abort();
  core::Status regionDone(std::size_t step);
  // Advances the state machine with the positioner's snapshot and the clock.
  void tick();

  [[nodiscard]] PrintRunState state() const { return m_state; }
  [[nodiscard]] std::size_t currentStep() const { return m_step; }
  [[nodiscard]] bool pausePending() const { return m_pausePending; }
  // A stop was asked for and the device has not confirmed it yet: keep calling tick() (even once Aborted).
  [[nodiscard]] bool stopUnconfirmed() const { return m_awaitingStopConfirmation; }
  [[nodiscard]] const std::vector<PrintStep>& steps() const { return m_steps; }
  [[nodiscard]] const std::vector<PrintRunLogEntry>& log() const { return m_log; }
  [[nodiscard]] const std::string& lastProblem() const { return m_lastProblem; }

  void setLogCallback(LogCallback callback) { m_logCallback = std::move(callback); }
  void setPrintRequestCallback(PrintRequestCallback callback) { m_printRequest = std::move(callback); }

 private:
  void enter(PrintRunState state, const std::string& message);
  void beginMove();
  void fault(const std::string& problem);
  // stopMotion(), remembering to log the device's confirmation; the positioner's refusal, if any.
  core::Status requestStop();
  void watchStop(const PositionerSnapshot& snapshot);
  std::string stepLabel() const;
  core::Status refuse(const std::string& event) const;

  Positioner& m_positioner;
  std::vector<PrintStep> m_steps;
  PrintRunOptions m_options;
  PrintRunState m_state = PrintRunState::Idle;
  std::size_t m_step = 0;
  bool m_pausePending = false;
  bool m_faultLoggedWhilePrinting = false;
  bool m_awaitingStopConfirmation = false;
  bool m_stopProblemLogged = false;
  std::chrono::steady_clock::time_point m_started{};
  std::chrono::steady_clock::time_point m_moveStarted{};
  std::chrono::steady_clock::time_point m_settleStarted{};
  std::chrono::steady_clock::time_point m_stopRequested{};
  std::string m_lastProblem;
  std::vector<PrintRunLogEntry> m_log;
  LogCallback m_logCallback;
  PrintRequestCallback m_printRequest;
};

}  // namespace multidir::hardware

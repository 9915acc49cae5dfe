#pragma once
// The print-run sequencer: turns the platform to each region's orientation, waits until it has settled, has
// the region printed, and goes on. With a printer link (printer_link.h) it uploads and starts the step's
// G-code itself and follows the printer's job until the printer reports it complete; without one (or for a
// step without G-code) it asks the operator to print the region and waits for "region done".
//
// Driven by calls, not by its own thread: the owner calls tick() regularly (a GUI timer, the CLI loop, a
// test) and forwards operator events (start, pause, resume, abort, regionDone, emergencyStop). Time comes
// from an injectable clock, so tests run without waiting. Not thread-safe: call every method from one thread.
//
// States and transitions (anything not listed is refused with InvalidParameter and changes nothing):
//
//   from      | event / condition (tick)                    | to        | action
//   ----------+---------------------------------------------+-----------+-----------------------------------
//   Idle      | start(k)                                    | Moving    | startMove(step k; 0 by default)
//   Moving    | tick: positioner reached the target         | Settling  |
//   Moving    | tick: fault, link down, move timeout        | Faulted   | stopMotion()
//   Moving    | start of move refused, or the printer busy  | Faulted   | (nothing moves)
//             |   or its state unknown (interlock)          |           |
//   Settling  | tick: reached for settleTime                | Printing  | print request callback(step); with a
//             |                                             |           | printer: upload the step's G-code
//   Settling  | tick: ... but the printer is busy or lost   | Faulted   | (nothing is sent)
//   Settling  | tick: no longer reached                     | Moving    | (waits again, same target)
//   Settling  | tick: fault, link down                      | Faulted   | stopMotion()
//   Moving,   | pause()                                     | Paused    | stopMotion()
//   Settling  |   ... the stop is refused                   | Faulted   | (pause() returns the refusal)
//   Printing  | pause()                                     | Printing  | pause pending: no motion while printing
//   Printing  | tick (printer): uploaded                    | Printing  | startPrint(step's file)
//   Printing  | tick (printer): job complete, or            | Moving    | startMove(step i+1)
//             | regionDone(i), i current, more steps        |           |
//             |   ... with a pause pending                  | Paused    | (step i+1 not started)
//   Printing  | the same, i the last step                   | Completed |
//   Printing  | tick (printer): upload or start refused,    | Paused    | print interrupted (the reason is
//             | printer error, job cancelled on the printer,|           | lastProblem); a temperature fault
//             | the job seen printing gone from the printer |           |
//             | (it restarted: standby, no or another file),|           |
//             | link lost, temperature fault, the platform  |           | or a moving platform also pauses the
//             | moving                                      |           | printer's job
//   Paused    | resume(), print interrupted: printer paused | Printing  | resumePrint()
//             |   ... printer still printing the file       | Printing  | (follows it again)
//             |   ... printer reports the file complete     | Moving    | startMove(step i+1) (or Completed)
//             |   ... anything else                         | Paused    | refused: finish the region by hand
//             |                                             |           | and regionDone(i), or abort
//   Paused    | regionDone(i), print interrupted            | Moving    | startMove(step i+1) (or Completed)
//   Paused    | restartStep(), print interrupted and the    | Printing  | upload and start the step's G-code
//             |   printer has no job of it any more (it     |           | again from its beginning (the operator
//             |   restarted: interruptedJobGone())          |           | cleared what the first attempt left)
//   Paused    | resume()                                    | Moving    | clearStop(), startMove(current step)
//   Faulted   | resume() (retry the current step)           | Moving    | clearStop(), startMove(current step)
//   Paused,   | resume() while the device has not confirmed | (same)    | refused: the stop has not reached the
//   Faulted   |   the stop (clearStop refused)              |           | device yet
//   any but   | abort()                                     | Aborted   | stopMotion() unless Printing; while
//   Completed,|                                             |           | Printing with a printer: cancelPrint()
//   Aborted   |                                             |           | (without: the operator stops it);
//             |                                             |           | with a printer, in every state:
//             |                                             |           | switchHeatersOff() (after the cancel)
//   any       | emergencyStop()                             | Aborted   | the positioner's and the printer's
//             |                                             | (final    | emergency stops, both at once, both
//             |                                             | states    | latched by their drivers
//             |                                             | stay)     |
//
// With a printer, every tick (in every state) logs the link's protocol warnings that are new since the last
// one (PrinterStatus::protocolWarnings, lastWarning: a stray ok, a noise line), once each; warnings from
// before the run was constructed are not repeated.
//
// A stop is only requested by stopMotion(); "motion stopped" is logged when a later tick() sees the device's
// confirmation (PositionerSnapshot::stopConfirmed), in whatever state the run is then (ticks keep watching
// for it in Paused, Faulted and Aborted); a stop not confirmed after a second is logged once as a warning. A
// refused stop is logged at once and says to use the E-STOP.
//
// Interlocks (checked on every move and every print start, whatever the state machine believes): the platform
// is never commanded while the printer reports a job printing or paused, or while the printer's state is
// unknown (link lost); the printer is never started unless the positioner reports the step's orientation
// reached, at rest, link up and no fault. While Printing no move is ever commanded; positioner faults seen
// while printing are logged and taken up after the region is done.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"

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
  // The step's G-code, uploaded to the printer and started when the run has a printer link; empty: the
  // operator prints the region and presses "region done".
  std::string gcodePath = {};
  // The SHA-256 of the G-code as the owner checked it (content_digest.h; `multidir run` takes it in its checks
  // before the first move): the printer link refuses the file if what it reads then differs, so a file
  // replaced during the run is never printed unchecked (the run pauses, naming it). "": not checked by the
  // owner (the studio); the file is sent as it is when its step comes up.
  std::string gcodeSha256 = {};
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
  // The device's own emergency stop (rotary: cut the power stage; robot: halt), latched like stopMotion().
  virtual core::Status emergencyStop() = 0;
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

// The situations after which the log tells the operator what to do (PrintRunOptions::advice).
enum class PrintRunAdvice {
  RetryStep,             // faulted before printing: fix it, then retry the step, or abort
  RetryWhenPrinterIdle,  // the move was not sent because the printer is busy or its state unknown
  PrintInterrupted,      // paused while the printer printed the step (printInterrupted())
  EmergencyStop,         // a stop was refused or is not confirmed: the device may still move
};

struct PrintRunOptions {
  std::chrono::milliseconds settleTime{500};     // reached this long before printing starts
  std::chrono::milliseconds moveTimeout{120000};  // a move not reached by then is a fault
  // With a printer: a heater this far above its target while the step prints is a temperature fault (a
  // heater running away; Klipper's own checks may shut it down later).
  double temperatureOvershootC = 15.0;
  // With a printer: started, but no job of the step's file seen printing or complete by then: a fault.
  std::chrono::milliseconds printStartTimeout{30000};
  // What the log tells the operator to do after a pause or fault, in the owner's words. Unset: the studio's
  // (resume, Region done, abort, the E-STOP). An owner without those buttons (the command line, which ends the run at a
  // pause) gives its own.
  std::function<std::string(PrintRunAdvice)> advice;
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

  // `printer` (optional, must outlive the run): prints the steps that have G-code; nullptr: the operator does.
  PrintRun(Positioner& positioner, std::vector<PrintStep> steps, PrintRunOptions options = {},
           PrinterLink* printer = nullptr);

  // From step `firstStep` (0-based; the steps before it were printed by an earlier run that was aborted):
  // its move is the first. InvalidParameter when there is no such step.
  core::Status start(std::size_t firstStep = 0);
  core::Status pause();
  core::Status resume();
  core::Status abort();
  core::Status regionDone(std::size_t step);
  // Prints the current step again from the beginning of its G-code, when the run is paused for an interrupted
  // print and the printer no longer has that job (interruptedJobGone(): it restarted, or the job was cancelled
  // on it), so Resume has nothing to resume. The owner asks the operator first to clear the platform of what
  // the first attempt printed. The platform does not move: the printer starts only if it still reports the
  // step's orientation reached (else the run faults, and resume() retries the step with its move). Refused
  // (InvalidParameter, naming why) in any other state, while the printer link is lost, its emergency stop is
  // latched or its firmware is not ready.
  core::Status restartStep();
  // Sends the positioner's and the printer's emergency stops at once and ends the run (Aborted); never refused.
  // Both are latched by their drivers and resent until confirmed; ticks log each confirmation.
  core::Status emergencyStop();
  // Advances the state machine with the positioner's snapshot, the printer's status and the clock.
  void tick();

  [[nodiscard]] PrintRunState state() const { return m_state; }
  [[nodiscard]] std::size_t currentStep() const { return m_step; }
  [[nodiscard]] bool pausePending() const { return m_pausePending; }
  // A stop was asked for and the device has not confirmed it yet, or the printer has not answered the
  // heaters-off of an abort yet: keep calling tick() (even once Aborted).
  [[nodiscard]] bool stopUnconfirmed() const {
    return m_awaitingStopConfirmation || m_awaitingPrinterStop || m_heatersOffCommand.valid();
  }
  // The current step's print was begun (the printer was asked to start its G-code, or the operator to print
  // the region) and has not been seen finished: part of the region may be on the platform, so printing the
  // step again from its start would print over it.
  [[nodiscard]] bool stepBegun() const { return m_stepBegun; }
  // The share (0..1) of the current step's G-code the printer had read at the last status read of it.
  [[nodiscard]] double stepProgress() const { return m_stepProgress; }
  // Paused because the printer's job for the current step was interrupted (lastProblem says why).
  [[nodiscard]] bool printInterrupted() const { return m_printInterrupted; }
  // Paused for an interrupted print, the printer answers, and it has no job of the current step to resume or
  // report complete (it restarted: standby with no file or another file; or the job ended cancelled or in
  // error): resume() is refused, restartStep() prints the step again.
  [[nodiscard]] bool interruptedJobGone() const;
  [[nodiscard]] bool hasPrinter() const { return m_printer != nullptr; }
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
  // Why the platform may not move now because of the printer ("" when it may).
  std::string printerForbidsMotion() const;
  void beginPrint(const PositionerSnapshot& snapshot);
  void tickPrinter(const PositionerSnapshot& snapshot);
  void interruptPrint(const std::string& reason);
  // The current region is printed: the next step, a pending pause, or Completed.
  void finishRegion();
  std::string remoteName() const;
  std::string advice(PrintRunAdvice situation) const;
  void switchHeatersOff();
  // Logs the printer link's protocol warnings (PrinterStatus::protocolWarnings) not logged yet, once each.
  void logProtocolWarnings();
  bool stepUsesPrinter() const { return m_printer != nullptr && !m_steps[m_step].gcodePath.empty(); }

  enum class PrintPhase { None, Uploading, Starting, Running };

  Positioner& m_positioner;
  PrinterLink* m_printer = nullptr;
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
  PrintPhase m_phase = PrintPhase::None;
  std::future<core::Status> m_printerCommand;  // the upload or start in flight
  std::future<core::Status> m_printerSideCommand;  // a pause or cancel sent on the side (outcome logged)
  std::future<core::Status> m_heatersOffCommand;   // an abort's heaters-off, until the printer answered it
  bool m_stepBegun = false;
  double m_stepProgress = 0.0;
  std::uint64_t m_pollsAtStart = 0;
  std::chrono::steady_clock::time_point m_printStarted{};
  bool m_printInterrupted = false;
  bool m_jobSeen = false;  // the current step's job was seen on the printer (printing or paused) since its start
  bool m_printerPausedLogged = false;
  int m_progressTenths = -1;
  bool m_awaitingPrinterStop = false;
  std::uint64_t m_protocolWarningsLogged = 0;  // PrinterStatus::protocolWarnings up to which the log told
  std::vector<PrintRunLogEntry> m_log;
  LogCallback m_logCallback;
  PrintRequestCallback m_printRequest;
};

}  // namespace multidir::hardware

#pragma once
// A Marlin printer on a pseudo-terminal, for tests, demos and `multidir simulate --printer marlin`: open
// devicePath() ("/dev/pts/N") as the printer's serial port (serial:///dev/pts/N). It speaks the subset of
// Marlin's host protocol MarlinLink uses (docs/hardware.md, "Marlin (USB serial)"): line numbers and
// checksums checked ("Error:checksum mismatch, Last Line: n" / "Error:Line Number is not Last Line Number+1,
// Last Line: n", then "Resend: n+1" and "ok"), M110, M105 ("ok T:.. /.. B:.. /.. @:0 B@:0"), M114 ("X:.. Y:..
// Z:.. E:.. Count X:.. Y:.. Z:.."), M400, M27, M155, M112 (halts at once: "Error:Printer halted. kill() called!",
// then nothing more), "echo:busy: processing" while a command blocks or waits for room in the planner. Moves and
// heater waits run on the same simulated printer as the Moonraker simulator (timed by feed rates and heating
// rates, `speed` times faster than real time, on the injectable clock); a move is acknowledged once it is in the
// planner (16 moves), M109/M190/G28/G4 once they are done, M400 once the planner is empty.
//
// Every method may be called from any thread. Every line received is recorded with its time from the
// injectable clock, and so is every command the printer executed, so tests assert on what reached the printer.
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"
#include "multidir/hardware/printer_simulator.h"
#include "multidir/hardware/simulated_axes.h"

namespace multidir::hardware {

struct MarlinSimulatorOptions {
  double speed = 1.0;                                   // simulated seconds per real second, (0, 100000]
  int plannerMoves = 16;                                // Marlin's BLOCK_BUFFER_SIZE
  std::chrono::milliseconds busyInterval{2000};         // "echo:busy: processing" while blocked (Marlin's default)
  std::chrono::milliseconds temperatureInterval{1000};  // "T:..." lines while M109/M190 wait
  // The clock of the records and of the simulated time; the system's steady clock unless a test injects one.
  std::function<std::chrono::steady_clock::time_point()> steadyNow;
  // ThermalRunaway or CancelledOnPrinter, injected by the printer itself once it has taken its faultAtMove-th
  // move (G0/G1) into the planner: on that event, not on a timer, so a late test thread cannot miss the job.
  PrinterFault fault = PrinterFault::None;
  long faultAtMove = 10;
  // Marlin's ADVANCED_OK: every ok of a numbered line says which: "ok N<line> P<planner free> B<buffer free>".
  bool advancedOk = false;
  // Rotary axes as Marlin 2.1 has them (AXIS4_NAME..): G-code letters, e.g. {"U", "V"} (--rotary-axes U,V).
  // M114 reports them after Z ("X:.. Y:.. Z:.. U:.. V:.. E:.. Count X:.. Y:.. Z:.. U:.. V:..") and M115's
  // first line says AXIS_COUNT:5. Manual steppers are Klipper's: refused.
  SimulatedRotaryAxes rotaryAxes;
};

struct MarlinLineRecord {
  enum class Outcome {
    Accepted,          // numbered, checksum and number right (or unnumbered): queued for execution
    ChecksumMismatch,  // answered Resend
    WrongLineNumber,   // answered Resend (a line skipped, or sent twice)
    NoChecksum,        // numbered without '*': answered Resend
    EmergencyStop,     // M112: Marlin halts at once
    Ignored,           // received after the halt: nothing is answered
  };
  std::chrono::steady_clock::time_point at;
  std::string text;      // as received, without the line end
  long lineNumber = -1;  // N; -1 when unnumbered
  std::string command;   // without number and checksum
  Outcome outcome = Outcome::Accepted;
};

struct MarlinExecutedRecord {
  std::chrono::steady_clock::time_point at;  // when the printer finished it (a move: when the move ended)
  long lineNumber = -1;
  std::string command;
};

struct MarlinSimulatorState {
  bool halted = false;
  std::string haltReason;  // Marlin's words, "" while running
  HeaterReading extruder;
  HeaterReading bed;
  long lastLineNumber = 0;      // Marlin's "Last Line"
  std::size_t queuedMoves = 0;  // in the planner, not finished
};

class MarlinSimulator {
 public:
  explicit MarlinSimulator(MarlinSimulatorOptions options = {});
  ~MarlinSimulator();
  MarlinSimulator(const MarlinSimulator&) = delete;
  MarlinSimulator& operator=(const MarlinSimulator&) = delete;

  // Opens the pseudo-terminal. InvalidParameter for bad options; DeviceUnreachable when no pty can be opened.
  core::Status start();
  void stop();                                   // idempotent; the device path disappears
  [[nodiscard]] std::string devicePath() const;  // "/dev/pts/5"

  // Faults, now.
  void injectThermalRunaway();  // the extruder runs away; Marlin halts: "Error:Thermal Runaway, system stopped!"
  void cancelJobOnPrinter();    // the LCD's "Stop print": the planner is emptied, heaters off, "//action:cancel"
  void dropLink();              // the printer stops hearing and answering (a cable fault) until restoreLink()
  void restoreLink();
  void closePort();                                     // the device disappears (unplugged): the link's reads fail
  void setReplyDelay(std::chrono::milliseconds delay);  // every line the printer writes is held this long
  void corruptNextLines(int count);                     // the next `count` numbered lines arrive with one byte changed
  void resetPrinter();  // the reset button: a halted printer restarts ("start") with line number 0
  // Lines a host cannot account for (test hooks): an ok that answers no line (a firmware's extra ok, a line
  // echoed back by a hub), a serial line that carries only noise, a printer that never reports its temperatures.
  void sendStrayOks(int count);                             // `count` oks that answer no line, written now
  void sendStrayOkOnReceiving(const std::string& command);  // a stray ok right after each line of `command` arrives
  // On: every line the printer writes arrives as noise, and more noise arrives every 20 ms (a wrong baud rate, a
  // bad cable): nothing reads as Marlin's protocol. Off: its lines arrive again.
  void garbleOutput(bool garbled);
  // Off: M105 is answered with a bare "ok", and no temperature line is written (heater waits, M155).
  void reportTemperatures(bool report);

  // Observation.
  [[nodiscard]] std::vector<MarlinLineRecord> received() const;
  [[nodiscard]] std::vector<MarlinExecutedRecord> executed() const;
  [[nodiscard]] MarlinSimulatorState state() const;
  // The streamed job's extrusions and turns with the rotary axes' coordinates (simulated_axes.h); `sequence`
  // counts the commands the printer ran since it was powered on (or reset).
  [[nodiscard]] SimulatedAxisLog axisLog() const;

 private:
  class Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace multidir::hardware

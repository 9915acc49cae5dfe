#pragma once
// What the printer simulators share (Moonraker: moonraker_simulator.h, OctoPrint: octoprint_simulator.h): an
// HTTP server in front of one simulated printer, for tests, demos and `multidir simulate --printer ...`.
// An uploaded G-code file is "printed" line by line: each move takes its length over its feed rate, M109/M190
// wait for the heater (heating at a finite rate), all of it `speed` times faster than real time.
//
// Listens on 127.0.0.1 unless told otherwise; port 0 picks a free port. Every method may be called from any
// thread. Every request is recorded (time from the injectable clock), and so is every change of the job's
// state, so tests assert on what reached the printer and when.
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"
#include "multidir/hardware/simulated_axes.h"

namespace multidir::hardware {

namespace sim {
class HttpPrinterSimulator;
}

enum class PrinterFault {
  None,
  ThermalRunaway,      // the extruder heater runs away upwards until the firmware shuts down
  LinkDrop,            // every connection closes and none is accepted for linkDropFor
  CancelledOnPrinter,  // the job is cancelled at the printer (its screen or another client)
  SlowReplies,         // every reply is held for slowReplyDelay
};

// "none", "thermal-runaway", "link-drop", "cancelled-on-printer", "slow-replies" (as the command line spells them).
const char* printerFaultName(PrinterFault fault);
// Errors: InvalidParameter listing the names.
core::Result<PrinterFault> parsePrinterFault(const std::string& name);

struct PrinterSimulatorOptions {
  std::string listenAddress = "127.0.0.1";  // an IPv4 address; anything but loopback only when asked for
  int port = 0;                             // 0: a free port chosen by the system
  double speed = 1.0;                       // simulated seconds per real second, (0, 100000]
  // A fault injected once, when a job's progress first reaches faultAtProgress (for demos; tests call the
  // injection methods directly).
  PrinterFault fault = PrinterFault::None;
  double faultAtProgress = 0.5;
  std::chrono::milliseconds linkDropFor{3000};
  std::chrono::milliseconds slowReplyDelay{3000};
  // The printer's rotary axes (simulated_axes.h): Moonraker takes manual steppers (--manual-stepper tilt,rotation),
  // OctoPrint G-code letters (--rotary-axes U,V); none by default.
  SimulatedRotaryAxes rotaryAxes;
  // The clock of the records and of the simulated time; the system's steady clock unless a test injects one.
  std::function<std::chrono::steady_clock::time_point()> steadyNow;
};

struct PrinterRequestRecord {
  std::chrono::steady_clock::time_point at;
  std::string method;  // "GET", "POST"
  std::string path;    // "/printer/print/start", "/api/job"
  std::string detail;  // the file name of an upload or a start, the command of a job or printer command
  int httpStatus = 0;
};

struct PrinterJobEvent {
  std::chrono::steady_clock::time_point at;
  // The simulated printer's job after the change: "printing", "paused", "complete", "cancelled", "error"
  // (Klipper's print_stats.state words, whichever protocol the simulator speaks).
  std::string state;
  std::string file;
};

struct SimulatedPrinterState {
  std::string jobState;       // as in PrinterJobEvent
  std::string firmwareState;  // "ready", or "shutdown" after an emergency stop or a heater fault
  std::string message;
  std::string file;
  double progress = 0.0;
  HeaterReading extruder;
  HeaterReading bed;
  std::vector<std::string> files;  // uploaded
};

class PrinterSimulator {
 public:
  virtual ~PrinterSimulator();
  PrinterSimulator(const PrinterSimulator&) = delete;
  PrinterSimulator& operator=(const PrinterSimulator&) = delete;

  // InvalidParameter for bad options; DeviceUnreachable when the address and port cannot be listened on.
  core::Status start();
  void stop();  // idempotent
  [[nodiscard]] int port() const;
  [[nodiscard]] std::string address() const;  // "127.0.0.1:40123"

  // Fault injection, now.
  void injectThermalRunaway();
  void cancelJobOnPrinter();
  // The printer restarts on its own (a power cycle, a firmware restart from its screen): its job is gone
  // (standby, no file, heaters off), the files uploaded to it stay.
  void restartPrinter();
  void dropLink();     // closes the listener and every connection until restoreLink()
  void restoreLink();  // listens again on the same port
  void setReplyDelay(std::chrono::milliseconds delay);

  // Observation.
  [[nodiscard]] std::vector<PrinterRequestRecord> requests() const;
  [[nodiscard]] std::vector<PrinterJobEvent> jobEvents() const;
  [[nodiscard]] SimulatedPrinterState state() const;
  // The current (or last) job's extrusions and turns with the rotary axes' coordinates (simulated_axes.h).
  [[nodiscard]] SimulatedAxisLog axisLog() const;

 protected:
  explicit PrinterSimulator(std::unique_ptr<sim::HttpPrinterSimulator> impl);

 private:
  std::unique_ptr<sim::HttpPrinterSimulator> m_impl;
};

}  // namespace multidir::hardware

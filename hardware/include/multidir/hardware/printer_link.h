#pragma once
// The printer as the print run sees it: upload a G-code file, start, pause, resume and cancel its job, stop it
// in an emergency, and read its state, progress, file and temperatures. One interface for every protocol
// (Moonraker: moonraker_link.h, OctoPrint: octoprint_link.h, Marlin: marlin_link.h; printer_url.h picks one
// from a URL); protocols are documented in docs/hardware.md with their sources.
//
// Thread model: a link owns a worker thread that polls the printer every pollInterval and runs the queued
// commands in order, and a second thread that only sends the emergency stop (so a slow status reply or an
// upload in flight never holds it up). Every public method may be called from any thread.
//
// Emergency stop: latched like the platform's stop (stop_latch.h): it cancels every queued command, is sent at
// once and resent (every stopRetryInterval) until the printer answered it, and every upload, start and resume
// is refused until clearStop(), which is refused until the printer confirmed the stop.
//
// Errors: InvalidParameter for a refused command (nothing sent), DeviceUnreachable when the printer did not
// answer (refused connection, timeout), DeviceFault when it answered with an error (the printer's own message
// quoted), Cancelled for commands cancelled by the emergency stop or disconnect().
#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/connection.h"
#include "multidir/hardware/stop_latch.h"

namespace multidir::hardware {

// The printer's job, in Klipper's print_stats.state words (OctoPrint's states are mapped onto them: see
// docs/hardware.md, "OctoPrint"). Unknown until the first good status read, and whenever the printer reports
// a word outside the protocol's documented set (the message names it): the print run then stops and asks.
enum class PrinterJobState { Unknown, Standby, Printing, Paused, Complete, Cancelled, Error };

// "unknown", "standby", "printing", "paused", "complete", "cancelled", "error".
const char* printerJobStateName(PrinterJobState state);

struct HeaterReading {
  double actualC = 0.0;  // degrees Celsius
  double targetC = 0.0;  // 0: heater off
};

struct PrinterStatus {
  LinkState link = LinkState::Disconnected;
  // No good status read for PrinterLinkOptions::linkLostAfter, as the last read failed or is still stuck (or
  // none yet since connect()): every value below
  // is the last one read and may be stale; the printer may still be printing on its own.
  bool linkLost = true;
  PrinterJobState state = PrinterJobState::Unknown;
  // "ready" when the printer takes jobs; else Klipper's webhooks.state ("startup", "shutdown", "error"),
  // OctoPrint's connection to the printer ("offline", "connecting", "error"), or Marlin's link "halted" once
  // Marlin stopped (kill, M112).
  std::string firmwareState;
  std::string message;      // the printer's own words: print_stats.message, or webhooks.state_message when the
                            // firmware is not ready; OctoPrint's error ("" when it says nothing)
  double progress = 0.0;    // 0..1 of the current file (virtual_sdcard.progress: bytes read / file size)
  std::string currentFile;  // print_stats.filename ("" when none)
  HeaterReading extruder;
  HeaterReading bed;
  std::uint64_t polls = 0;                            // good status reads since connect()
  std::chrono::steady_clock::time_point lastReply{};  // of the last good read (PrinterLinkOptions::steadyNow)
  std::string lastError;                              // the latest link or printer problem ("" after a good read)
  StopLatch stop;                                     // the emergency stop, when one is latched
  // Lines the link could not account for since connect() (Marlin: an ok that answers no line in flight, a line
  // that is not Marlin's protocol): how many, and the latest in words. The link went on without them.
  std::uint64_t protocolWarnings = 0;
  std::string lastWarning;

  [[nodiscard]] bool busy() const { return state == PrinterJobState::Printing || state == PrinterJobState::Paused; }
};

struct PrinterLinkOptions {
  std::chrono::milliseconds pollInterval{250};
  // Each request's total deadline: connect, send and the whole reply, however slowly it trickles in (an
  // upload's is uploadTimeout). Replies are limited to 1 MiB and 64 levels of JSON (docs/hardware.md).
  std::chrono::milliseconds requestTimeout{2000};
  std::chrono::milliseconds uploadTimeout{120000};
  std::chrono::milliseconds linkLostAfter{3000};     // no good status read this long: PrinterStatus::linkLost
  std::chrono::milliseconds stopRetryInterval{100};  // an unanswered emergency stop is resent this often
  // The clock of lastReply and linkLost; the system's steady clock unless a test injects one.
  std::function<std::chrono::steady_clock::time_point()> steadyNow;
};

// The extra axes a printer's firmware has, as it reports them (docs/hardware.md, "The printer's own axes").
struct FirmwareAxes {
  std::vector<std::string> letters;         // Marlin: the axes M114 reports beyond X, Y, Z and E ("U", "V")
  std::vector<std::string> manualSteppers;  // Klipper: NAME of each "manual_stepper NAME" object Moonraker lists
};

// Names the first option out of range (InvalidParameter).
core::Status validate(const PrinterLinkOptions& options);

class PrinterLink {
 public:
  virtual ~PrinterLink() = default;

  // Starts the worker threads and waits for the first status read. Done once read; otherwise its error,
  // and the worker keeps polling in the background (status().linkLost tells when it answers).
  virtual core::Status connect() = 0;
  // Stops the threads; queued commands end Cancelled. The printer is left as it is.
  virtual void disconnect() = 0;

  // Commands: each future ends once the printer answered (Done or its error). Refused at once while an
  // emergency stop is latched (upload, start, resume).
  // Sends `localPath` to the printer as `remoteName` (a plain file name, replaced when it exists). The file is
  // read once, into memory, and what is sent (uploaded, or streamed line by line by the Marlin link) is those
  // bytes. With `checkedSha256` (content_digest.h: the SHA-256 taken when the file was checked), bytes whose
  // SHA-256 differs are refused (InvalidParameter, "step-02.gcode changed after it was checked; nothing of it
  // was sent ..."), so a file replaced after its check is never printed; "": whatever the file holds is sent.
  virtual std::future<core::Status> upload(const std::string& localPath, const std::string& remoteName,
                                           const std::string& checkedSha256) = 0;
  std::future<core::Status> upload(const std::string& localPath, const std::string& remoteName) {
    return upload(localPath, remoteName, std::string());
  }
  virtual std::future<core::Status> startPrint(const std::string& remoteName) = 0;
  virtual std::future<core::Status> pausePrint() = 0;
  virtual std::future<core::Status> resumePrint() = 0;
  virtual std::future<core::Status> cancelPrint() = 0;
  // Sets every heater's target to 0 (Moonraker: Klipper's TURN_OFF_HEATERS; OctoPrint and Marlin: M104 S0 and
  // M140 S0), whatever the job; queued behind the commands before it (after a cancel, once it was answered).
  // Not refused while an emergency stop is latched (the stop already switches a Klipper or Marlin printer's
  // heaters off; this then fails in the printer's words).
  virtual std::future<core::Status> switchHeatersOff() = 0;
  // Latched (see above); the future ends once the printer answered it.
  virtual std::future<core::Status> emergencyStop() = 0;
  // The operator allows uploads and starts again; refused until the printer confirmed the stop. A Klipper
  // printer also needs a FIRMWARE_RESTART after its emergency stop (firmwareState "shutdown"); behind
  // OctoPrint, a reset of the printer and a Connect in OctoPrint (firmwareState "error").
  virtual core::Status clearStop() = 0;

  // Brings the printer's firmware back after an emergency stop shut it down, once the operator confirmed it is
  // safe: Moonraker POST /printer/firmware_restart (Klipper's FIRMWARE_RESTART, firmwareState "shutdown" ->
  // "ready"); OctoPrint POST /api/connection {"command": "connect"} (opening the serial port resets the
  // printer's board, firmwareState "error" -> "ready"). Not refused while an emergency stop is latched: it
  // starts no job, and the latch still holds uploads and starts until clearStop(). Marlin halted by M112 (kill())
  // answers nothing on its serial line until its reset button or a power cycle: the default answers
  // InvalidParameter saying so.
  virtual std::future<core::Status> restartFirmware();

  // Asks the printer which extra axes its firmware has, for the checks before a program that turns them:
  // Moonraker lists Klipper's objects (GET /printer/objects/list); Marlin answers M114 (asked between jobs; the
  // answer's letters beyond X Y Z E). OctoPrint relays no firmware reply to its API clients, so it cannot be
  // asked: the default answers InvalidParameter saying so.
  virtual std::future<core::Result<FirmwareAxes>> readFirmwareAxes();
  [[nodiscard]] virtual PrinterStatus status() const = 0;
  // "Moonraker printer at 127.0.0.1:7125", "OctoPrint printer at 192.168.0.21:80".
  [[nodiscard]] virtual std::string name() const = 0;
};

}  // namespace multidir::hardware

#pragma once
// Marlin's host protocol, shared by the link and the simulator: what a G-code file line sends, and what a
// line the printer writes means (docs/hardware.md, "Marlin (USB serial)").
#include <optional>
#include <string>

#include "multidir/hardware/printer_link.h"

namespace multidir::hardware::marlin {

// The command a file line sends: comment (';' to the end) and surrounding blanks removed; "" for nothing.
std::string commandOf(const std::string& fileLine);

struct Reply {
  enum class Kind {
    Ok,         // "ok", "ok T:...", "ok N12 P15 B3" (ADVANCED_OK)
    Resend,     // "Resend: 12" / "rs 12": send again from line `resendLine`
    LineError,  // "Error:checksum mismatch, Last Line: 11" and the other transmission errors (a Resend follows)
    Fault,      // any other "Error:..." line: Marlin stops ("Thermal Runaway, system stopped!", "kill() called")
    Busy,       // "echo:busy: processing" / "busy: paused for user": alive, still working
    Action,     // "//action:cancel", "//action:pause", "//action:resume" (host action commands)
    Position,   // M114's report: "X:10.00 Y:20.00 Z:0.30 E:0.00 Count X:800 Y:1600 Z:120"
    Info,       // other lines Marlin writes: "start", "echo:...", "//...", temperature reports ("T:210.0 /210.0
                // B:60.0 /60.0", "T:... W:?"), "wait", "Not SD printing", M115's "FIRMWARE_NAME:..." and "Cap:..."
    Unknown,    // not Marlin's protocol: line noise, a wrong baud rate, another device on the port
  };
  Kind kind = Kind::Unknown;
  long resendLine = -1;
  // Ok with ADVANCED_OK: the number of the line it answers ("ok N12 P15 B3"); -1 without.
  long okLine = -1;
  std::string text;                       // Fault: the printer's words after "Error:"; Action: "cancel", "pause", ...
  bool killed = false;                    // the line says Marlin halted ("Printer halted", "kill() called")
  std::optional<HeaterReading> extruder;  // from "T:210.0 /210.0" in an ok or Info line (never from Unknown)
  std::optional<HeaterReading> bed;       // from "B:60.0 /60.0"
};

Reply parseReply(const std::string& line);

// `line` as a message may quote it: at most 60 characters, bytes outside printable ASCII as '?'.
std::string quoted(const std::string& line);

}  // namespace multidir::hardware::marlin

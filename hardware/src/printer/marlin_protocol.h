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
    Other,      // "start", "echo:...", temperature auto-reports, anything else
  };
  Kind kind = Kind::Other;
  long resendLine = -1;
  std::string text;                       // Fault: the printer's words after "Error:"; Action: "cancel", "pause", ...
  bool killed = false;                    // the line says Marlin halted ("Printer halted", "kill() called")
  std::optional<HeaterReading> extruder;  // from "T:210.0 /210.0" anywhere in the line
  std::optional<HeaterReading> bed;       // from "B:60.0 /60.0"
};

Reply parseReply(const std::string& line);

}  // namespace multidir::hardware::marlin

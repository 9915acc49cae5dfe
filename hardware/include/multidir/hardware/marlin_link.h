#pragma once
// The printer link for Marlin over USB serial (docs/hardware.md, "Marlin (USB serial)"). There is no file
// upload: upload() reads the G-code into memory (comments and blank lines stripped), startPrint() streams it
// line by line as `N<n> <command>*<checksum>`, at most `maxUnacknowledgedLines` lines ahead of the printer's
// `ok`s, and re-sends from line n when the printer asks `Resend: n`. Between lines the link polls `M105`
// (Marlin answers `ok T:210.0 /210.0 B:60.0 /60.0`); the end of the file is followed by `M400` and `M114`, whose
// position report proves the last move done (job complete): an `ok` that answers no line in flight is a protocol
// warning, never the end of a job. Only lines of Marlin's protocol count as answers, and only status reads
// (temperatures, position, busy) keep the status fresh (docs/hardware.md). The emergency stop is `M112`,
// written by the stop thread outside the line numbering (Marlin's emergency parser acts on it at once) and
// re-sent until the printer reports its kill ("Error:Printer halted. kill() called!").
//
// URL and rates: marlin_url.cpp. POSIX termios on the device (raw, 8N1, no flow control), no other library.
// Linux only for the rates that are not termios constants (250000: set with termios2).
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"

namespace multidir::hardware {

struct MarlinSettings {
  std::string devicePath = "/dev/ttyACM0";  // the printer's USB serial device (or a pseudo-terminal)
  int baud = 115200;                        // one of marlinBaudRates(); Marlin's BAUDRATE
  // Lines sent ahead of the printer's oks. 1 (the default) is what every host does safely; Marlin's command
  // buffer (BUFSIZE) holds 4.
  int maxUnacknowledgedLines = 1;
};

// The rates the link can set: the termios rates from 9600 to 1000000 and Marlin's 250000.
const std::vector<int>& marlinBaudRates();

// "serial:///dev/ttyACM0" or "serial:///dev/ttyACM0?baud=250000". Errors: InvalidParameter naming what is
// wrong (no path, a relative path, an unknown option, a rate not in marlinBaudRates()).
core::Result<MarlinSettings> parseMarlinUrl(const std::string& url);

// InvalidParameter for bad settings or options (nothing opened).
core::Result<std::unique_ptr<PrinterLink>> makeMarlinLink(const MarlinSettings& settings,
                                                          const PrinterLinkOptions& options = {});

// Marlin's line checksum: the XOR of every byte of `text` ("N12 G1 X5"), 0..255.
int marlinChecksum(const std::string& text);
// "N12 G1 X5*<checksum>" (no line end).
std::string marlinNumberedLine(long number, const std::string& command);

}  // namespace multidir::hardware

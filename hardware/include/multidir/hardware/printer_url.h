#pragma once
// One --printer URL to the printer link it names (docs/hardware.md, "Printer link"):
//   http://HOST[:PORT], HOST[:PORT]    Moonraker (Klipper): port 80 with http://, else 7125
//   moonraker://HOST[:PORT]            Moonraker, port 7125 unless given
//   serial:///dev/ttyACM0[?baud=N]     Marlin over USB serial (baud 115200 unless given)
#include <memory>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"

namespace multidir::hardware {

// The scheme of `url` ("http", "serial", ...), "" when it has none (a bare HOST:PORT).
std::string printerUrlScheme(const std::string& url);

// `apiKey` is used by the protocols that have one (Moonraker's X-Api-Key). Errors: InvalidParameter naming
// what is wrong, or an unknown scheme with the ones this version knows.
core::Result<std::unique_ptr<PrinterLink>> makePrinterLinkFromUrl(const std::string& url, const std::string& apiKey,
                                                                  const PrinterLinkOptions& options = {});

}  // namespace multidir::hardware

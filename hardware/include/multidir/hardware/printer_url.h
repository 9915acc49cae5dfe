#pragma once
// One printer address for every protocol, as `multidir run --printer URL` takes it (docs/hardware.md):
//   http://HOST[:PORT], HOST[:PORT], moonraker://HOST[:PORT]   Klipper through Moonraker (moonraker_link.h)
//   octoprint://HOST[:PORT]                                    OctoPrint (octoprint_link.h; needs the API key)
//   serial:///dev/ttyACM0[?baud=N]                             Marlin over USB serial (marlin_link.h)
#include <memory>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"

namespace multidir::hardware {

// The URL's protocol: "moonraker" (http://, moonraker:// and a bare HOST:PORT), "octoprint" or "serial".
// Errors: InvalidParameter for an unknown scheme, naming the ones there are.
core::Result<std::string> printerUrlScheme(const std::string& url);

// The link the URL names (not connected yet). `apiKey`: Moonraker's (optional) or OctoPrint's (required);
// a serial printer has none. Errors: InvalidParameter naming what is wrong with the URL, the key or the options.
core::Result<std::unique_ptr<PrinterLink>> makePrinterLinkFromUrl(const std::string& url, const std::string& apiKey,
                                                                  const PrinterLinkOptions& options = {});

}  // namespace multidir::hardware

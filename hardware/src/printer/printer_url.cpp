#include "multidir/hardware/printer_url.h"

#include "multidir/hardware/marlin_link.h"
#include "multidir/hardware/moonraker_link.h"

namespace multidir::hardware {

std::string printerUrlScheme(const std::string& url) {
  const std::size_t colon = url.find("://");
  return colon == std::string::npos ? std::string() : url.substr(0, colon);
}

core::Result<std::unique_ptr<PrinterLink>> makePrinterLinkFromUrl(const std::string& url, const std::string& apiKey,
                                                                  const PrinterLinkOptions& options) {
  const std::string scheme = printerUrlScheme(url);
  // One branch per protocol; each parser names what is wrong in its own kind of address.
  if (scheme.empty() || scheme == "http" || scheme == "https" || scheme == "moonraker") {
    core::Result<MoonrakerSettings> settings =
        parseMoonrakerUrl(scheme == "moonraker" ? url.substr(std::string("moonraker://").size()) : url);
    if (!settings) return settings.error();
    settings->apiKey = apiKey;
    return makeMoonrakerLink(*settings, options);
  }
  if (scheme == "serial") {
    core::Result<MarlinSettings> settings = parseMarlinUrl(url);
    if (!settings) return settings.error();
    return makeMarlinLink(*settings, options);
  }
  return core::Error{core::ErrorCode::InvalidParameter,
                     "'" + url + "': unknown scheme '" + scheme +
                         "://', use one of http://HOST:PORT or moonraker://HOST:PORT (Klipper through Moonraker), "
                         "serial:///dev/ttyACM0?baud=115200 (Marlin over USB)",
                     "--printer"};
}

}  // namespace multidir::hardware

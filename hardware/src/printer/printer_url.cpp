#include "multidir/hardware/printer_url.h"

#include "multidir/hardware/marlin_link.h"
#include "multidir/hardware/moonraker_link.h"
#include "multidir/hardware/octoprint_link.h"

namespace multidir::hardware {

core::Result<std::string> printerUrlScheme(const std::string& url) {
  const std::size_t separator = url.find("://");
  if (separator == std::string::npos) return std::string("moonraker");
  const std::string scheme = url.substr(0, separator);
  // https is Moonraker's so that its parser can say that https is not supported.
  if (scheme == "http" || scheme == "https" || scheme == "moonraker") return std::string("moonraker");
  if (scheme == "octoprint" || scheme == "serial") return scheme;
  return core::Error{core::ErrorCode::InvalidParameter,
                     "'" + url + "': unknown printer scheme '" + scheme +
                         "://'; use one of http://HOST:PORT or moonraker://HOST:PORT (Klipper through Moonraker), "
                         "octoprint://HOST:PORT (OctoPrint), serial:///dev/ttyACM0?baud=115200 (Marlin over USB)",
                     "--printer"};
}

core::Result<std::unique_ptr<PrinterLink>> makePrinterLinkFromUrl(const std::string& url, const std::string& apiKey,
                                                                  const PrinterLinkOptions& options) {
  const core::Result<std::string> scheme = printerUrlScheme(url);
  if (!scheme) return scheme.error();
  // One case per protocol; each parser names what is wrong in its own kind of address.
  if (*scheme == "octoprint") {
    core::Result<OctoPrintSettings> settings = parseOctoPrintUrl(url);
    if (!settings) return settings.error();
    settings->apiKey = apiKey;
    return makeOctoPrintLink(*settings, options);
  }
  if (*scheme == "serial") {
    core::Result<MarlinSettings> settings = parseMarlinUrl(url);
    if (!settings) return settings.error();
    return makeMarlinLink(*settings, options);
  }
  core::Result<MoonrakerSettings> settings = parseMoonrakerUrl(url);
  if (!settings) return settings.error();
  settings->apiKey = apiKey;
  return makeMoonrakerLink(*settings, options);
}

}  // namespace multidir::hardware

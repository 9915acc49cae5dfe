#include "multidir/hardware/printer_url.h"

#include "multidir/hardware/moonraker_link.h"

namespace multidir::hardware {

core::Result<std::unique_ptr<PrinterLink>> makePrinterLinkFromUrl(const std::string& url, const std::string& apiKey,
                                                                  const PrinterLinkOptions& options) {
  const std::string::size_type scheme = url.find("://");
  const std::string kind = scheme == std::string::npos ? std::string() : url.substr(0, scheme);
  if (kind.empty() || kind == "http" || kind == "https") {  // Moonraker's parser explains why not https
    core::Result<MoonrakerSettings> settings = parseMoonrakerUrl(url);
    if (!settings) return settings.error();
    settings->apiKey = apiKey;
    return makeMoonrakerLink(*settings, options);
  }
  return core::Error{core::ErrorCode::InvalidParameter,
                     "the printer address '" + url + "' starts with '" + kind +
                         "://', which MultiDir does not speak: use http://HOST:PORT or HOST:PORT (Moonraker)",
                     "printer address"};
}

}  // namespace multidir::hardware

// The serial:// printer address and the rates the link can set (docs/hardware.md, "Marlin (USB serial)").
#include <algorithm>
#include <string>
#include <vector>

#include "multidir/hardware/marlin_link.h"
#include "printer/serial_port.h"

namespace multidir::hardware {
namespace {

core::Error invalid(const std::string& what, const std::string& where) {
  return core::Error{core::ErrorCode::InvalidParameter, what, where};
}

}  // namespace

const std::vector<int>& marlinBaudRates() {
  static const std::vector<int> rates = {9600,   19200,  38400,  57600,  115200, 230400,
                                         250000, 460800, 500000, 576000, 921600, 1000000};
  return rates;
}

core::Result<MarlinSettings> parseMarlinUrl(const std::string& url) {
  const std::string scheme = "serial://";
  if (url.rfind(scheme, 0) != 0)
    return invalid("'" + url + "' is not a serial address: use serial:///dev/ttyACM0[?baud=115200]", "--printer");
  std::string rest = url.substr(scheme.size());
  MarlinSettings settings;
  std::string query;
  if (const std::size_t q = rest.find('?'); q != std::string::npos) {
    query = rest.substr(q + 1);
    rest.resize(q);
  }
  if (rest.empty() || rest[0] != '/')
    return invalid("'" + url + "' names no absolute device path: use serial:///dev/ttyACM0 (three slashes)",
                   "--printer");
  settings.devicePath = rest;
  std::size_t begin = 0;
  while (begin < query.size()) {
    std::size_t end = query.find('&', begin);
    if (end == std::string::npos) end = query.size();
    const std::string pair = query.substr(begin, end - begin);
    begin = end + 1;
    const std::size_t eq = pair.find('=');
    const std::string key = pair.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : pair.substr(eq + 1);
    const bool digits = !value.empty() && value.size() <= 8 &&
                        std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (key == "baud") {
      if (!digits || !serial::supportedRate(std::stoi(value)))
        return invalid("'" + url +
                           "': baud must be one of 9600, 19200, 38400, 57600, 115200, 230400, 250000, "
                           "460800, 500000, 576000, 921600, 1000000 (Marlin's BAUDRATE)",
                       "--printer");
      settings.baud = std::stoi(value);
    } else if (key == "window") {
      if (!digits || std::stoi(value) < 1 || std::stoi(value) > 4)
        return invalid("'" + url + "': window must be 1 to 4 lines (Marlin's command buffer)", "--printer");
      settings.maxUnacknowledgedLines = std::stoi(value);
    } else {
      return invalid("'" + url + "': unknown option '" + key + "' (known: baud, window)", "--printer");
    }
  }
  return settings;
}

}  // namespace multidir::hardware

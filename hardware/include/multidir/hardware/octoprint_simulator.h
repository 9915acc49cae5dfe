#pragma once
// An OctoPrint server in front of a simulated printer (printer_simulator.h; the printer behaves as Marlin does
// behind OctoPrint), for tests, demos and `multidir simulate --printer octoprint`: the endpoints OctoPrintLink
// uses with OctoPrint's request and reply shapes (docs/hardware.md, "OctoPrint"), plus GET /api/version and
// GET/POST /api/connection (reconnecting to the printer after an emergency stop or a firmware error).
// Every request must carry the API key (X-Api-Key, "Authorization: Bearer KEY" or ?apikey=KEY); without it,
// or with another key, OctoPrint's answer for an anonymous request: 403 Forbidden.
#include <string>

#include "multidir/hardware/printer_simulator.h"

namespace multidir::hardware {

// The simulator's key unless told otherwise (printed by `multidir simulate --printer octoprint`).
inline constexpr const char* kOctoPrintSimulatorApiKey = "MULTIDIR-SIMULATED-OCTOPRINT-KEY";

struct OctoPrintSimulatorOptions : PrinterSimulatorOptions {
  std::string apiKey = kOctoPrintSimulatorApiKey;  // not empty
};

class OctoPrintSimulator : public PrinterSimulator {
 public:
  explicit OctoPrintSimulator(OctoPrintSimulatorOptions options = {});
  [[nodiscard]] const std::string& apiKey() const { return m_apiKey; }

 private:
  std::string m_apiKey;
};

}  // namespace multidir::hardware

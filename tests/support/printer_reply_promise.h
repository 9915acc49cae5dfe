#pragma once
// What the HTTP printers' reply readers promise for any bytes a server sends (header-only: shared by the
// corpus replay test and the libFuzzer harness): parsed with the links' bounded parser and read as Moonraker's
// status and OctoPrint's job and printer replies, each either refuses with a message or gives a reading whose
// numbers a printer can report (temperatures a sensor reads, progress in [0, 1]). Returns an empty string when the promise holds, else what broke it.
#include <cmath>
#include <string>

#include "printer/moonraker_status.h"
#include "printer/octoprint_status.h"
#include "printer/plausible_reading.h"
#include "printer/reply_json.h"
#include "support/refusal_promise.h"

namespace multidir::test {

inline std::string brokenHeaterPromise(const hardware::HeaterReading& heater) {
  return hardware::plausibleCelsius(heater.actualC) && hardware::plausibleCelsius(heater.targetC)
             ? std::string()
             : "read a temperature no heater's sensor reports";
}

inline std::string brokenPrinterReplyPromise(const std::string& text) {
  const auto parsed = hardware::parseReplyJson(text, "GET /fuzz", "", "fuzzed printer");
  if (!parsed) return parsed.error().message.empty() ? "refused without a message" : std::string();
  const auto moonraker = hardware::readMoonrakerStatus(*parsed, "fuzzed printer");
  if (!moonraker) {
    if (moonraker.error().message.empty()) return "Moonraker status refused without a message";
  } else {
    if (!(std::isfinite(moonraker->progress) && moonraker->progress >= 0 && moonraker->progress <= 1))
      return "read a Moonraker progress outside [0, 1]";
    if (auto broken = brokenHeaterPromise(moonraker->extruder); !broken.empty()) return broken;
    if (auto broken = brokenHeaterPromise(moonraker->bed); !broken.empty()) return broken;
  }
  const auto job = hardware::readOctoPrintJob(*parsed, "fuzzed printer");
  if (!job) {
    if (job.error().message.empty()) return "OctoPrint job refused without a message";
  } else if (job->completion && !(*job->completion >= 0 && *job->completion <= 100)) {
    return "read an OctoPrint completion outside [0, 100] %";
  }
  const auto printer = hardware::readOctoPrintPrinter(*parsed, "fuzzed printer");
  if (!printer) {
    if (printer.error().message.empty()) return "OctoPrint printer refused without a message";
  } else {
    if (auto broken = brokenHeaterPromise(printer->tool0); !broken.empty()) return broken;
    if (auto broken = brokenHeaterPromise(printer->bed); !broken.empty()) return broken;
  }
  return {};
}

}  // namespace multidir::test

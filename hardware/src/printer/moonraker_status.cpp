#include "printer/moonraker_status.h"

#include <algorithm>
#include <utility>

#include "printable_text.h"
#include "printer/plausible_reading.h"

namespace multidir::hardware {
namespace {

double number(const nlohmann::json& object, const char* key) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number()) return 0.0;
  return object[key].get<double>();
}

std::string text(const nlohmann::json& object, const char* key) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_string()) return {};
  return object[key].get<std::string>();
}

core::Result<HeaterReading> heater(const nlohmann::json& status, const char* name, const std::string& printer) {
  HeaterReading reading;
  if (!status.contains(name)) return reading;
  reading.actualC = number(status[name], "temperature");
  reading.targetC = number(status[name], "target");
  for (const auto& [field, value] : {std::pair{".temperature", reading.actualC}, std::pair{".target", reading.targetC}})
    if (!plausibleCelsius(value))
      return core::Error{core::ErrorCode::DeviceFault, implausibleCelsiusMessage(name + std::string(field), value),
                         printer};
  return reading;
}

}  // namespace

PrinterJobState parsePrinterJobState(const std::string& t) {
  if (t == "standby") return PrinterJobState::Standby;
  if (t == "printing") return PrinterJobState::Printing;
  if (t == "paused") return PrinterJobState::Paused;
  if (t == "complete") return PrinterJobState::Complete;
  if (t == "cancelled") return PrinterJobState::Cancelled;
  if (t == "error") return PrinterJobState::Error;
  return PrinterJobState::Unknown;
}

core::Result<PrinterReading> readMoonrakerStatus(const nlohmann::json& result, const std::string& printer) {
  if (!result.is_object() || !result.contains("status") || !result["status"].is_object() ||
      !result["status"].contains("print_stats") || text(result["status"]["print_stats"], "state").empty())
    return core::Error{core::ErrorCode::DeviceFault,
                       "the status reply has no status.print_stats.state: is this Klipper's Moonraker, with "
                       "[virtual_sdcard] in printer.cfg?",
                       printer};
  const nlohmann::json& status = result["status"];
  PrinterReading r;
  const std::string state = text(status["print_stats"], "state");
  r.state = parsePrinterJobState(state);
  r.currentFile = text(status["print_stats"], "filename");
  r.message = text(status["print_stats"], "message");
  // A word outside the documented set: the run stops and asks (it never takes it for an idle printer).
  if (r.state == PrinterJobState::Unknown)
    r.message = "Moonraker's print_stats.state '" + escapeControls(state) +
                "' is not one MultiDir knows (standby, printing, paused, complete, cancelled, error)";
  if (status.contains("webhooks")) {
    r.firmwareState = text(status["webhooks"], "state");
    if (r.firmwareState != "ready" && !text(status["webhooks"], "state_message").empty())
      r.message = text(status["webhooks"], "state_message");
  }
  // A fraction of the file: anything outside [0, 1] is a broken server's, never shown as more than done.
  if (status.contains("virtual_sdcard")) r.progress = std::clamp(number(status["virtual_sdcard"], "progress"), 0.0, 1.0);
  const auto extruder = heater(status, "extruder", printer);
  if (!extruder) return extruder.error();
  const auto bed = heater(status, "heater_bed", printer);
  if (!bed) return bed.error();
  r.extruder = *extruder;
  r.bed = *bed;
  return r;
}

}  // namespace multidir::hardware

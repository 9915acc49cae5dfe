#include "printer/moonraker_status.h"

#include "printable_text.h"

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

HeaterReading heater(const nlohmann::json& status, const char* name) {
  HeaterReading reading;
  if (!status.contains(name)) return reading;
  reading.actualC = number(status[name], "temperature");
  reading.targetC = number(status[name], "target");
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
  if (status.contains("virtual_sdcard")) r.progress = number(status["virtual_sdcard"], "progress");
  r.extruder = heater(status, "extruder");
  r.bed = heater(status, "heater_bed");
  return r;
}

}  // namespace multidir::hardware

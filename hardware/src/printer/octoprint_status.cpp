#include "printer/octoprint_status.h"

#include <algorithm>
#include <utility>

#include "printable_text.h"
#include "printer/plausible_reading.h"

namespace multidir::hardware {
namespace {

using Json = nlohmann::json;

std::string text(const Json& object, const char* key) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_string()) return {};
  return object[key].get<std::string>();
}

bool flag(const Json& flags, const char* key) {
  return flags.contains(key) && flags[key].is_boolean() && flags[key].get<bool>();
}

HeaterReading heater(const Json& temperature, const char* name) {
  HeaterReading reading;
  if (!temperature.is_object() || !temperature.contains(name) || !temperature[name].is_object()) return reading;
  const Json& h = temperature[name];
  if (h.contains("actual") && h["actual"].is_number()) reading.actualC = h["actual"].get<double>();
  if (h.contains("target") && h["target"].is_number()) reading.targetC = h["target"].get<double>();
  return reading;
}

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

enum class Kind { Active, Paused, Operational, Error, Offline, Connecting, Unknown };

// OctoPrint's state strings (comm.py, MachineCom.getStateString): anything printing or about to (starting,
// finishing, pausing, resuming, cancelling, SD transfers) keeps the job active.
Kind kindOf(const std::string& state) {
  if (state == "Paused") return Kind::Paused;
  if (state == "Operational") return Kind::Operational;
  if (startsWith(state, "Error") || startsWith(state, "Offline after error") || startsWith(state, "Offline (Error"))
    return Kind::Error;
  if (state == "Offline" || state == "Closed") return Kind::Offline;
  if (startsWith(state, "Opening") || startsWith(state, "Detecting") || startsWith(state, "Connecting") ||
      state == "Reconnecting")
    return Kind::Connecting;
  static const char* const kActive[] = {"Printing",   "Pausing",  "Resuming",           "Finishing",
                                        "Cancelling", "Starting", "Sending file to SD", "Transferring file to SD"};
  for (const char* active : kActive)
    if (startsWith(state, active)) return Kind::Active;
  // A word outside the table (OctoPrint's own "Unknown" among them): the run stops and asks; it never takes
  // it for an idle printer.
  return Kind::Unknown;
}

}  // namespace

core::Result<OctoPrintJobReading> readOctoPrintJob(const Json& reply, const std::string& printer) {
  if (!reply.is_object() || text(reply, "state").empty())
    return core::Error{core::ErrorCode::DeviceFault,
                       "the reply to GET /api/job has no \"state\": is this OctoPrint's address?", printer};
  OctoPrintJobReading r;
  r.stateText = text(reply, "state");
  r.error = text(reply, "error");
  if (reply.contains("job") && reply["job"].is_object() && reply["job"].contains("file"))
    r.file = text(reply["job"]["file"], "name");
  if (reply.contains("progress") && reply["progress"].is_object() && reply["progress"].contains("completion") &&
      reply["progress"]["completion"].is_number())
    // A percentage: a broken server's 1e308 is never shown as more than done.
    r.completion = std::clamp(reply["progress"]["completion"].get<double>(), 0.0, 100.0);
  return r;
}

core::Result<OctoPrintPrinterReading> readOctoPrintPrinter(const Json& reply, const std::string& printer) {
  if (!reply.is_object() || !reply.contains("state") || !reply["state"].is_object() ||
      !reply["state"].contains("flags") || !reply["state"]["flags"].is_object())
    return core::Error{core::ErrorCode::DeviceFault,
                       "the reply to GET /api/printer has no state.flags: is this OctoPrint's address?", printer};
  const Json& flags = reply["state"]["flags"];
  OctoPrintPrinterReading r;
  r.operational = flag(flags, "operational");
  r.error = flag(flags, "error");
  if (reply.contains("temperature")) {
    r.tool0 = heater(reply["temperature"], "tool0");
    r.bed = heater(reply["temperature"], "bed");
    for (const auto& [field, value] :
         {std::pair{"temperature.tool0.actual", r.tool0.actualC}, std::pair{"temperature.tool0.target", r.tool0.targetC},
          std::pair{"temperature.bed.actual", r.bed.actualC}, std::pair{"temperature.bed.target", r.bed.targetC}})
      if (!plausibleCelsius(value))
        return core::Error{core::ErrorCode::DeviceFault, implausibleCelsiusMessage(field, value), printer};
  }
  return r;
}

PrinterReading OctoPrintJobTracker::read(const OctoPrintJobReading& job, const OctoPrintPrinterReading* printer) {
  if (printer != nullptr) {
    m_tool0 = printer->tool0;
    m_bed = printer->bed;
  }
  PrinterReading r;
  r.currentFile = job.file;
  r.progress = std::clamp(job.completion.value_or(0.0) / 100.0, 0.0, 1.0);
  r.extruder = m_tool0;
  r.bed = m_bed;
  Kind kind = kindOf(job.stateText);
  if (printer != nullptr && printer->error) kind = Kind::Error;
  switch (kind) {
    case Kind::Active:
    case Kind::Paused:
      r.state = kind == Kind::Paused ? PrinterJobState::Paused : PrinterJobState::Printing;
      r.firmwareState = "ready";
      m_activeFile = job.file;
      if (m_endedFile == job.file) m_endedFile.clear();
      return r;
    case Kind::Error:
      r.state = PrinterJobState::Error;
      r.firmwareState = "error";
      r.message = job.error.empty() ? job.stateText : job.error;
      m_activeFile.clear();
      m_endedFile = job.file;
      m_ended = PrinterJobState::Error;
      return r;
    case Kind::Offline:
    case Kind::Connecting:
      // No job can run through OctoPrint while it has no connection to the printer.
      r.state = PrinterJobState::Standby;
      r.firmwareState = kind == Kind::Offline ? "offline" : "connecting";
      r.message = "OctoPrint is not connected to the printer (" + job.stateText +
                  "): connect it in OctoPrint's Connection panel";
      m_activeFile.clear();
      return r;
    case Kind::Unknown:
      r.state = PrinterJobState::Unknown;
      r.firmwareState = "unknown";
      r.message = "OctoPrint's state '" + escapeControls(job.stateText) + "' is not one MultiDir knows";
      return r;  // the job seen active stays so: nothing tells that it ended
    case Kind::Operational:
      break;
  }
  r.firmwareState = "ready";
  r.message = job.error;
  if (!job.file.empty() && job.completion && *job.completion >= 100.0) {
    r.state = PrinterJobState::Complete;
  } else if (!job.file.empty() && job.file == m_activeFile) {
    r.state = PrinterJobState::Cancelled;
  } else if (!job.file.empty() && job.file == m_endedFile && m_ended == PrinterJobState::Cancelled) {
    r.state = PrinterJobState::Cancelled;
  } else {
    r.state = PrinterJobState::Standby;
  }
  if (r.state == PrinterJobState::Complete || r.state == PrinterJobState::Cancelled) {
    m_activeFile.clear();
    m_endedFile = job.file;
    m_ended = r.state;
  }
  return r;
}

}  // namespace multidir::hardware

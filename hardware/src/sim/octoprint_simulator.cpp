// OctoPrint's REST API in front of SimulatedPrinter (a Marlin printer on OctoPrint's serial connection); the
// server, records and faults are HttpPrinterSimulator's. Reply shapes and status codes as docs.octoprint.org
// documents them ("REST API": General information, File operations, Job operations, Printer operations,
// Connection handling).
#include "multidir/hardware/octoprint_simulator.h"

#include <nlohmann/json.hpp>

#include "sim/http_printer_simulator.h"

namespace multidir::hardware {
namespace {

using Json = nlohmann::json;
using sim::replyJson;

constexpr int kNoContent = 204;
// What OctoPrint says when it sends M112 itself and closes the serial port (comm.py).
constexpr const char* kEmergencyStopClose = "Closing serial port due to emergency stop M112.";

void replyError(httplib::Response& res, int status, const std::string& message) {
  replyJson(res, status, Json{{"error", message}});
}

void noContent(httplib::Response& res) { res.status = kNoContent; }

bool isGcodeName(const std::string& name) {
  for (const char* ending : {".gcode", ".gco", ".g"})
    if (name.size() > std::string(ending).size() &&
        name.compare(name.size() - std::string(ending).size(), std::string::npos, ending) == 0)
      return true;
  return false;
}

// The printer behind OctoPrint is a Marlin: its rotary axes are G-code letters.
sim::SimulatedPrinterSettings marlin(const SimulatedRotaryAxes& axes) {
  sim::SimulatedPrinterSettings settings;
  settings.overTemperatureShutdown = "MAXTEMP triggered, system stopped! Heater_ID: 0";
  settings.axes = {sim::RotaryAxisSetup::Firmware::Marlin, axes.letters};
  return settings;
}

class OctoPrintServer : public sim::HttpPrinterSimulator {
 public:
  explicit OctoPrintServer(OctoPrintSimulatorOptions options)
      : HttpPrinterSimulator(options, marlin(options.rotaryAxes)), m_apiKey(std::move(options.apiKey)) {}
  ~OctoPrintServer() override { stop(); }

 protected:
  core::Status validateOwnOptions() const override {
    if (m_apiKey.empty())
      return core::Error{core::ErrorCode::InvalidParameter, "the simulated OctoPrint needs an API key", "--api-key"};
    if (!m_options.rotaryAxes.manualSteppers.empty())
      return core::Error{core::ErrorCode::InvalidParameter,
                         "the printer behind OctoPrint is a Marlin, which has rotary axes as G-code letters, not "
                         "Klipper's manual steppers: give --rotary-axes",
                         "--manual-stepper"};
    return core::Done{};
  }

  // OctoPrint treats a request without a valid key as anonymous, and anonymous API requests get 403.
  bool authorized(const httplib::Request& req, httplib::Response& res) override {
    const std::string bearer = req.get_header_value("Authorization");
    if (req.get_header_value("X-Api-Key") == m_apiKey || bearer == "Bearer " + m_apiKey ||
        req.get_param_value("apikey") == m_apiKey)
      return true;
    replyError(res, 403,
               "You don't have the permission to access the requested resource. It is either read-protected or not "
               "readable by the server.");
    return false;
  }

  void configure(httplib::Server& server) override {
    using Request = httplib::Request;
    using Response = httplib::Response;
    server.Get("/api/version", handled("GET", [](const Request&, Response& res, std::string&) {
                 replyJson(res, 200, Json{{"api", "0.1"}, {"server", "1.10.2"}, {"text", "OctoPrint (simulated)"}});
               }));
    server.Get("/api/job", handled("GET", [this](const Request&, Response& res, std::string&) { job(res); }));
    server.Post("/api/job", handled("POST", [this](const Request& req, Response& res, std::string& detail) {
                  jobCommand(req, res, detail);
                }));
    server.Get("/api/printer", handled("GET", [this](const Request&, Response& res, std::string&) { printer(res); }));
    server.Post("/api/printer/command", handled("POST", [this](const Request& req, Response& res, std::string& detail) {
                  printerCommand(req, res, detail);
                }));
    server.Post("/api/files/local", handled("POST", [this](const Request& req, Response& res, std::string& detail) {
                  upload(req, res, detail);
                }));
    server.Post(R"(/api/files/local/([^/]+))",
                handled("POST", [this](const Request& req, Response& res, std::string& detail) {
                  fileCommand(req, res, detail);
                }));
    server.Get("/api/connection", handled("GET", [this](const Request&, Response& res, std::string&) {
                 replyJson(res, 200,
                           Json{{"current",
                                 {{"state", stateText()},
                                  {"port", m_connected ? Json("/dev/ttyACM0") : Json(nullptr)},
                                  {"baudrate", m_connected ? Json(115200) : Json(nullptr)},
                                  {"printerProfile", "_default"}}},
                                {"options",
                                 {{"ports", {"/dev/ttyACM0"}},
                                  {"baudrates", {250000, 115200}},
                                  {"printerProfiles", {{{"id", "_default"}, {"name", "Default"}}}}}}});
               }));
    server.Post("/api/connection", handled("POST", [this](const Request& req, Response& res, std::string& detail) {
                  connection(req, res, detail);
                }));
  }

 private:
  // Requires m_mutex. OctoPrint's serial connection: closed after the firmware shut down (M112, a heater
  // fault), or by a disconnect.
  bool operational() const { return m_connected && m_printer.firmwareState() == "ready"; }

  // OctoPrint's state string (comm.py getStateString) for the simulated printer.
  std::string stateText() const {
    if (m_printer.firmwareState() != "ready") return "Offline after error";
    if (!m_connected) return "Offline";
    if (m_printer.jobState() == "printing") return "Printing";
    if (m_printer.jobState() == "paused") return "Paused";
    return "Operational";
  }

  std::string errorText() const {
    if (m_printer.firmwareState() == "ready") return "";
    return m_closedByEmergencyStop ? kEmergencyStopClose : m_printer.shutdownReason();
  }

  std::string shownFile() const { return m_selected.empty() ? m_printer.currentFile() : m_selected; }

  void job(httplib::Response& res) {
    const std::string file = shownFile();
    const std::string& state = m_printer.jobState();
    const bool ran = !file.empty() && file == m_printer.currentFile();
    // OctoPrint sets the completion to 100 % when a job is done and clears the progress when it is cancelled.
    Json completion = nullptr;
    if (ran && state == "complete") completion = 100.0;
    if (ran && (state == "printing" || state == "paused" || state == "error"))
      completion = m_printer.progress() * 100.0;
    const bool active = ran && (state == "printing" || state == "paused");
    replyJson(res, 200,
              Json{{"job",
                    {{"file",
                      {{"name", file.empty() ? Json(nullptr) : Json(file)},
                       {"path", file.empty() ? Json(nullptr) : Json(file)},
                       {"display", file.empty() ? Json(nullptr) : Json(file)},
                       {"origin", file.empty() ? Json(nullptr) : Json("local")},
                       {"size", file.empty() ? Json(nullptr) : Json(m_printer.fileSize(file))},
                       {"date", nullptr}}},
                     {"estimatedPrintTime", nullptr},
                     {"lastPrintTime", nullptr},
                     {"filament", nullptr},
                     {"user", nullptr}}},
                   {"progress",
                    {{"completion", completion},
                     {"filepos", active ? Json(m_printer.filePosition()) : Json(nullptr)},
                     {"printTime", active ? Json(m_printer.printSeconds()) : Json(nullptr)},
                     {"printTimeLeft", nullptr},
                     {"printTimeLeftOrigin", nullptr}}},
                   {"state", stateText()},
                   {"error", errorText()}});
  }

  void printer(httplib::Response& res) {
    if (!operational()) return replyError(res, 409, "Printer is not operational");
    const HeaterReading tool = m_printer.extruder();
    const HeaterReading bed = m_printer.bed();
    const bool printing = m_printer.jobState() == "printing";
    const bool paused = m_printer.jobState() == "paused";
    replyJson(res, 200,
              Json{{"temperature",
                    {{"tool0", {{"actual", tool.actualC}, {"target", tool.targetC}, {"offset", 0}}},
                     {"bed", {{"actual", bed.actualC}, {"target", bed.targetC}, {"offset", 0}}}}},
                   {"state",
                    {{"text", stateText()},
                     {"flags",
                      {{"operational", true},
                       {"printing", printing},
                       {"paused", paused},
                       {"pausing", false},
                       {"cancelling", false},
                       {"resuming", false},
                       {"finishing", false},
                       {"sdReady", false},
                       {"error", false},
                       {"ready", !printing && !paused},
                       {"closedOrError", false}}}}}});
  }

  static const Json* body(const httplib::Request& req, Json& parsed) {
    parsed = Json::parse(req.body, nullptr, false);
    return parsed.is_object() && parsed.contains("command") && parsed["command"].is_string() ? &parsed : nullptr;
  }

  void jobCommand(const httplib::Request& req, httplib::Response& res, std::string& detail) {
    Json parsed;
    if (body(req, parsed) == nullptr) return replyError(res, 400, "Expected content-type JSON with a command");
    const std::string command = parsed["command"].get<std::string>();
    const std::string action =
        parsed.contains("action") && parsed["action"].is_string() ? parsed["action"].get<std::string>() : "toggle";
    detail = command == "pause" ? command + " " + action : command;
    if (!operational()) return replyError(res, 409, "Printer is not operational");
    const std::string& state = m_printer.jobState();
    const bool active = state == "printing" || state == "paused";
    if (command == "cancel") {
      if (!active)
        return replyError(res, 409, "Printer is neither printing nor paused, 'cancel' command cannot be performed");
      m_printer.cancel();
      return noContent(res);
    }
    if (command == "pause") {
      if (!active)
        return replyError(res, 409, "Printer is neither printing nor paused, 'pause' command cannot be performed");
      if (action == "pause" || (action == "toggle" && state == "printing")) {
        if (state == "printing") m_printer.pause();
        return noContent(res);
      }
      if (action == "resume" || action == "toggle") {
        if (state == "paused") m_printer.resume();
        return noContent(res);
      }
      return replyError(res, 400, "Unknown action for command pause: " + action);
    }
    if (command == "start") {
      if (active) return replyError(res, 409, "Printer already has an active print job, did you mean 'restart'?");
      if (shownFile().empty()) return replyError(res, 409, "Printer has no file selected");
      return startSelected(res);
    }
    replyError(res, 400, "Unknown command: " + command);
  }

  void startSelected(httplib::Response& res) {
    const std::string why = m_printer.start(shownFile());
    if (!why.empty()) return replyError(res, 409, why);
    m_selected.clear();
    noContent(res);
  }

  void printerCommand(const httplib::Request& req, httplib::Response& res, std::string& detail) {
    const Json parsed = Json::parse(req.body, nullptr, false);
    std::vector<std::string> commands;
    if (parsed.is_object() && parsed.contains("commands") && parsed["commands"].is_array()) {
      for (const Json& c : parsed["commands"])
        if (c.is_string()) commands.push_back(c.get<std::string>());
    } else if (parsed.is_object() && parsed.contains("command") && parsed["command"].is_string()) {
      commands.push_back(parsed["command"].get<std::string>());
    } else {
      return replyError(res, 400, "Expected content-type JSON with command or commands");
    }
    for (const std::string& c : commands) detail += (detail.empty() ? "" : " ") + c;
    if (!operational()) return replyError(res, 409, "Printer is not operational");
    for (const std::string& c : commands) {
      // M104/M140 set the heater at once, as Marlin does; other commands reach the printer's terminal only.
      const sim::TimelineLine read = sim::GcodeTimelineReader{}.read(c, 0);
      if (read.heater != sim::TimelineLine::Heater::None && !read.waitForHeater)
        m_printer.setTarget(read.heater, read.targetC);
      if (c.rfind("M112", 0) != 0) continue;
      // OctoPrint sends M112 ahead of its queue, switches the heaters off and closes the serial port.
      m_printer.emergencyStop();
      m_closedByEmergencyStop = true;
      m_selected.clear();
      break;
    }
    noContent(res);
  }

  void upload(const httplib::Request& req, httplib::Response& res, std::string& detail) {
    if (!req.is_multipart_form_data() || !req.has_file("file")) return replyError(res, 400, "No file included");
    const httplib::MultipartFormData file = req.get_file_value("file");
    detail = file.filename;
    if (file.filename.empty() || file.filename.find('/') != std::string::npos ||
        file.filename.find("..") != std::string::npos)
      return replyError(res, 400, "Invalid file name: " + file.filename);
    if (!isGcodeName(file.filename))
      return replyError(res, 415, "Could not upload the file \"" + file.filename + "\", invalid type");
    const std::string& state = m_printer.jobState();
    if (file.filename == m_printer.currentFile() && (state == "printing" || state == "paused"))
      return replyError(res, 409, "Trying to overwrite file that is currently being printed: " + file.filename);
    m_printer.storeFile(file.filename, file.content);
    const auto flag = [&](const char* name) {
      return req.has_file(name) && req.get_file_value(name).content == "true";
    };
    if (flag("select") || flag("print")) m_selected = file.filename;
    if (flag("print") && operational() && state != "printing" && state != "paused") (void)startSelected(res);
    res.set_header("Location", "/api/files/local/" + file.filename);
    replyJson(res, 201,
              Json{{"files",
                    {{"local",
                      {{"name", file.filename},
                       {"path", file.filename},
                       {"origin", "local"},
                       {"refs",
                        {{"resource", "/api/files/local/" + file.filename},
                         {"download", "/downloads/files/local/" + file.filename}}}}}}},
                   {"done", true},
                   {"effectiveSelect", flag("select") || flag("print")},
                   {"effectivePrint", flag("print") && m_printer.jobState() == "printing"}});
  }

  void fileCommand(const httplib::Request& req, httplib::Response& res, std::string& detail) {
    const std::string name = req.matches.size() > 1 ? std::string(req.matches[1]) : "";
    detail = name;
    Json parsed;
    if (body(req, parsed) == nullptr) return replyError(res, 400, "Expected content-type JSON with a command");
    if (parsed["command"] != "select") return replyError(res, 400, "Unknown command: " + parsed["command"].dump());
    if (!m_printer.hasFile(name)) return replyError(res, 404, "File not found on 'local': " + name);
    const bool print = parsed.contains("print") && parsed["print"].is_boolean() && parsed["print"].get<bool>();
    const std::string& state = m_printer.jobState();
    if (print && (!operational() || state == "printing" || state == "paused"))
      return replyError(res, 409, "Printer is already printing or not operational, cannot select and print");
    m_selected = name;
    if (print) return startSelected(res);
    noContent(res);
  }

  void connection(const httplib::Request& req, httplib::Response& res, std::string& detail) {
    Json parsed;
    if (body(req, parsed) == nullptr) return replyError(res, 400, "Expected content-type JSON with a command");
    detail = parsed["command"].get<std::string>();
    if (detail == "connect") {
      // Opening the serial port resets the printer's board (DTR), which is what Marlin needs after M112 or a
      // heater fault.
      if (m_printer.firmwareState() != "ready") m_printer.firmwareRestart();
      m_connected = true;
      m_closedByEmergencyStop = false;
      return noContent(res);
    }
    if (detail == "disconnect") {
      if (m_printer.jobState() == "printing" || m_printer.jobState() == "paused") m_printer.cancel();
      m_connected = false;
      return noContent(res);
    }
    replyError(res, 400, "Unknown command: " + detail);
  }

  std::string m_apiKey;
  bool m_connected = true;
  bool m_closedByEmergencyStop = false;
  std::string m_selected;  // selected and not started (OctoPrint shows it as the job's file)
};

}  // namespace

OctoPrintSimulator::OctoPrintSimulator(OctoPrintSimulatorOptions options)
    : PrinterSimulator(std::make_unique<OctoPrintServer>(options)), m_apiKey(options.apiKey) {}

}  // namespace multidir::hardware

// Moonraker's HTTP API in front of SimulatedPrinter; the server, records and faults are HttpPrinterSimulator's.
#include "multidir/hardware/moonraker_simulator.h"

#include <nlohmann/json.hpp>
#include <sstream>

#include "sim/http_printer_simulator.h"

namespace multidir::hardware {
namespace {

using Json = nlohmann::json;
using sim::replyJson;

// Moonraker's error shape: {"error": {"code": 400, "message": "...", "traceback": ""}}.
void replyError(httplib::Response& res, int status, const std::string& message) {
  replyJson(res, status, Json{{"error", {{"code", status}, {"message", message}, {"traceback", ""}}}});
}

// Keeps the attributes asked for ("extruder=target,temperature"); all when none is named.
Json filtered(const Json& object, const std::string& attributes) {
  if (attributes.empty()) return object;
  Json out = Json::object();
  std::stringstream names(attributes);
  std::string name;
  while (std::getline(names, name, ','))
    if (object.contains(name)) out[name] = object[name];
  return out;
}

sim::SimulatedPrinterSettings klipper(const SimulatedRotaryAxes& axes) {
  sim::SimulatedPrinterSettings settings;
  settings.axes = {sim::RotaryAxisSetup::Firmware::Klipper, axes.manualSteppers};
  return settings;
}

class MoonrakerServer : public sim::HttpPrinterSimulator {
 public:
  explicit MoonrakerServer(PrinterSimulatorOptions options)
      : HttpPrinterSimulator(options, klipper(options.rotaryAxes)) {}
  ~MoonrakerServer() override { stop(); }

 protected:
  core::Status validateOwnOptions() const override {
    if (!m_options.rotaryAxes.letters.empty())
      return core::Error{core::ErrorCode::InvalidParameter,
                         "Klipper's G1 moves X, Y, Z and E only: its rotary axes are [manual_stepper]s, moved by "
                         "MANUAL_STEPPER: give --manual-stepper",
                         "--rotary-axes"};
    return core::Done{};
  }

  void configure(httplib::Server& server) override {
    server.Get("/printer/objects/query", handled("GET", [this](const httplib::Request& req, httplib::Response& res,
                                                               std::string&) { query(req, res); }));
    // Klipper's loaded objects: the heaters and print objects, and one "manual_stepper NAME" per configured stepper.
    server.Get("/printer/objects/list",
               handled("GET", [this](const httplib::Request&, httplib::Response& res, std::string&) {
                 Json objects = {"webhooks", "print_stats", "virtual_sdcard", "extruder", "heater_bed", "toolhead"};
                 for (const std::string& name : m_printer.axes().names) objects.push_back("manual_stepper " + name);
                 replyJson(res, 200, Json{{"result", {{"objects", objects}}}});
               }));
    server.Get("/printer/info", handled("GET", [this](const httplib::Request&, httplib::Response& res, std::string&) {
                 replyJson(res, 200,
                           Json{{"result",
                                 {{"state", m_printer.firmwareState()},
                                  {"state_message", m_printer.firmwareMessage()},
                                  {"hostname", "multidir-simulator"},
                                  {"software_version", "multidir-simulated-klipper"}}}});
               }));
    server.Post("/printer/print/start",
                handled("POST", [this](const httplib::Request& req, httplib::Response& res, std::string& detail) {
                  detail = req.get_param_value("filename");
                  if (detail.empty()) return replyError(res, 400, "No data for argument: filename");
                  command(res, m_printer.start(detail));
                }));
    server.Post("/printer/print/pause", handled("POST", [this](const httplib::Request&, httplib::Response& res,
                                                               std::string&) { command(res, m_printer.pause()); }));
    server.Post("/printer/print/resume", handled("POST", [this](const httplib::Request&, httplib::Response& res,
                                                                std::string&) { command(res, m_printer.resume()); }));
    server.Post("/printer/print/cancel", handled("POST", [this](const httplib::Request&, httplib::Response& res,
                                                                std::string&) { command(res, m_printer.cancel()); }));
    server.Post("/printer/emergency_stop",
                handled("POST", [this](const httplib::Request&, httplib::Response& res, std::string&) {
                  m_printer.emergencyStop();
                  command(res, "");
                }));
    server.Post("/printer/gcode/script",
                handled("POST", [this](const httplib::Request& req, httplib::Response& res, std::string& detail) {
                  detail = req.get_param_value("script");
                  gcodeScript(res, detail);
                }));
    server.Post("/printer/firmware_restart",
                handled("POST", [this](const httplib::Request&, httplib::Response& res, std::string&) {
                  m_printer.firmwareRestart();
                  command(res, "");
                }));
    server.Post("/server/files/upload", handled("POST", [this](const httplib::Request& req, httplib::Response& res,
                                                               std::string& detail) { upload(req, res, detail); }));
  }

 private:
  void command(httplib::Response& res, const std::string& error) {
    if (!error.empty()) return replyError(res, 400, error);
    replyJson(res, 200, Json{{"result", "ok"}});
  }

  // The console's commands that touch the simulated heaters (TURN_OFF_HEATERS, M104, M140); others are taken
  // and do nothing. Klipper refuses every command while it is shut down.
  void gcodeScript(httplib::Response& res, const std::string& script) {
    if (script.empty()) return replyError(res, 400, "No data for argument: script");
    if (m_printer.firmwareState() != "ready") return replyError(res, 400, m_printer.firmwareMessage());
    std::stringstream lines(script);
    std::string line;
    while (std::getline(lines, line)) {
      if (line == "TURN_OFF_HEATERS") {
        m_printer.setTarget(sim::TimelineLine::Heater::Extruder, 0.0);
        m_printer.setTarget(sim::TimelineLine::Heater::Bed, 0.0);
        continue;
      }
      const sim::TimelineLine read = sim::GcodeTimelineReader{}.read(line, 0);
      if (read.heater != sim::TimelineLine::Heater::None && !read.waitForHeater)
        m_printer.setTarget(read.heater, read.targetC);
    }
    command(res, "");
  }

  void query(const httplib::Request& req, httplib::Response& res) {
    const HeaterReading extruder = m_printer.extruder();
    const HeaterReading bed = m_printer.bed();
    const std::string path =
        m_printer.currentFile().empty() ? "" : "/home/pi/printer_data/gcodes/" + m_printer.currentFile();
    const Json all = {
        {"webhooks", {{"state", m_printer.firmwareState()}, {"state_message", m_printer.firmwareMessage()}}},
        {"print_stats",
         {{"filename", m_printer.currentFile()},
          {"total_duration", m_printer.printSeconds()},
          {"print_duration", m_printer.printSeconds()},
          {"filament_used", 0.0},
          {"state", m_printer.jobState()},
          {"message", m_printer.jobMessage()},
          {"info", {{"total_layer", nullptr}, {"current_layer", nullptr}}}}},
        {"virtual_sdcard",
         {{"file_path", path.empty() ? Json(nullptr) : Json(path)},
          {"progress", m_printer.progress()},
          {"is_active", m_printer.jobState() == "printing"},
          {"file_position", m_printer.filePosition()},
          {"file_size", m_printer.fileSize(m_printer.currentFile())}}},
        {"extruder", {{"temperature", extruder.actualC}, {"target", extruder.targetC}, {"power", 0.0}}},
        {"heater_bed", {{"temperature", bed.actualC}, {"target", bed.targetC}, {"power", 0.0}}}};
    // klippy/extras/manual_stepper.py get_status: the commanded position and whether the motor is enabled.
    Json withSteppers = all;
    for (std::size_t i = 0; i < m_printer.axes().names.size(); ++i)
      withSteppers["manual_stepper " + m_printer.axes().names[i]] = {{"position", m_printer.axisPosition(i)},
                                                                     {"enabled", m_printer.axisEnabled(i)}};
    Json status = Json::object();
    for (const auto& [name, attributes] : req.params)
      if (withSteppers.contains(name)) status[name] = filtered(withSteppers[name], attributes);
    const double eventtime = std::chrono::duration<double>(now().time_since_epoch()).count();
    replyJson(res, 200, Json{{"result", {{"eventtime", eventtime}, {"status", status}}}});
  }

  void upload(const httplib::Request& req, httplib::Response& res, std::string& detail) {
    if (!req.is_multipart_form_data() || !req.has_file("file"))
      return replyError(res, 400, "No file name specifed in upload form");
    const httplib::MultipartFormData file = req.get_file_value("file");
    detail = file.filename;
    const std::string root = req.has_file("root") ? req.get_file_value("root").content : "gcodes";
    if (root != "gcodes") return replyError(res, 400, "Invalid root request: " + root);
    if (file.filename.empty() || file.filename.find('/') != std::string::npos ||
        file.filename.find("..") != std::string::npos)
      return replyError(res, 400, "Invalid file name: " + file.filename);
    if (file.filename == m_printer.currentFile() &&
        (m_printer.jobState() == "printing" || m_printer.jobState() == "paused"))
      return replyError(res, 403, "File is loaded, upload not permitted");
    m_printer.storeFile(file.filename, file.content);
    bool started = false;
    if (req.has_file("print") && req.get_file_value("print").content == "true")
      started = m_printer.start(file.filename).empty();
    const double modified = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
    replyJson(res, 201,
              Json{{"result",
                    {{"item",
                      {{"path", file.filename},
                       {"root", "gcodes"},
                       {"modified", modified},
                       {"size", file.content.size()},
                       {"permissions", "rw"}}},
                     {"print_started", started},
                     {"print_queued", false},
                     {"action", "create_file"}}}});
  }
};

}  // namespace

MoonrakerSimulator::MoonrakerSimulator(MoonrakerSimulatorOptions options)
    : PrinterSimulator(std::make_unique<MoonrakerServer>(std::move(options))) {}

}  // namespace multidir::hardware

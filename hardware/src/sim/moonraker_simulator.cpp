// Moonraker's HTTP API in front of SimulatedPrinter, with cpp-httplib's server (loopback by default).
#include "multidir/hardware/moonraker_simulator.h"

#include <arpa/inet.h>
#include <httplib.h>

#include <condition_variable>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "sim/simulated_printer.h"

namespace multidir::hardware {
namespace {

using Clock = std::chrono::steady_clock;
using Json = nlohmann::json;

constexpr std::chrono::milliseconds kTickInterval{10};

void replyJson(httplib::Response& res, int status, const Json& body) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
}

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

}  // namespace

const char* printerFaultName(PrinterFault fault) {
  switch (fault) {
    case PrinterFault::None:
      return "none";
    case PrinterFault::ThermalRunaway:
      return "thermal-runaway";
    case PrinterFault::LinkDrop:
      return "link-drop";
    case PrinterFault::CancelledOnPrinter:
      return "cancelled-on-printer";
    case PrinterFault::SlowReplies:
      return "slow-replies";
  }
  return "?";
}

core::Result<PrinterFault> parsePrinterFault(const std::string& name) {
  for (PrinterFault f : {PrinterFault::None, PrinterFault::ThermalRunaway, PrinterFault::LinkDrop,
                         PrinterFault::CancelledOnPrinter, PrinterFault::SlowReplies})
    if (name == printerFaultName(f)) return f;
  return core::Error{core::ErrorCode::InvalidParameter,
                     "unknown printer fault '" + name +
                         "': choose none, thermal-runaway, link-drop, cancelled-on-printer or slow-replies",
                     "--fault"};
}

class MoonrakerSimulator::Impl {
 public:
  explicit Impl(MoonrakerSimulatorOptions options) : m_options(std::move(options)) {
    if (!m_options.steadyNow) m_options.steadyNow = [] { return Clock::now(); };
  }
  ~Impl() { stop(); }

  core::Status start() {
    in_addr parsed{};
    if (inet_pton(AF_INET, m_options.listenAddress.c_str(), &parsed) != 1)
      return core::Error{core::ErrorCode::InvalidParameter,
                         "'" + m_options.listenAddress + "' is not an IPv4 address (such as 127.0.0.1)", "--listen"};
    if (m_options.port < 0 || m_options.port > 65535)
      return core::Error{core::ErrorCode::InvalidParameter, "the port must be between 0 and 65535", "--port"};
    if (!(m_options.speed > 0.0) || m_options.speed > 100000.0)
      return core::Error{core::ErrorCode::InvalidParameter, "the speed must be above 0 and at most 100000", "--speed"};
    if (!(m_options.faultAtProgress >= 0.0) || m_options.faultAtProgress > 1.0)
      return core::Error{core::ErrorCode::InvalidParameter, "the fault's progress must be between 0 and 1",
                         "--fault-at"};
    std::lock_guard<std::mutex> serverLock(m_serverMutex);
    if (m_server) return core::Done{};
    m_port = m_options.port;
    if (core::Status listening = listen(); !listening) return listening;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_lastAdvance = m_options.steadyNow();
      m_quit = false;
    }
    m_ticker = std::thread([this] { tickLoop(); });
    return core::Done{};
  }

  void stop() {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_quit = true;
    }
    m_tickWake.notify_all();
    if (m_ticker.joinable()) m_ticker.join();
    std::lock_guard<std::mutex> serverLock(m_serverMutex);
    closeServer();
  }

  int port() const {
    std::lock_guard<std::mutex> serverLock(m_serverMutex);
    return m_port;
  }
  std::string address() const { return m_options.listenAddress + ":" + std::to_string(port()); }

  void injectThermalRunaway() {
    std::lock_guard<std::mutex> lock(m_mutex);
    advanceLocked();
    m_printer.thermalRunaway();
  }
  void cancelJobOnPrinter() {
    std::lock_guard<std::mutex> lock(m_mutex);
    advanceLocked();
    m_printer.cancel();
    noteJobState();
  }
  void dropLink() {
    std::lock_guard<std::mutex> serverLock(m_serverMutex);
    closeServer();
  }
  void restoreLink() {
    std::lock_guard<std::mutex> serverLock(m_serverMutex);
    if (!m_server) (void)listen();
  }
  void setReplyDelay(std::chrono::milliseconds delay) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_replyDelay = delay;
  }

  std::vector<PrinterRequestRecord> requests() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_requests;
  }
  std::vector<PrinterJobEvent> jobEvents() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_events;
  }
  SimulatedPrinterState state() {
    std::lock_guard<std::mutex> lock(m_mutex);
    advanceLocked();
    SimulatedPrinterState s;
    s.jobState = m_printer.jobState();
    s.firmwareState = m_printer.firmwareState();
    s.message = m_printer.firmwareState() == "ready" ? m_printer.jobMessage() : m_printer.firmwareMessage();
    s.file = m_printer.currentFile();
    s.progress = m_printer.progress();
    s.extruder = m_printer.extruder();
    s.bed = m_printer.bed();
    s.files = m_printer.fileNames();
    return s;
  }

 private:
  // Requires m_serverMutex.
  core::Status listen() {
    auto server = std::make_unique<httplib::Server>();
    configure(*server);
    server->set_keep_alive_timeout(1);
    int bound = -1;
    if (m_port == 0) {
      bound = server->bind_to_any_port(m_options.listenAddress);
    } else {
      bound = server->bind_to_port(m_options.listenAddress.c_str(), m_port) ? m_port : -1;
    }
    if (bound <= 0)
      return core::Error{core::ErrorCode::DeviceUnreachable,
                         "cannot listen on " + m_options.listenAddress + ":" + std::to_string(m_port) +
                             ": the port is in use or needs root, or the address is not one of this machine's; "
                             "choose another port",
                         "printer simulator"};
    m_port = bound;
    m_server = std::move(server);
    httplib::Server* raw = m_server.get();
    m_serverThread = std::thread([raw] { raw->listen_after_bind(); });
    // stop() does nothing to a server whose loop has not started yet: wait for it (bounded), so that a stop
    // right after start() cannot leave the thread listening.
    for (int i = 0; i < 2000 && !raw->is_running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return core::Done{};
  }

  // Requires m_serverMutex.
  void closeServer() {
    if (!m_server) return;
    m_server->stop();
    if (m_serverThread.joinable()) m_serverThread.join();
    m_server.reset();
  }

  // Requires m_mutex: runs the printer up to now.
  void advanceLocked() {
    const auto now = m_options.steadyNow();
    const double seconds = std::chrono::duration<double>(now - m_lastAdvance).count() * m_options.speed;
    m_lastAdvance = now;
    if (seconds > 0.0) m_printer.advance(seconds);
    noteJobState();
    if (!m_faultInjected && m_options.fault != PrinterFault::None && m_printer.jobState() == "printing" &&
        m_printer.progress() >= m_options.faultAtProgress) {
      m_faultInjected = true;
      switch (m_options.fault) {
        case PrinterFault::ThermalRunaway:
          m_printer.thermalRunaway();
          break;
        case PrinterFault::CancelledOnPrinter:
          m_printer.cancel();
          noteJobState();
          break;
        case PrinterFault::SlowReplies:
          m_replyDelay = m_options.slowReplyDelay;
          break;
        case PrinterFault::LinkDrop:
          m_dropUntil = now + m_options.linkDropFor;
          m_dropPending = true;
          break;
        case PrinterFault::None:
          break;
      }
    }
  }

  void noteJobState() {
    const std::string& state = m_printer.jobState();
    if (state == m_lastState) return;
    m_lastState = state;
    m_events.push_back(PrinterJobEvent{m_options.steadyNow(), state, m_printer.currentFile()});
  }

  void tickLoop() {
    bool dropped = false;
    std::chrono::steady_clock::time_point restoreAt{};
    while (true) {
      bool drop = false;
      bool restore = false;
      {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_tickWake.wait_for(lock, kTickInterval, [this] { return m_quit; });
        if (m_quit) return;
        advanceLocked();
        if (m_dropPending) {
          m_dropPending = false;
          drop = true;
          restoreAt = m_dropUntil;
        }
        if (dropped && m_options.steadyNow() >= restoreAt) restore = true;
      }
      if (drop) {
        dropLink();
        dropped = true;
      }
      if (restore) {
        restoreLink();
        dropped = false;
      }
    }
  }

  // Runs a handler with the printer brought up to now, records the request, then holds the reply for the
  // reply delay (outside the lock, so a slow reply never holds up the simulated printer).
  template <typename Handler>
  httplib::Server::Handler handled(const char* method, Handler handler) {
    return [this, method, handler](const httplib::Request& req, httplib::Response& res) {
      std::chrono::milliseconds delay{0};
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        advanceLocked();
        std::string detail;
        handler(req, res, detail);
        noteJobState();
        m_requests.push_back(PrinterRequestRecord{m_options.steadyNow(), method, req.path, detail, res.status});
        delay = m_replyDelay;
      }
      if (delay.count() > 0) std::this_thread::sleep_for(delay);
    };
  }

  void configure(httplib::Server& server) {
    server.Get("/printer/objects/query", handled("GET", [this](const httplib::Request& req, httplib::Response& res,
                                                               std::string&) { query(req, res); }));
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
    server.Post("/printer/firmware_restart",
                handled("POST", [this](const httplib::Request&, httplib::Response& res, std::string&) {
                  m_printer.firmwareRestart();
                  command(res, "");
                }));
    server.Post("/server/files/upload", handled("POST", [this](const httplib::Request& req, httplib::Response& res,
                                                               std::string& detail) { upload(req, res, detail); }));
  }

  void command(httplib::Response& res, const std::string& error) {
    if (!error.empty()) return replyError(res, 400, error);
    replyJson(res, 200, Json{{"result", "ok"}});
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
    Json status = Json::object();
    for (const auto& [name, attributes] : req.params)
      if (all.contains(name)) status[name] = filtered(all[name], attributes);
    const double eventtime = std::chrono::duration<double>(m_options.steadyNow().time_since_epoch()).count();
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

  MoonrakerSimulatorOptions m_options;

  mutable std::mutex m_serverMutex;  // the HTTP server's lifetime; never taken while holding m_mutex
  std::unique_ptr<httplib::Server> m_server;
  std::thread m_serverThread;
  int m_port = 0;

  mutable std::mutex m_mutex;  // the printer and the records
  std::condition_variable m_tickWake;
  bool m_quit = false;
  std::thread m_ticker;
  sim::SimulatedPrinter m_printer;
  Clock::time_point m_lastAdvance{};
  std::string m_lastState = "standby";
  std::vector<PrinterRequestRecord> m_requests;
  std::vector<PrinterJobEvent> m_events;
  std::chrono::milliseconds m_replyDelay{0};
  bool m_faultInjected = false;
  bool m_dropPending = false;
  Clock::time_point m_dropUntil{};
};

MoonrakerSimulator::MoonrakerSimulator(MoonrakerSimulatorOptions options)
    : m_impl(std::make_unique<Impl>(std::move(options))) {}
MoonrakerSimulator::~MoonrakerSimulator() = default;
core::Status MoonrakerSimulator::start() { return m_impl->start(); }
void MoonrakerSimulator::stop() { m_impl->stop(); }
int MoonrakerSimulator::port() const { return m_impl->port(); }
std::string MoonrakerSimulator::address() const { return m_impl->address(); }
void MoonrakerSimulator::injectThermalRunaway() { m_impl->injectThermalRunaway(); }
void MoonrakerSimulator::cancelJobOnPrinter() { m_impl->cancelJobOnPrinter(); }
void MoonrakerSimulator::dropLink() { m_impl->dropLink(); }
void MoonrakerSimulator::restoreLink() { m_impl->restoreLink(); }
void MoonrakerSimulator::setReplyDelay(std::chrono::milliseconds delay) { m_impl->setReplyDelay(delay); }
std::vector<PrinterRequestRecord> MoonrakerSimulator::requests() const { return m_impl->requests(); }
std::vector<PrinterJobEvent> MoonrakerSimulator::jobEvents() const { return m_impl->jobEvents(); }
SimulatedPrinterState MoonrakerSimulator::state() const { return m_impl->state(); }

}  // namespace multidir::hardware

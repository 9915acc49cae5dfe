// The HTTP side every printer simulator shares (see http_printer_simulator.h), and PrinterSimulator's
// methods, which all forward to it.
#include "sim/http_printer_simulator.h"

#include <arpa/inet.h>
#include <sys/socket.h>
#include <unistd.h>

#include "sim/listen_socket.h"

namespace multidir::hardware {

namespace sim {
namespace {

constexpr std::chrono::milliseconds kTickInterval{10};

}  // namespace

void replyJson(httplib::Response& res, int status, const nlohmann::json& body) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
}

HttpPrinterSimulator::HttpPrinterSimulator(PrinterSimulatorOptions options, SimulatedPrinterSettings printer)
    : m_options(std::move(options)), m_printer(printer) {
  if (!m_options.steadyNow) m_options.steadyNow = [] { return Clock::now(); };
}

HttpPrinterSimulator::~HttpPrinterSimulator() { stop(); }

core::Status HttpPrinterSimulator::start() {
  in_addr parsed{};
  if (inet_pton(AF_INET, m_options.listenAddress.c_str(), &parsed) != 1)
    return core::Error{core::ErrorCode::InvalidParameter,
                       "'" + m_options.listenAddress + "' is not an IPv4 address (such as 127.0.0.1)", "--listen"};
  if (m_options.port < 0 || m_options.port > 65535)
    return core::Error{core::ErrorCode::InvalidParameter, "the port must be between 0 and 65535", "--port"};
  if (!(m_options.speed > 0.0) || m_options.speed > 100000.0)
    return core::Error{core::ErrorCode::InvalidParameter, "the speed must be above 0 and at most 100000", "--speed"};
  if (!(m_options.faultAtProgress >= 0.0) || m_options.faultAtProgress > 1.0)
    return core::Error{core::ErrorCode::InvalidParameter, "the fault's progress must be between 0 and 1", "--fault-at"};
  if (core::Status axes = validate(m_options.rotaryAxes, "rotaryAxes"); !axes) return axes;
  if (core::Status own = validateOwnOptions(); !own) return own;
  std::lock_guard<std::mutex> serverLock(m_serverMutex);
  if (m_server) return core::Done{};
  m_port = m_options.port;
  if (core::Status listening = listen(); !listening) return listening;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_lastAdvance = now();
    m_quit = false;
  }
  m_ticker = std::thread([this] { tickLoop(); });
  return core::Done{};
}

void HttpPrinterSimulator::stop() {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_quit = true;
  }
  m_tickWake.notify_all();
  if (m_ticker.joinable()) m_ticker.join();
  std::lock_guard<std::mutex> serverLock(m_serverMutex);
  closeServer();
}

int HttpPrinterSimulator::port() const {
  std::lock_guard<std::mutex> serverLock(m_serverMutex);
  return m_port;
}

std::string HttpPrinterSimulator::address() const { return m_options.listenAddress + ":" + std::to_string(port()); }

void HttpPrinterSimulator::injectThermalRunaway() {
  std::lock_guard<std::mutex> lock(m_mutex);
  advanceLocked();
  m_printer.thermalRunaway();
}

void HttpPrinterSimulator::cancelJobOnPrinter() {
  std::lock_guard<std::mutex> lock(m_mutex);
  advanceLocked();
  m_printer.cancel();
  noteJobState();
}

void HttpPrinterSimulator::restartPrinter() {
  std::lock_guard<std::mutex> lock(m_mutex);
  advanceLocked();
  m_printer.firmwareRestart();
  m_printer.setTarget(sim::TimelineLine::Heater::Extruder, 0.0);
  m_printer.setTarget(sim::TimelineLine::Heater::Bed, 0.0);
  noteJobState();
}

void HttpPrinterSimulator::dropLink() {
  std::lock_guard<std::mutex> serverLock(m_serverMutex);
  closeServer();
}

void HttpPrinterSimulator::restoreLink() {
  std::lock_guard<std::mutex> serverLock(m_serverMutex);
  if (!m_server) (void)listen();
}

void HttpPrinterSimulator::setReplyDelay(std::chrono::milliseconds delay) {
  std::lock_guard<std::mutex> lock(m_mutex);
  m_replyDelay = delay;
}

std::vector<PrinterRequestRecord> HttpPrinterSimulator::requests() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_requests;
}

std::vector<PrinterJobEvent> HttpPrinterSimulator::jobEvents() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_events;
}

SimulatedPrinterState HttpPrinterSimulator::state() {
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

SimulatedAxisLog HttpPrinterSimulator::axisLog() {
  std::lock_guard<std::mutex> lock(m_mutex);
  advanceLocked();
  return m_printer.axisLog();
}

core::Status HttpPrinterSimulator::listen() {
  auto server = std::make_unique<httplib::Server>();
  configure(*server);
  server->set_keep_alive_timeout(1);
  // cpp-httplib's default socket options add SO_REUSEPORT, with which a second simulator binds a port another
  // one listens on and the kernel splits the connections between the two. SO_REUSEADDR alone lets a restarted
  // simulator (or restoreLink) bind past its old connections in TIME_WAIT, and a port in use still fails.
  server->set_socket_options([](socket_t sock) {
    const int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  int bound = -1;
  if (m_port == 0) {
    bound = server->bind_to_any_port(m_options.listenAddress);
  } else {
    bound = server->bind_to_port(m_options.listenAddress.c_str(), m_port) ? m_port : -1;
  }
  if (bound <= 0) {
    // cpp-httplib does not say why; binding once more ourselves gives the system's reason in words to act on.
    core::Result<int> again = listenTcp(m_options.listenAddress, m_port, 1);
    if (again.ok()) ::close(*again);
    return core::Error{core::ErrorCode::DeviceUnreachable,
                       again.ok() ? "the simulator cannot listen on " + m_options.listenAddress + ":" +
                                        std::to_string(m_port) +
                                        ": the HTTP server could not bind it; try again or "
                                        "choose another port with --port (0 picks a free one)"
                                  : again.error().message,
                       "printer simulator"};
  }
  m_port = bound;
  m_server = std::move(server);
  httplib::Server* raw = m_server.get();
  m_serverThread = std::thread([raw] { raw->listen_after_bind(); });
  // stop() does nothing to a server whose loop has not started yet: wait for it (bounded), so that a stop
  // right after start() cannot leave the thread listening.
  for (int i = 0; i < 2000 && !raw->is_running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return core::Done{};
}

void HttpPrinterSimulator::closeServer() {
  if (!m_server) return;
  m_server->stop();
  if (m_serverThread.joinable()) m_serverThread.join();
  m_server.reset();
}

void HttpPrinterSimulator::advanceLocked() {
  const auto at = now();
  double left = std::chrono::duration<double>(at - m_lastAdvance).count() * m_options.speed;
  m_lastAdvance = at;
  // With a fault armed, the printer runs in steps of at most 0.1 simulated seconds and the fault is checked
  // after each: however late this thread runs (a loaded machine), the fault lands when the job reaches its
  // progress, never after the job has ended.
  do {
    const double step = faultArmed() ? std::min(left, 0.1) : left;
    if (step > 0.0) m_printer.advance(step);
    left -= step;
    noteJobState();
    if (faultArmed() && m_printer.jobState() == "printing" && m_printer.progress() >= m_options.faultAtProgress)
      injectFault(at);
  } while (left > 0.0);
}

bool HttpPrinterSimulator::faultArmed() const { return !m_faultInjected && m_options.fault != PrinterFault::None; }

void HttpPrinterSimulator::injectFault(Clock::time_point at) {
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
      m_dropUntil = at + m_options.linkDropFor;
      m_dropPending = true;
      break;
    case PrinterFault::None:
      break;
  }
}

void HttpPrinterSimulator::noteJobState() {
  const std::string& state = m_printer.jobState();
  if (state == m_lastState) return;
  m_lastState = state;
  m_events.push_back(PrinterJobEvent{now(), state, m_printer.currentFile()});
}

void HttpPrinterSimulator::tickLoop() {
  bool dropped = false;
  Clock::time_point restoreAt{};
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
      if (dropped && now() >= restoreAt) restore = true;
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

httplib::Server::Handler HttpPrinterSimulator::handled(const char* method, Route route) {
  return [this, method, route = std::move(route)](const httplib::Request& req, httplib::Response& res) {
    std::chrono::milliseconds delay{0};
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      advanceLocked();
      std::string detail;
      if (authorized(req, res)) route(req, res, detail);
      noteJobState();
      m_requests.push_back(PrinterRequestRecord{now(), method, req.path, detail, res.status});
      delay = m_replyDelay;
    }
    if (delay.count() > 0) std::this_thread::sleep_for(delay);
  };
}

}  // namespace sim

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

PrinterSimulator::PrinterSimulator(std::unique_ptr<sim::HttpPrinterSimulator> impl) : m_impl(std::move(impl)) {}
PrinterSimulator::~PrinterSimulator() = default;
core::Status PrinterSimulator::start() { return m_impl->start(); }
void PrinterSimulator::stop() { m_impl->stop(); }
int PrinterSimulator::port() const { return m_impl->port(); }
std::string PrinterSimulator::address() const { return m_impl->address(); }
void PrinterSimulator::injectThermalRunaway() { m_impl->injectThermalRunaway(); }
void PrinterSimulator::cancelJobOnPrinter() { m_impl->cancelJobOnPrinter(); }
void PrinterSimulator::restartPrinter() { m_impl->restartPrinter(); }
void PrinterSimulator::dropLink() { m_impl->dropLink(); }
void PrinterSimulator::restoreLink() { m_impl->restoreLink(); }
void PrinterSimulator::setReplyDelay(std::chrono::milliseconds delay) { m_impl->setReplyDelay(delay); }
std::vector<PrinterRequestRecord> PrinterSimulator::requests() const { return m_impl->requests(); }
std::vector<PrinterJobEvent> PrinterSimulator::jobEvents() const { return m_impl->jobEvents(); }
SimulatedPrinterState PrinterSimulator::state() const { return m_impl->state(); }
SimulatedAxisLog PrinterSimulator::axisLog() const { return m_impl->axisLog(); }

}  // namespace multidir::hardware

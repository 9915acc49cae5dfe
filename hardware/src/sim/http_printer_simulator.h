#pragma once
// What the Moonraker and OctoPrint simulators share: cpp-httplib's server and its lifetime (listen, drop,
// restore on the same port), the ticker that runs the simulated printer and injects the demo fault, the
// request record and the job events, the reply delay. A protocol adds its routes in configure(), each wrapped
// in handled(), and may refuse requests in authorized().
#include <httplib.h>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "multidir/hardware/printer_simulator.h"
#include "sim/simulated_printer.h"

namespace multidir::hardware::sim {

void replyJson(httplib::Response& res, int status, const nlohmann::json& body);

class HttpPrinterSimulator {
 public:
  HttpPrinterSimulator(PrinterSimulatorOptions options, SimulatedPrinterSettings printer);
  // A derived class calls stop() in its own destructor, so that no request reaches its routes while it is
  // destroyed.
  virtual ~HttpPrinterSimulator();
  HttpPrinterSimulator(const HttpPrinterSimulator&) = delete;
  HttpPrinterSimulator& operator=(const HttpPrinterSimulator&) = delete;

  core::Status start();
  void stop();
  int port() const;
  std::string address() const;

  void injectThermalRunaway();
  void cancelJobOnPrinter();
  void restartPrinter();
  void dropLink();
  void restoreLink();
  void setReplyDelay(std::chrono::milliseconds delay);

  std::vector<PrinterRequestRecord> requests() const;
  std::vector<PrinterJobEvent> jobEvents() const;
  SimulatedPrinterState state();
  SimulatedAxisLog axisLog();

 protected:
  using Clock = std::chrono::steady_clock;
  using Route = std::function<void(const httplib::Request&, httplib::Response&, std::string& detail)>;

  virtual void configure(httplib::Server& server) = 0;
  // Options of the protocol's own beyond the shared ones (InvalidParameter naming the option).
  virtual core::Status validateOwnOptions() const { return core::Done{}; }
  // Called under the lock before a route; false when it answered the request itself (refused).
  virtual bool authorized(const httplib::Request&, httplib::Response&) { return true; }

  // Runs `route` with the printer brought up to now and the lock held, records the request, then holds the
  // reply for the reply delay (outside the lock, so a slow reply never holds up the simulated printer).
  httplib::Server::Handler handled(const char* method, Route route);
  // Requires m_mutex: records a change of the printer's job state.
  void noteJobState();
  Clock::time_point now() const { return m_options.steadyNow(); }

  PrinterSimulatorOptions m_options;
  mutable std::mutex m_mutex;  // the printer, the records and the derived class's state
  SimulatedPrinter m_printer;

 private:
  core::Status listen();                   // requires m_serverMutex
  void closeServer();                      // requires m_serverMutex
  void advanceLocked();                    // requires m_mutex: runs the printer up to now
  [[nodiscard]] bool faultArmed() const;   // requires m_mutex: options.fault not injected yet
  void injectFault(Clock::time_point at);  // requires m_mutex: options.fault, now
  void tickLoop();

  mutable std::mutex m_serverMutex;  // the HTTP server's lifetime; never taken while holding m_mutex
  std::unique_ptr<httplib::Server> m_server;
  std::thread m_serverThread;
  int m_port = 0;

  std::condition_variable m_tickWake;
  bool m_quit = false;
  std::thread m_ticker;
  Clock::time_point m_lastAdvance{};
  std::string m_lastState = "standby";
  std::vector<PrinterRequestRecord> m_requests;
  std::vector<PrinterJobEvent> m_events;
  std::chrono::milliseconds m_replyDelay{0};
  bool m_faultInjected = false;
  bool m_dropPending = false;
  Clock::time_point m_dropUntil{};
};

}  // namespace multidir::hardware::sim

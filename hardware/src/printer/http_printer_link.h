#pragma once
// What every printer link over HTTP shares (Moonraker, OctoPrint): the worker thread that polls and runs the
// queued commands in order, the thread that only sends the latched emergency stop on its own connection, the
// command queue and the status. A protocol supplies the status read, the emergency-stop request and its
// commands (through submit()). cpp-httplib stays in hardware/src/printer.
#include <httplib.h>

#include <deque>
#include <memory>
#include <mutex>
#include <string>

#include "multidir/hardware/printer_link.h"
#include "printer/latched_emergency_stop.h"
#include "printer/printer_link_threads.h"

namespace multidir::hardware {

// One good status read, in the protocol's words mapped onto PrinterStatus's fields.
struct PrinterReading {
  PrinterJobState state = PrinterJobState::Unknown;
  std::string firmwareState;
  std::string message;
  double progress = 0.0;
  std::string currentFile;
  HeaterReading extruder;
  HeaterReading bed;
};

struct HttpEndpoint {
  std::string host;
  int port = 0;
  std::string apiKey;  // sent as X-Api-Key when not empty
};

class HttpPrinterLink : public PrinterLink {
 public:
  ~HttpPrinterLink() override;

  core::Status connect() override;
  void disconnect() override;
  // Refuses a name that is not a plain file name, reads the file (FileNotFound), and queues postFile().
  std::future<core::Status> upload(const std::string& localPath, const std::string& remoteName) override;
  std::future<core::Status> emergencyStop() override;
  core::Status clearStop() override;
  PrinterStatus status() const override;
  std::string name() const override { return m_name; }

 protected:
  using Command = std::function<core::Status(httplib::Client&)>;

  // name(): "<protocol> printer at HOST:PORT".
  HttpPrinterLink(const std::string& protocol, HttpEndpoint endpoint, PrinterLinkOptions options);

  // Queues `command` for the worker (it gets a client with the request timeout). `what` names it in errors
  // ("uploading step-01.gcode"); refusedWhileStopped: refused at once while an emergency stop is latched.
  std::future<core::Status> submit(const std::string& what, bool refusedWhileStopped, Command command);
  // A fresh client (no keep-alive) that waits `replyTimeout` for each reply.
  std::unique_ptr<httplib::Client> client(std::chrono::milliseconds replyTimeout) const;
  const PrinterLinkOptions& options() const { return m_options; }

  // The protocol. Both run on the link's own threads, never at once with themselves. A derived class calls
  // disconnect() in its destructor, so that no thread calls them while it is destroyed.
  virtual core::Result<PrinterReading> readStatus(httplib::Client& client) = 0;
  virtual core::Status sendEmergencyStop(httplib::Client& client) = 0;
  // Sends the file's bytes as `remoteName` (`uploader` waits uploadTimeout for the reply).
  virtual core::Status postFile(httplib::Client& uploader, const std::string& content,
                                const std::string& remoteName) = 0;

 private:
  struct Pending {
    Command command;
    std::promise<core::Status> promise;
    std::string what;
  };

  void failQueued(const core::Error& error);
  void poll();
  void runWorker();
  void runStopper();

  HttpEndpoint m_endpoint;
  PrinterLinkOptions m_options;
  std::string m_name;

  mutable std::mutex m_mutex;  // everything below
  PrinterLinkThreads m_threads{m_mutex};
  std::deque<Pending> m_queue;
  bool m_lastPollFailed = false;
  PrinterStatus m_status;  // but its stop, which is m_stop's
  LatchedEmergencyStop m_stop;
};

// Helpers the protocols share.
core::Error invalidParameter(const std::string& what, const std::string& where);
std::future<core::Status> readyStatus(core::Status status);
// "%2F"-style encoding of everything but unreserved characters and '/'.
std::string percentEncode(const std::string& text);
// The G-code file's bytes, or FileNotFound saying to slice the job first.
core::Result<std::string> readFileToUpload(const std::string& localPath);
// Refuses a remote name that is not a plain file name (InvalidParameter naming `printer`); "" when fine.
std::string plainFileNameProblem(const std::string& remoteName);

// "http://HOST[:PORT]" (defaultPortWithScheme when absent), "HOST:PORT" or "HOST" (defaultPort). `scheme` is
// the URL scheme accepted besides http:// ("octoprint", "moonraker"); `example` is shown in errors.
// Errors: InvalidParameter for https, a path, no host, a port out of 1..65535.
struct HostPort {
  std::string host;
  int port = 0;
};
core::Result<HostPort> parseHostPortUrl(const std::string& url, const std::string& scheme, int defaultPortWithScheme,
                                        int defaultPort, const std::string& example);

// A protocol's settings (host and port filled in) from its URL, as parseHostPortUrl reads it.
template <typename Settings>
core::Result<Settings> settingsFromUrl(const std::string& url, const std::string& scheme, int defaultPortWithHttp,
                                       int defaultPort, const std::string& example) {
  const core::Result<HostPort> parsed = parseHostPortUrl(url, scheme, defaultPortWithHttp, defaultPort, example);
  if (!parsed) return parsed.error();
  Settings settings;
  settings.host = parsed->host;
  settings.port = parsed->port;
  return settings;
}

// InvalidParameter for an empty host, a port out of 1..65535, or options out of range.
core::Status validateEndpoint(const std::string& host, int port, const PrinterLinkOptions& options);

}  // namespace multidir::hardware

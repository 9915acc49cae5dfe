#pragma once
// What every printer link over HTTP shares (Moonraker, OctoPrint): the worker thread that polls and runs the
// queued commands in order, the thread that only sends the latched emergency stop on its own connection, the
// command queue and the status. A protocol supplies the status read, the emergency-stop request and its
// commands (through submit()). Every request goes through a BoundedHttpClient (a total deadline, a size
// limit); cpp-httplib stays in hardware/src/printer.
#include <deque>
#include <optional>
#include <memory>
#include <mutex>
#include <string>

#include "multidir/hardware/printer_link.h"
#include "printer/bounded_http_client.h"
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

class HttpPrinterLink : public PrinterLink {
 public:
  ~HttpPrinterLink() override;

  core::Status connect() override;
  void disconnect() override;
  // Refuses a name that is not a plain file name, reads the file (FileNotFound), and queues postFile().
  using PrinterLink::upload;
  std::future<core::Status> upload(const std::string& localPath, const std::string& remoteName,
                                   const std::string& checkedSha256) override;
  // Refuses a name that is not a plain file name, and queues postStart().
  std::future<core::Status> startPrint(const std::string& remoteName) override;
  std::future<core::Status> emergencyStop() override;
  core::Status clearStop() override;
  PrinterStatus status() const override;
  std::string name() const override { return m_name; }

 protected:
  using Command = std::function<core::Status(const BoundedHttpClient&)>;

  // name(): "<protocol> printer at HOST:PORT".
  HttpPrinterLink(const std::string& protocol, HttpEndpoint endpoint, PrinterLinkOptions options);

  // Queues `command` for the worker (its client's deadline is the request timeout). `what` names it in errors
  // ("uploading step-01.gcode"); refusedWhileStopped: refused at once while an emergency stop is latched.
  std::future<core::Status> submit(const std::string& what, bool refusedWhileStopped, Command command);
  // A client whose every request ends by `deadline` (and connects within the request timeout).
  BoundedHttpClient client(std::chrono::milliseconds deadline) const;
  const PrinterLinkOptions& options() const { return m_options; }

  // The protocol. Both run on the link's own threads, never at once with themselves. A derived class calls
  // disconnect() in its destructor, so that no thread calls them while it is destroyed.
  virtual core::Result<PrinterReading> readStatus(const BoundedHttpClient& client) = 0;
  virtual core::Status sendEmergencyStop(const BoundedHttpClient& client) = 0;
  // Sends the file's bytes as `remoteName` (`uploader`'s deadline is uploadTimeout).
  virtual core::Status postFile(const BoundedHttpClient& uploader, const std::string& content,
                                const std::string& remoteName) = 0;
  // Starts the printer's job of `remoteName` (a plain file name).
  virtual core::Status postStart(const BoundedHttpClient& client, const std::string& remoteName) = 0;

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
  // When the status read in flight began (options' clock); a read stuck past linkLostAfter is a lost link.
  std::optional<std::chrono::steady_clock::time_point> m_pollBegan;
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
// Why a remote name is not a plain file name ("" when it is): a path, "..", a quote, a backslash or a control
// character (shown escaped: it would end the upload's header, or add a line to the log).
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

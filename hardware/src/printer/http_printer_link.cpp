// The worker, queue and stop thread every HTTP printer link shares (see http_printer_link.h); the threads'
// start and stop are PrinterLinkThreads', the latch a LatchedEmergencyStop, as in the Marlin link.
#include "printer/http_printer_link.h"

#include <algorithm>
#include <cctype>

#include "printable_text.h"
#include "printer/checked_gcode.h"

namespace multidir::hardware {

using Clock = std::chrono::steady_clock;

core::Error invalidParameter(const std::string& what, const std::string& where) {
  return core::Error{core::ErrorCode::InvalidParameter, what, where};
}

std::future<core::Status> readyStatus(core::Status status) {
  std::promise<core::Status> promise;
  promise.set_value(std::move(status));
  return promise.get_future();
}

std::string percentEncode(const std::string& text) {
  static const char* const kHex = "0123456789ABCDEF";
  std::string out;
  for (const unsigned char c : text) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~' || c == '/') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

std::string plainFileNameProblem(const std::string& remoteName) {
  if (remoteName.empty() || remoteName.find('/') != std::string::npos || remoteName.find("..") != std::string::npos)
    return "the printer's file name '" + escapeControls(remoteName) + "' must be a plain file name";
  if (hasControls(remoteName) || remoteName.find('"') != std::string::npos ||
      remoteName.find('\\') != std::string::npos)
    return "the printer's file name '" + escapeControls(remoteName) +
           "' holds a quote, a backslash or a control character: rename the G-code file";
  return {};
}

core::Result<HostPort> parseHostPortUrl(const std::string& url, const std::string& scheme, int defaultPortWithHttp,
                                        int defaultPort, const std::string& example) {
  std::string rest = url;
  int port = defaultPort;
  if (rest.rfind("https://", 0) == 0)
    return invalidParameter("'" + url + "': https is not supported; use http:// on the lab network (or a tunnel)",
                            "--printer");
  if (rest.rfind("http://", 0) == 0) {
    rest = rest.substr(7);
    port = defaultPortWithHttp;
  } else if (rest.rfind(scheme + "://", 0) == 0) {
    rest = rest.substr(scheme.size() + 3);
  }
  if (!rest.empty() && rest.back() == '/') rest.pop_back();
  if (rest.find('/') != std::string::npos)
    return invalidParameter("'" + url + "': give the printer's address without a path, such as " + example,
                            "--printer");
  const std::size_t colon = rest.rfind(':');
  HostPort out;
  out.host = colon == std::string::npos ? rest : rest.substr(0, colon);
  if (out.host.empty()) return invalidParameter("'" + url + "' names no host, such as " + example, "--printer");
  out.port = port;
  if (colon != std::string::npos) {
    const std::string portText = rest.substr(colon + 1);
    const bool digits = !portText.empty() && portText.size() <= 5 &&
                        std::all_of(portText.begin(), portText.end(), [](char c) { return c >= '0' && c <= '9'; });
    out.port = digits ? std::stoi(portText) : 0;
    if (out.port < 1 || out.port > 65535)
      return invalidParameter("'" + url + "': the port must be a number from 1 to 65535", "--printer");
  }
  return out;
}

core::Status validateEndpoint(const std::string& host, int port, const PrinterLinkOptions& options) {
  if (host.empty()) return invalidParameter("the printer's host is empty", "printer");
  if (port < 1 || port > 65535) return invalidParameter("the printer's port must be 1..65535", "printer");
  return validate(options);
}

HttpPrinterLink::HttpPrinterLink(const std::string& protocol, HttpEndpoint endpoint, PrinterLinkOptions options)
    : m_endpoint(std::move(endpoint)),
      m_options(std::move(options)),
      m_name(protocol + " printer at " + m_endpoint.host + ":" + std::to_string(m_endpoint.port)) {
  if (!m_options.steadyNow) m_options.steadyNow = [] { return Clock::now(); };
}

HttpPrinterLink::~HttpPrinterLink() { disconnect(); }

core::Status HttpPrinterLink::connect() {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_threads.running()) return invalidParameter("already connected", m_name);
    m_threads.begin();
    m_status.link = LinkState::Connecting;
    m_status.polls = 0;
  }
  return m_threads.start([this] { runWorker(); }, [this] { runStopper(); });
}

void HttpPrinterLink::disconnect() {
  if (!m_threads.stop()) return;
  std::lock_guard<std::mutex> lock(m_mutex);
  m_threads.finish();
  m_status.link = LinkState::Disconnected;
  failQueued(core::Error{core::ErrorCode::Cancelled, "the link was disconnected before the command was sent", m_name});
  m_stop.cancelWaiters(m_name);
}

std::future<core::Status> HttpPrinterLink::upload(const std::string& localPath, const std::string& remoteName,
                                                  const std::string& checkedSha256) {
  if (const std::string problem = plainFileNameProblem(remoteName); !problem.empty())
    return readyStatus(invalidParameter(problem, m_name));
  return submit("uploading " + remoteName, true, [this, localPath, remoteName, checkedSha256](const BoundedHttpClient&) {
    const core::Result<std::string> content = readGcodeToSend(localPath, checkedSha256, "upload");
    if (!content) return core::Status(content.error());
    return postFile(client(m_options.uploadTimeout), *content, remoteName);
  });
}

std::future<core::Status> HttpPrinterLink::startPrint(const std::string& remoteName) {
  if (const std::string problem = plainFileNameProblem(remoteName); !problem.empty())
    return readyStatus(invalidParameter(problem, m_name));
  return submit("starting " + remoteName, true,
                [this, remoteName](const BoundedHttpClient& c) { return postStart(c, remoteName); });
}

std::future<core::Status> HttpPrinterLink::emergencyStop() {
  std::future<core::Status> future;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    future = m_stop.latch();
    failQueued(core::Error{core::ErrorCode::Cancelled, "cancelled by the emergency stop", m_name});
  }
  m_threads.stopWake().notify_all();
  return future;
}

core::Status HttpPrinterLink::clearStop() {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_stop.clear(m_name);
}

PrinterStatus HttpPrinterLink::status() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  PrinterStatus s = m_status;
  s.stop = m_stop.state();
  const auto now = m_options.steadyNow();
  // A status read stuck longer than linkLostAfter loses the link before its deadline ends it: the last
  // reading is not shown as live.
  const bool readStuck = m_pollBegan && now - *m_pollBegan >= m_options.linkLostAfter;
  s.linkLost = s.polls == 0 ||
               ((s.link != LinkState::Connected || readStuck) && now - s.lastReply >= m_options.linkLostAfter);
  return s;
}

BoundedHttpClient HttpPrinterLink::client(std::chrono::milliseconds deadline) const {
  return BoundedHttpClient(m_endpoint, m_options.requestTimeout, deadline);
}

std::future<core::Status> HttpPrinterLink::submit(const std::string& what, bool refusedWhileStopped, Command command) {
  std::promise<core::Status> promise;
  std::future<core::Status> future = promise.get_future();
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_threads.running()) {
      promise.set_value(invalidParameter("not connected: " + what + " was not sent", m_name));
      return future;
    }
    if (refusedWhileStopped && m_stop.latched()) {
      promise.set_value(invalidParameter(
          "the emergency stop is latched: " + what + " was not sent; clear the stop (and restart the printer) first",
          m_name));
      return future;
    }
    m_queue.push_back(Pending{std::move(command), std::move(promise), what});
  }
  m_threads.workerWake().notify_all();
  return future;
}

void HttpPrinterLink::failQueued(const core::Error& error) {
  for (Pending& pending : m_queue) pending.promise.set_value(error);
  m_queue.clear();
}

void HttpPrinterLink::poll() {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_pollBegan = m_options.steadyNow();
  }
  const core::Result<PrinterReading> reading = readStatus(client(m_options.requestTimeout));
  std::lock_guard<std::mutex> lock(m_mutex);
  m_pollBegan.reset();
  if (!reading) {
    m_status.link =
        m_status.polls == 0 && m_status.link == LinkState::Connecting ? LinkState::Connecting : LinkState::Reconnecting;
    m_status.lastError = reading.error().describe();
    m_lastPollFailed = true;
    m_threads.reportFirst(reading.error());
    return;
  }
  const PrinterReading& r = *reading;
  m_status.link = LinkState::Connected;
  m_status.state = r.state;
  m_status.firmwareState = r.firmwareState;
  m_status.message = r.message;
  m_status.progress = r.progress;
  m_status.currentFile = r.currentFile;
  m_status.extruder = r.extruder;
  m_status.bed = r.bed;
  ++m_status.polls;
  m_status.lastReply = m_options.steadyNow();
  m_status.lastError.clear();
  // Back after a failure with a stop latched: send it again (the printer may have restarted meanwhile).
  if (m_lastPollFailed && m_stop.latched()) {
    m_stop.markDue();
    m_threads.stopWake().notify_all();
  }
  m_lastPollFailed = false;
  m_threads.reportFirst(core::Done{});
}

void HttpPrinterLink::runWorker() {
  auto nextPoll = Clock::now();
  while (true) {
    Pending pending;
    bool havePending = false;
    {
      std::unique_lock<std::mutex> lock(m_mutex);
      m_threads.workerWake().wait_until(lock, nextPoll, [this] { return m_threads.quitting() || !m_queue.empty(); });
      if (m_threads.quitting()) return;
      if (!m_queue.empty()) {
        pending = std::move(m_queue.front());
        m_queue.pop_front();
        havePending = true;
      }
    }
    if (havePending) {
      core::Status outcome = pending.command(client(m_options.requestTimeout));
      if (!outcome.ok()) {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_status.lastError = outcome.error().describe();
      }
      pending.promise.set_value(std::move(outcome));
      nextPoll = Clock::now();  // read the effect at once
      continue;
    }
    if (Clock::now() >= nextPoll) {
      poll();
      nextPoll = Clock::now() + m_options.pollInterval;
    }
  }
}

void HttpPrinterLink::runStopper() {
  while (true) {
    std::uint64_t generation = 0;
    {
      std::unique_lock<std::mutex> lock(m_mutex);
      m_threads.stopWake().wait(lock, [this] { return m_threads.quitting() || m_stop.due(); });
      if (m_threads.quitting()) return;
      generation = m_stop.take();
    }
    const core::Status sent = sendEmergencyStop(client(m_options.requestTimeout));
    std::unique_lock<std::mutex> lock(m_mutex);
    if (sent.ok()) {  // its reply is the printer's confirmation
      m_stop.confirm(generation);
      continue;
    }
    m_stop.setProblem(sent.error().describe());
    m_stop.markDue();  // until the printer answers
    m_threads.stopWake().wait_for(lock, m_options.stopRetryInterval, [this] { return m_threads.quitting(); });
  }
}

}  // namespace multidir::hardware

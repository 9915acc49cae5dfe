// Moonraker over HTTP with cpp-httplib: one worker thread polls and runs commands in order, one thread sends
// the latched emergency stop on its own connection.
#include "multidir/hardware/moonraker_link.h"

#include <httplib.h>

#include <algorithm>
#include <cctype>
#include <condition_variable>
#include <deque>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include "printer/moonraker_status.h"

namespace multidir::hardware {
namespace {

using Clock = std::chrono::steady_clock;
using Json = nlohmann::json;

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

core::Error invalid(const std::string& what, const std::string& where) {
  return core::Error{core::ErrorCode::InvalidParameter, what, where};
}

template <typename T>
std::future<T> readyFuture(T value) {
  std::promise<T> promise;
  promise.set_value(std::move(value));
  return promise.get_future();
}

class MoonrakerLink : public PrinterLink {
 public:
  MoonrakerLink(MoonrakerSettings settings, PrinterLinkOptions options)
      : m_settings(std::move(settings)), m_options(std::move(options)) {
    if (!m_options.steadyNow) m_options.steadyNow = [] { return Clock::now(); };
    m_name = "Moonraker printer at " + m_settings.host + ":" + std::to_string(m_settings.port);
  }
  ~MoonrakerLink() override { disconnect(); }

  core::Status connect() override {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (m_running) return invalid("already connected", m_name);
      m_quit = false;
      m_running = true;
      m_firstDone = false;
      m_status.link = LinkState::Connecting;
      m_status.polls = 0;
    }
    m_worker = std::thread([this] { runWorker(); });
    m_stopper = std::thread([this] { runStopper(); });
    std::unique_lock<std::mutex> lock(m_mutex);
    m_firstCondition.wait(lock, [this] { return m_firstDone; });
    return m_first;
  }

  void disconnect() override {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (!m_running) return;
      m_quit = true;
    }
    m_wake.notify_all();
    m_stopWake.notify_all();
    if (m_worker.joinable()) m_worker.join();
    if (m_stopper.joinable()) m_stopper.join();
    std::lock_guard<std::mutex> lock(m_mutex);
    m_running = false;
    m_status.link = LinkState::Disconnected;
    failQueued(
        core::Error{core::ErrorCode::Cancelled, "the link was disconnected before the command was sent", m_name});
    for (auto& waiter : m_stopWaiters)
      waiter.second.set_value(core::Error{core::ErrorCode::Cancelled,
                                          "disconnected before the printer confirmed the emergency stop (it stays "
                                          "latched and is sent first on the next connect)",
                                          m_name});
    m_stopWaiters.clear();
  }

  std::future<core::Status> upload(const std::string& localPath, const std::string& remoteName) override {
    if (remoteName.empty() || remoteName.find('/') != std::string::npos || remoteName.find("..") != std::string::npos)
      return readyFuture<core::Status>(
          invalid("the printer's file name '" + remoteName + "' must be a plain file name", m_name));
    return submit("uploading " + remoteName, true, [this, localPath, remoteName](httplib::Client& client) {
      return doUpload(client, localPath, remoteName);
    });
  }
  std::future<core::Status> startPrint(const std::string& remoteName) override {
    return submit("starting " + remoteName, true, [this, remoteName](httplib::Client& client) {
      return post(client, "/printer/print/start?filename=" + percentEncode(remoteName));
    });
  }
  std::future<core::Status> pausePrint() override {
    return submit("pausing the print", false,
                  [this](httplib::Client& client) { return post(client, "/printer/print/pause"); });
  }
  std::future<core::Status> resumePrint() override {
    return submit("resuming the print", true,
                  [this](httplib::Client& client) { return post(client, "/printer/print/resume"); });
  }
  std::future<core::Status> cancelPrint() override {
    return submit("cancelling the print", false,
                  [this](httplib::Client& client) { return post(client, "/printer/print/cancel"); });
  }

  std::future<core::Status> emergencyStop() override {
    std::promise<core::Status> promise;
    std::future<core::Status> future = promise.get_future();
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_status.stop.kind = StopKind::EmergencyStop;
      m_status.stop.confirmed = false;
      m_status.stop.problem = "not sent yet";
      ++m_stopGeneration;
      m_stopDue = true;
      m_stopWaiters.emplace_back(m_stopGeneration, std::move(promise));
      failQueued(core::Error{core::ErrorCode::Cancelled, "cancelled by the emergency stop", m_name});
    }
    m_stopWake.notify_all();
    return future;
  }

  core::Status clearStop() override {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_status.stop.latched()) return core::Done{};
    if (!m_status.stop.confirmed)
      return invalid("the printer has not confirmed the emergency stop yet (" + m_status.stop.problem +
                         "): it cannot be cleared before it took effect",
                     m_name);
    m_status.stop = StopLatch{};
    return core::Done{};
  }

  PrinterStatus status() const override {
    std::lock_guard<std::mutex> lock(m_mutex);
    PrinterStatus s = m_status;
    s.linkLost = s.polls == 0 ||
                 (s.link != LinkState::Connected && m_options.steadyNow() - s.lastReply >= m_options.linkLostAfter);
    return s;
  }

  std::string name() const override { return m_name; }

 private:
  using Command = std::function<core::Status(httplib::Client&)>;
  struct Pending {
    Command command;
    std::promise<core::Status> promise;
    std::string what;
  };

  std::unique_ptr<httplib::Client> client(std::chrono::milliseconds replyTimeout) const {
    auto c = std::make_unique<httplib::Client>(m_settings.host, m_settings.port);
    const auto set = [](std::chrono::milliseconds t) {
      return std::pair<time_t, time_t>(static_cast<time_t>(t.count() / 1000),
                                       static_cast<time_t>(t.count() % 1000) * 1000);
    };
    const auto connectTimeout = set(m_options.requestTimeout);
    const auto replyTimeoutParts = set(replyTimeout);
    c->set_connection_timeout(connectTimeout.first, connectTimeout.second);
    c->set_read_timeout(replyTimeoutParts.first, replyTimeoutParts.second);
    c->set_write_timeout(replyTimeoutParts.first, replyTimeoutParts.second);
    c->set_keep_alive(false);
    if (!m_settings.apiKey.empty()) c->set_default_headers({{"X-Api-Key", m_settings.apiKey}});
    return c;
  }

  // The reply's "result" (Moonraker wraps every successful reply in {"result": ...}), or the error.
  core::Result<Json> reply(const httplib::Result& res, const std::string& request) const {
    if (!res)
      return core::Error{core::ErrorCode::DeviceUnreachable,
                         "no answer to " + request + " (" + httplib::to_string(res.error()) +
                             "): check that Moonraker runs, the address and the network",
                         m_name};
    Json body = Json::parse(res->body, nullptr, false);
    if (res->status < 200 || res->status >= 300) {
      std::string message = "HTTP " + std::to_string(res->status);
      if (!body.is_discarded() && body.contains("error") && body["error"].is_object() &&
          body["error"].contains("message") && body["error"]["message"].is_string())
        message += ": " + body["error"]["message"].get<std::string>();
      return core::Error{core::ErrorCode::DeviceFault, "the printer refused " + request + " (" + message + ")", m_name};
    }
    if (body.is_discarded())
      return core::Error{core::ErrorCode::DeviceFault,
                         "the reply to " + request + " is not JSON: is this Moonraker's address?", m_name};
    if (body.is_object() && body.contains("result")) return body["result"];
    return body;  // Moonraker before 2021 answered uploads without the wrapper
  }

  core::Status post(httplib::Client& client, const std::string& path) const {
    const core::Result<Json> answered = reply(client.Post(path.c_str()), "POST " + path);
    if (!answered) return answered.error();
    return core::Done{};
  }

  core::Status doUpload(httplib::Client&, const std::string& localPath, const std::string& remoteName) const {
    std::ifstream in(localPath, std::ios::binary);
    if (!in)
      return core::Error{core::ErrorCode::FileNotFound,
                         "cannot read the G-code file to upload: check that it exists (slice the job first)",
                         localPath};
    std::ostringstream content;
    content << in.rdbuf();
    auto uploader = client(m_options.uploadTimeout);
    const httplib::MultipartFormDataItems items = {{"file", content.str(), remoteName, "application/octet-stream"},
                                                   {"root", "gcodes", "", ""}};
    const core::Result<Json> answered =
        reply(uploader->Post("/server/files/upload", items), "POST /server/files/upload (" + remoteName + ")");
    if (!answered) return answered.error();
    const Json& result = *answered;
    if (!result.is_object() || !result.contains("item") || !result["item"].is_object())
      return core::Error{core::ErrorCode::DeviceFault,
                         "the upload of " + remoteName + " was answered without an \"item\": is this Moonraker?",
                         m_name};
    return core::Done{};
  }

  std::future<core::Status> submit(const std::string& what, bool refusedWhileStopped, Command command) {
    std::promise<core::Status> promise;
    std::future<core::Status> future = promise.get_future();
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (!m_running) {
        promise.set_value(invalid("not connected: " + what + " was not sent", m_name));
        return future;
      }
      if (refusedWhileStopped && m_status.stop.latched()) {
        promise.set_value(invalid("the emergency stop is latched: " + what +
                                      " was not sent; clear the stop (and restart the printer's firmware) first",
                                  m_name));
        return future;
      }
      m_queue.push_back(Pending{std::move(command), std::move(promise), what});
    }
    m_wake.notify_all();
    return future;
  }

  void failQueued(const core::Error& error) {
    for (Pending& pending : m_queue) pending.promise.set_value(error);
    m_queue.clear();
  }

  void poll() {
    auto c = client(m_options.requestTimeout);
    const std::string path = "/printer/objects/query?webhooks&print_stats&virtual_sdcard&extruder&heater_bed";
    const core::Result<Json> answered = reply(c->Get(path.c_str()), "GET " + path);
    core::Result<MoonrakerReading> reading =
        answered ? readMoonrakerStatus(*answered, m_name) : core::Result<MoonrakerReading>(answered.error());
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!reading) {
      m_status.link = m_status.polls == 0 && m_status.link == LinkState::Connecting ? LinkState::Connecting
                                                                                    : LinkState::Reconnecting;
      m_status.lastError = reading.error().describe();
      m_lastPollFailed = true;
      if (!m_firstDone) finishFirst(reading.error());
      return;
    }
    const MoonrakerReading& r = *reading;
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
    if (m_lastPollFailed && m_status.stop.latched()) {
      m_stopDue = true;
      m_stopWake.notify_all();
    }
    m_lastPollFailed = false;
    if (!m_firstDone) finishFirst(core::Done{});
  }

  void finishFirst(core::Status outcome) {
    m_first = std::move(outcome);
    m_firstDone = true;
    m_firstCondition.notify_all();
  }

  void runWorker() {
    auto nextPoll = Clock::now();
    while (true) {
      Pending pending;
      bool havePending = false;
      {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_wake.wait_until(lock, nextPoll, [this] { return m_quit || !m_queue.empty(); });
        if (m_quit) return;
        if (!m_queue.empty()) {
          pending = std::move(m_queue.front());
          m_queue.pop_front();
          havePending = true;
        }
      }
      if (havePending) {
        auto c = client(m_options.requestTimeout);
        core::Status outcome = pending.command(*c);
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

  void runStopper() {
    while (true) {
      std::uint64_t generation = 0;
      {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_stopWake.wait(lock, [this] { return m_quit || m_stopDue; });
        if (m_quit) return;
        generation = m_stopGeneration;
        m_stopDue = false;
      }
      auto c = client(m_options.requestTimeout);
      const core::Status sent = post(*c, "/printer/emergency_stop");
      std::unique_lock<std::mutex> lock(m_mutex);
      if (sent.ok()) {
        ++m_status.stop.writes;
        if (generation == m_stopGeneration) {
          m_status.stop.confirmed = true;
          m_status.stop.problem.clear();
        }
        for (auto it = m_stopWaiters.begin(); it != m_stopWaiters.end();) {
          if (it->first <= generation) {
            it->second.set_value(core::Done{});
            it = m_stopWaiters.erase(it);
          } else {
            ++it;
          }
        }
        continue;
      }
      m_status.stop.problem = sent.error().describe();
      m_stopDue = true;  // resend until the printer answers
      m_stopWake.wait_for(lock, m_options.stopRetryInterval, [this] { return m_quit; });
    }
  }

  MoonrakerSettings m_settings;
  PrinterLinkOptions m_options;
  std::string m_name;

  mutable std::mutex m_mutex;
  std::condition_variable m_wake;
  std::condition_variable m_stopWake;
  std::condition_variable m_firstCondition;
  std::deque<Pending> m_queue;
  bool m_quit = false;
  bool m_running = false;
  bool m_firstDone = false;
  core::Status m_first = core::Done{};
  bool m_lastPollFailed = false;
  PrinterStatus m_status;
  std::uint64_t m_stopGeneration = 0;
  bool m_stopDue = false;
  std::vector<std::pair<std::uint64_t, std::promise<core::Status>>> m_stopWaiters;
  std::thread m_worker;
  std::thread m_stopper;
};

}  // namespace

core::Result<MoonrakerSettings> parseMoonrakerUrl(const std::string& url) {
  MoonrakerSettings settings;
  std::string rest = url;
  bool schemeGiven = false;
  if (rest.rfind("https://", 0) == 0)
    return invalid("'" + url + "': https is not supported; use http:// on the lab network (or a tunnel)", "--printer");
  if (rest.rfind("http://", 0) == 0) {
    rest = rest.substr(7);
    schemeGiven = true;
  }
  if (!rest.empty() && rest.back() == '/') rest.pop_back();
  if (rest.find('/') != std::string::npos)
    return invalid("'" + url + "': give Moonraker's address without a path, such as http://192.168.0.20:7125",
                   "--printer");
  const std::size_t colon = rest.rfind(':');
  std::string host = colon == std::string::npos ? rest : rest.substr(0, colon);
  if (host.empty()) return invalid("'" + url + "' names no host, such as http://192.168.0.20:7125", "--printer");
  settings.host = host;
  settings.port = schemeGiven ? 80 : 7125;
  if (colon != std::string::npos) {
    const std::string portText = rest.substr(colon + 1);
    const bool digits = !portText.empty() && portText.size() <= 5 &&
                        std::all_of(portText.begin(), portText.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int port = digits ? std::stoi(portText) : 0;
    if (port < 1 || port > 65535)
      return invalid("'" + url + "': the port must be a number from 1 to 65535", "--printer");
    settings.port = port;
  }
  return settings;
}

core::Result<std::unique_ptr<PrinterLink>> makeMoonrakerLink(const MoonrakerSettings& settings,
                                                             const PrinterLinkOptions& options) {
  if (settings.host.empty()) return invalid("the printer's host is empty", "printer");
  if (settings.port < 1 || settings.port > 65535) return invalid("the printer's port must be 1..65535", "printer");
  if (core::Status valid = validate(options); !valid) return valid.error();
  return std::unique_ptr<PrinterLink>(std::make_unique<MoonrakerLink>(settings, options));
}

}  // namespace multidir::hardware

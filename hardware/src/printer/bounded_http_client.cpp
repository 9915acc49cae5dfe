#include "printer/bounded_http_client.h"

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <random>
#include <thread>
#include <utility>

#include "printable_text.h"

namespace multidir::hardware {
namespace {

using Clock = std::chrono::steady_clock;

// Shuts `client`'s socket down once `limit` has passed, until finish(). cpp-httplib's stop() shuts the
// socket down only while a request is in flight (one still connecting waits for its connect timeout), so it
// is called again every 20 ms until the request has ended.
class DeadlineWatchdog {
 public:
  DeadlineWatchdog(httplib::Client& client, std::chrono::milliseconds limit)
      : m_thread([this, &client, deadline = Clock::now() + limit] { watch(client, deadline); }) {}
  ~DeadlineWatchdog() { finish(); }
  DeadlineWatchdog(const DeadlineWatchdog&) = delete;
  DeadlineWatchdog& operator=(const DeadlineWatchdog&) = delete;

  // Stops watching; whether the deadline passed.
  bool finish() {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_done = true;
    }
    m_wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
    return m_expired;
  }

 private:
  void watch(httplib::Client& client, Clock::time_point deadline) {
    std::unique_lock<std::mutex> lock(m_mutex);
    if (m_wake.wait_until(lock, deadline, [this] { return m_done; })) return;
    m_expired = true;
    while (!m_done) {
      lock.unlock();
      client.stop();
      lock.lock();
      m_wake.wait_for(lock, std::chrono::milliseconds(20), [this] { return m_done; });
    }
  }

  std::mutex m_mutex;
  std::condition_variable m_wake;
  bool m_done = false;
  bool m_expired = false;
  std::thread m_thread;  // last: it starts once the members above exist
};

std::pair<time_t, time_t> secondsAndMicroseconds(std::chrono::milliseconds t) {
  return {static_cast<time_t>(t.count() / 1000), static_cast<time_t>(t.count() % 1000) * 1000};
}

// A declared Content-Length, or 0 when absent or not a number (cpp-httplib then refuses it itself).
std::uint64_t declaredLength(const httplib::Response& response) {
  const std::string text = response.get_header_value("Content-Length");
  if (text.empty() || text.size() > 19 || text.find_first_not_of("0123456789") != std::string::npos) return 0;
  return std::stoull(text);
}

std::string randomBoundary() {
  static const char kAlphabet[] = "0123456789abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
  std::random_device random;
  std::string out = "----MultiDirFormBoundary";
  for (int i = 0; i < 24; ++i) out += kAlphabet[random() % (sizeof kAlphabet - 1)];
  return out;
}

bool headerSafe(const std::string& text) {
  return !hasControls(text) && text.find('"') == std::string::npos && text.find('\\') == std::string::npos;
}

}  // namespace

core::Result<std::string> multipartBody(const std::vector<FormPart>& parts, const std::string& boundary,
                                        const std::string& where) {
  std::string body;
  for (const FormPart& part : parts) {
    for (const std::string* name : {&part.name, &part.fileName})
      if (!headerSafe(*name))
        return core::Error{core::ErrorCode::InvalidParameter,
                           "the name '" + escapeControls(*name) +
                               "' holds a quote, a backslash or a control character, which an upload cannot carry: "
                               "rename it",
                           where};
    body += "--" + boundary + "\r\nContent-Disposition: form-data; name=\"" + part.name + "\"";
    if (!part.fileName.empty()) body += "; filename=\"" + part.fileName + "\"";
    body += "\r\n";
    if (!part.contentType.empty()) body += "Content-Type: " + escapeControls(part.contentType) + "\r\n";
    body += "\r\n" + part.content + "\r\n";
  }
  return body + "--" + boundary + "--\r\n";
}

BoundedHttpClient::BoundedHttpClient(HttpEndpoint endpoint, std::chrono::milliseconds connectTimeout,
                                     std::chrono::milliseconds deadline)
    : m_endpoint(std::move(endpoint)), m_connectTimeout(std::min(connectTimeout, deadline)), m_deadline(deadline) {}

core::Result<HttpReply> BoundedHttpClient::get(const std::string& path, const std::string& where) const {
  httplib::Request request;
  request.method = "GET";
  request.path = path;
  return send(std::move(request), where);
}

core::Result<HttpReply> BoundedHttpClient::post(const std::string& path, const std::string& body,
                                                const std::string& contentType, const std::string& where) const {
  httplib::Request request;
  request.method = "POST";
  request.path = path;
  request.body = body;
  if (!contentType.empty()) request.set_header("Content-Type", contentType);
  return send(std::move(request), where);
}

core::Result<HttpReply> BoundedHttpClient::postForm(const std::string& path, const std::vector<FormPart>& parts,
                                                    const std::string& where) const {
  std::string boundary = randomBoundary();
  for (const FormPart& part : parts)
    while (part.content.find(boundary) != std::string::npos) boundary = randomBoundary();
  core::Result<std::string> body = multipartBody(parts, boundary, where);
  if (!body) return body.error();
  return post(path, *body, "multipart/form-data; boundary=" + boundary, where);
}

core::Result<HttpReply> BoundedHttpClient::send(httplib::Request request, const std::string& where) const {
  httplib::Client client(m_endpoint.host, m_endpoint.port);
  const auto connect = secondsAndMicroseconds(m_connectTimeout);
  const auto each = secondsAndMicroseconds(m_deadline);
  client.set_connection_timeout(connect.first, connect.second);
  client.set_read_timeout(each.first, each.second);
  client.set_write_timeout(each.first, each.second);
  client.set_keep_alive(false);
  if (!m_endpoint.apiKey.empty()) request.set_header("X-Api-Key", m_endpoint.apiKey);

  std::string body;
  std::uint64_t declared = 0;
  bool tooLarge = false;
  request.response_handler = [&](const httplib::Response& response) {
    declared = declaredLength(response);
    tooLarge = declared > kMaxReplyBytes;
    return !tooLarge;
  };
  request.content_receiver = [&](const char* data, std::size_t length, std::uint64_t, std::uint64_t) {
    if (body.size() + length > kMaxReplyBytes) {
      tooLarge = true;
      return false;
    }
    body.append(data, length);
    return true;
  };

  httplib::Response response;
  httplib::Error error = httplib::Error::Success;
  DeadlineWatchdog watchdog(client, m_deadline);
  const bool answered = client.send(request, response, error);
  const bool expired = watchdog.finish();
  if (tooLarge)
    return core::Error{core::ErrorCode::DeviceFault,
                       "the reply is larger than the 1 MiB limit of a printer's reply (" +
                           (declared > kMaxReplyBytes ? "it declares " + std::to_string(declared) + " bytes"
                                                      : std::string("cut off at the limit")) +
                           "): refused; check what answers at this address",
                       where};
  if (!answered && expired)
    return core::Error{core::ErrorCode::DeviceUnreachable,
                       "the whole reply did not arrive within the request's " + std::to_string(m_deadline.count()) +
                           " ms deadline",
                       where};
  if (!answered) return core::Error{core::ErrorCode::DeviceUnreachable, httplib::to_string(error), where};
  return HttpReply{response.status, std::move(body)};
}

}  // namespace multidir::hardware

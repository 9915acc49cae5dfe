#pragma once
// A bare HTTP server on 127.0.0.1 (ephemeral port) whose replies the test writes byte by byte, for the hostile
// printers the links must survive: a reply dripped one byte at a time, a body larger than any printer sends,
// JSON nested 100,000 deep. Each connection gets its own thread, so a stuck reply does not hold up another
// request (the emergency stop's own connection).
//
// Bounded by design: reading a request gives up after kRequestLimit; every write gives up once the server
// stops or the peer closes; drip() and stream() end by themselves after the time they are given. stop() (and
// the destructor) closes the listener and waits for every connection's thread.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace multidir::hardware::test {

struct SeenHttpRequest {
  std::string method;  // "GET"
  std::string target;  // "/printer/objects/query?webhooks&..."
  std::string head;    // the request line and headers, as received
  std::string body;
};

// One accepted connection, as the test's reply handler sees it.
class ScriptedConnection {
 public:
  ScriptedConnection(int fd, const std::atomic<bool>& stopping) : m_fd(fd), m_stopping(stopping) {}

  // Sends all of `bytes`; false once the peer closed, the server stops, or 5 s passed.
  bool send(const std::string& bytes) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    std::size_t sent = 0;
    while (sent < bytes.size()) {
      if (m_stopping || std::chrono::steady_clock::now() >= deadline) return false;
      if (!writable(50)) continue;
      const ssize_t n = ::send(m_fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) continue;
      if (n <= 0) return false;
      sent += static_cast<std::size_t>(n);
    }
    return true;
  }

  // Sends `bytes` one byte every `interval`, for at most `limit`; false when it stopped early (the peer
  // closed, the server stops, the limit passed).
  bool drip(const std::string& bytes, std::chrono::milliseconds interval, std::chrono::milliseconds limit) {
    const auto end = std::chrono::steady_clock::now() + limit;
    for (const char c : bytes) {
      if (std::chrono::steady_clock::now() >= end || peerClosed() || !send(std::string(1, c))) return false;
      sleepUnlessStopped(interval, end);
    }
    return true;
  }

  // Sends `chunk` again and again until `totalBytes` went out, or the peer closed, the server stops or
  // `limit` passed; the bytes sent.
  std::uint64_t stream(const std::string& chunk, std::uint64_t totalBytes, std::chrono::milliseconds limit) {
    const auto end = std::chrono::steady_clock::now() + limit;
    std::uint64_t sent = 0;
    while (sent < totalBytes && std::chrono::steady_clock::now() < end && !m_stopping) {
      if (!send(chunk)) break;
      sent += chunk.size();
    }
    return sent;
  }

  // Whether the client closed its end (or reset it).
  bool peerClosed() {
    pollfd p{m_fd, POLLIN, 0};
    if (::poll(&p, 1, 0) <= 0) return false;
    if ((p.revents & (POLLHUP | POLLERR)) != 0) return true;
    char byte = 0;
    return ::recv(m_fd, &byte, 1, MSG_PEEK | MSG_DONTWAIT) == 0;
  }

 private:
  bool writable(int timeoutMs) {
    pollfd p{m_fd, POLLOUT, 0};
    return ::poll(&p, 1, timeoutMs) > 0 && (p.revents & POLLOUT) != 0;
  }
  void sleepUnlessStopped(std::chrono::milliseconds interval, std::chrono::steady_clock::time_point end) {
    const auto until = std::min(end, std::chrono::steady_clock::now() + interval);
    while (std::chrono::steady_clock::now() < until && !m_stopping && !peerClosed())
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }

  int m_fd;
  const std::atomic<bool>& m_stopping;
};

// "HTTP/1.1 200 OK" with a JSON body and its length.
inline std::string jsonReply(const std::string& body, int status = 200) {
  return "HTTP/1.1 " + std::to_string(status) + (status == 200 ? " OK" : " Error") +
         "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) +
         "\r\nConnection: close\r\n\r\n" + body;
}

// Moonraker's status reply (the shape of docs/hardware.md, "Moonraker") for a job `state` (JSON string text:
// escapes as JSON writes them) of step-01.gcode at `progress`.
inline std::string moonrakerStatusJson(const std::string& state, double progress) {
  return R"({"result": {"eventtime": 1.0, "status": {"webhooks": {"state": "ready", "state_message": ""}, )"
         R"("print_stats": {"state": ")" +
         state + R"(", "filename": "step-01.gcode", "message": ""}, "virtual_sdcard": {"progress": )" +
         std::to_string(progress) +
         R"(}, "extruder": {"temperature": 200.0, "target": 200.0}, "heater_bed": {"temperature": 60.0, "target": 60.0}}}})";
}

class ScriptedHttpServer {
 public:
  // Writes the reply to one request; it must return within a bounded time (ScriptedConnection's calls do).
  using Handler = std::function<void(ScriptedConnection&, const SeenHttpRequest&)>;

  static constexpr std::size_t kRequestLimit = 32u << 20;  // a request's bytes (an upload's body included)

  explicit ScriptedHttpServer(Handler handler) : m_handler(std::move(handler)) {
    m_listen = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in where{};
    where.sin_family = AF_INET;
    where.sin_port = 0;
    where.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (m_listen < 0 || ::bind(m_listen, reinterpret_cast<const sockaddr*>(&where), sizeof where) != 0 ||
        ::listen(m_listen, 16) != 0)
      return;
    socklen_t length = sizeof where;
    ::getsockname(m_listen, reinterpret_cast<sockaddr*>(&where), &length);
    m_port = ntohs(where.sin_port);
    m_acceptor = std::thread([this] { acceptLoop(); });
  }
  ~ScriptedHttpServer() { stop(); }
  ScriptedHttpServer(const ScriptedHttpServer&) = delete;
  ScriptedHttpServer& operator=(const ScriptedHttpServer&) = delete;

  [[nodiscard]] int port() const { return m_port; }

  [[nodiscard]] std::vector<SeenHttpRequest> requests() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_requests;
  }
  [[nodiscard]] int count(const std::string& method, const std::string& pathPrefix) const {
    int n = 0;
    for (const auto& r : requests()) n += r.method == method && r.target.rfind(pathPrefix, 0) == 0 ? 1 : 0;
    return n;
  }

  void stop() {
    if (m_stopping.exchange(true)) return;
    if (m_listen >= 0) ::shutdown(m_listen, SHUT_RDWR);
    if (m_acceptor.joinable()) m_acceptor.join();
    if (m_listen >= 0) ::close(m_listen);
    std::vector<std::thread> connections;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      connections.swap(m_connections);
    }
    for (std::thread& t : connections) t.join();
  }

 private:
  void acceptLoop() {
    while (!m_stopping) {
      pollfd p{m_listen, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      const int fd = ::accept4(m_listen, nullptr, nullptr, SOCK_CLOEXEC);
      if (fd < 0) continue;
      std::lock_guard<std::mutex> lock(m_mutex);
      m_connections.emplace_back([this, fd] { serve(fd); });
    }
  }

  void serve(int fd) {
    SeenHttpRequest request;
    if (readRequest(fd, request)) {
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_requests.push_back(request);
      }
      ScriptedConnection connection(fd, m_stopping);
      m_handler(connection, request);
    }
    ::shutdown(fd, SHUT_RDWR);
    ::close(fd);
  }

  // The request's head and its body (by Content-Length), within kRequestLimit and 5 s.
  bool readRequest(int fd, SeenHttpRequest& request) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    std::string data;
    std::size_t headEnd = std::string::npos;
    std::size_t wanted = 0;
    char buffer[65536];
    while (!m_stopping && std::chrono::steady_clock::now() < deadline && data.size() < kRequestLimit) {
      if (headEnd != std::string::npos && data.size() >= headEnd + 4 + wanted) break;
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
      if (n <= 0) return false;
      data.append(buffer, static_cast<std::size_t>(n));
      if (headEnd == std::string::npos && (headEnd = data.find("\r\n\r\n")) != std::string::npos) {
        request.head = data.substr(0, headEnd);
        std::string lower = request.head;
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (const std::size_t at = lower.find("\r\ncontent-length:"); at != std::string::npos)
          wanted = std::stoul(lower.substr(at + 17));
      }
    }
    if (headEnd == std::string::npos || data.size() < headEnd + 4 + wanted) return false;
    request.body = data.substr(headEnd + 4, wanted);
    const std::size_t space = request.head.find(' ');
    const std::size_t space2 = request.head.find(' ', space + 1);
    request.method = request.head.substr(0, space);
    request.target = request.head.substr(space + 1, space2 - space - 1);
    return true;
  }

  Handler m_handler;
  int m_listen = -1;
  int m_port = 0;
  std::atomic<bool> m_stopping{false};
  std::thread m_acceptor;
  mutable std::mutex m_mutex;
  std::vector<std::thread> m_connections;
  std::vector<SeenHttpRequest> m_requests;
};

}  // namespace multidir::hardware::test

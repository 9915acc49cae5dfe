#pragma once
// A bare TCP client for the simulator's robustness tests: sends any bytes (broken frames, one byte at a
// time, pipelined requests) and reads replies with a deadline. 127.0.0.1 only.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

namespace multidir::hardware::test {

class RawClient {
 public:
  explicit RawClient(int port) {
    m_fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (m_fd < 0) return;
    sockaddr_in where{};
    where.sin_family = AF_INET;
    where.sin_port = htons(static_cast<std::uint16_t>(port));
    where.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(m_fd, reinterpret_cast<const sockaddr*>(&where), sizeof where) != 0) close();
  }
  ~RawClient() { close(); }
  RawClient(const RawClient&) = delete;
  RawClient& operator=(const RawClient&) = delete;
  RawClient(RawClient&& other) noexcept : m_fd(other.m_fd), m_pending(std::move(other.m_pending)) { other.m_fd = -1; }

  [[nodiscard]] bool connected() const { return m_fd >= 0; }
  void close() {
    if (m_fd >= 0) ::close(m_fd);
    m_fd = -1;
  }

  bool send(const std::vector<std::uint8_t>& bytes) {
    return m_fd >= 0 && ::send(m_fd, bytes.data(), bytes.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(bytes.size());
  }

  // One reply frame (MBAP header and PDU), or nothing when none came within `limit` or the server closed.
  std::optional<std::vector<std::uint8_t>> readFrame(
      std::chrono::milliseconds limit = std::chrono::milliseconds(2000)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    for (;;) {
      if (m_pending.size() >= 7) {
        const std::size_t size = 6 + ((static_cast<std::size_t>(m_pending[4]) << 8) | m_pending[5]);
        if (m_pending.size() >= size) {
          std::vector<std::uint8_t> frame(m_pending.begin(), m_pending.begin() + static_cast<std::ptrdiff_t>(size));
          m_pending.erase(m_pending.begin(), m_pending.begin() + static_cast<std::ptrdiff_t>(size));
          return frame;
        }
      }
      if (!waitReadable(deadline)) return std::nullopt;
      std::uint8_t chunk[512];
      const ssize_t got = ::recv(m_fd, chunk, sizeof chunk, 0);
      if (got <= 0) return std::nullopt;
      m_pending.insert(m_pending.end(), chunk, chunk + got);
    }
  }

  // True once the server closed the connection (read returns end of stream) within `limit`.
  bool closedByServer(std::chrono::milliseconds limit = std::chrono::milliseconds(3000)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    for (;;) {
      if (!waitReadable(deadline)) return false;
      std::uint8_t chunk[512];
      const ssize_t got = ::recv(m_fd, chunk, sizeof chunk, 0);
      if (got == 0) return true;
      if (got < 0) return errno == ECONNRESET;
    }
  }

 private:
  bool waitReadable(std::chrono::steady_clock::time_point deadline) {
    if (m_fd < 0) return false;
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{m_fd, POLLIN, 0};
    return ::poll(&p, 1, static_cast<int>(left.count())) > 0;
  }

  int m_fd = -1;
  std::vector<std::uint8_t> m_pending;
};

// A Modbus TCP frame: transaction id, protocol id, unit id and PDU.
inline std::vector<std::uint8_t> mbapFrame(std::uint16_t transaction, std::uint8_t unit,
                                           const std::vector<std::uint8_t>& pdu, std::uint16_t protocol = 0) {
  const auto length = static_cast<std::uint16_t>(pdu.size() + 1);
  std::vector<std::uint8_t> frame = {static_cast<std::uint8_t>(transaction >> 8),
                                     static_cast<std::uint8_t>(transaction & 0xFF),
                                     static_cast<std::uint8_t>(protocol >> 8),
                                     static_cast<std::uint8_t>(protocol & 0xFF),
                                     static_cast<std::uint8_t>(length >> 8),
                                     static_cast<std::uint8_t>(length & 0xFF),
                                     unit};
  frame.insert(frame.end(), pdu.begin(), pdu.end());
  return frame;
}

// Function 03: read `quantity` holding registers from `address`.
inline std::vector<std::uint8_t> readPdu(std::uint16_t address, std::uint16_t quantity) {
  return {0x03, static_cast<std::uint8_t>(address >> 8), static_cast<std::uint8_t>(address & 0xFF),
          static_cast<std::uint8_t>(quantity >> 8), static_cast<std::uint8_t>(quantity & 0xFF)};
}

// Function 06 (one value) or 16 (several): write `values` from `address`.
inline std::vector<std::uint8_t> writePdu(std::uint16_t address, const std::vector<std::uint16_t>& values) {
  std::vector<std::uint8_t> pdu = {static_cast<std::uint8_t>(values.size() == 1 ? 0x06 : 0x10),
                                   static_cast<std::uint8_t>(address >> 8), static_cast<std::uint8_t>(address & 0xFF)};
  if (values.size() != 1) {
    pdu.push_back(static_cast<std::uint8_t>(values.size() >> 8));
    pdu.push_back(static_cast<std::uint8_t>(values.size() & 0xFF));
    pdu.push_back(static_cast<std::uint8_t>(2 * values.size()));
  }
  for (std::uint16_t value : values) {
    pdu.push_back(static_cast<std::uint8_t>(value >> 8));
    pdu.push_back(static_cast<std::uint8_t>(value & 0xFF));
  }
  return pdu;
}

}  // namespace multidir::hardware::test

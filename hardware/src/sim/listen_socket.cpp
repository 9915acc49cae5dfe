#include "sim/listen_socket.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace multidir::hardware::sim {

std::string listenFailure(const std::string& address, int port, int errnum) {
  const std::string head = "the simulator cannot listen on " + address + ":" + std::to_string(port) + ": ";
  switch (errnum) {
    case EADDRINUSE:
      return head + "port " + std::to_string(port) + " on " + address +
             " is in use (address already in use): stop the other program listening there (another simulator?) "
             "or choose another port with --port (0 picks a free one)";
    case EADDRNOTAVAIL:
      return head + "cannot assign requested address: " + address +
             " is not an address of this machine; use 127.0.0.1, 0.0.0.0 (every interface) or one of the "
             "addresses 'ip -4 addr' lists";
    case EACCES:
      return head + "permission denied: ports below 1024 need root; use a port above 1023 (1502 is the default)";
    default:
      return head + std::strerror(errnum);
  }
}

core::Result<int> listenTcp(const std::string& address, int port, int backlog) {
  const auto fail = [&](int errnum, int fd) -> core::Result<int> {
    if (fd >= 0) ::close(fd);
    return core::Error{core::ErrorCode::Internal, listenFailure(address, port, errnum), "listen address"};
  };
  sockaddr_in where{};
  where.sin_family = AF_INET;
  where.sin_port = htons(static_cast<std::uint16_t>(port));
  if (inet_pton(AF_INET, address.c_str(), &where.sin_addr) != 1) return fail(EINVAL, -1);
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) return fail(errno, -1);
  const int yes = 1;
  // A restarted simulator must not wait for the previous one's connections in TIME_WAIT.
  if (::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes) != 0) return fail(errno, fd);
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&where), sizeof where) != 0) return fail(errno, fd);
  if (::listen(fd, backlog) != 0) return fail(errno, fd);
  return fd;
}

}  // namespace multidir::hardware::sim

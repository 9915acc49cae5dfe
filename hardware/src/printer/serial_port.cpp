#include "printer/serial_port.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace multidir::hardware::serial {
namespace {

struct Rate {
  int baud;
  speed_t constant;
};

constexpr Rate kRates[] = {{9600, B9600},     {19200, B19200},   {38400, B38400},    {57600, B57600},
                           {115200, B115200}, {230400, B230400}, {460800, B460800},  {500000, B500000},
                           {576000, B576000}, {921600, B921600}, {1000000, B1000000}};
constexpr int kMarlinCustomRate = 250000;  // Marlin's usual BAUDRATE besides 115200; no termios constant

core::Error unreachable(const std::string& what, const std::string& path) {
  return core::Error{core::ErrorCode::DeviceUnreachable, what, path};
}

}  // namespace

bool supportedRate(int baud) {
  if (baud == kMarlinCustomRate) return true;
  for (const Rate& r : kRates)
    if (r.baud == baud) return true;
  return false;
}

core::Result<int> openRaw(const std::string& path, int baud) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    std::string hint = "check that the printer is plugged in and switched on, and the device path";
    if (error == EACCES) hint = "add the user to the 'dialout' group (then log in again)";
    if (error == EBUSY) hint = "another program (OctoPrint, Pronterface, a slicer) holds the port: close it";
    return unreachable("cannot open the printer's serial device (" + std::string(std::strerror(error)) + "): " + hint,
                       path);
  }
  termios tio{};
  if (!::isatty(fd) || tcgetattr(fd, &tio) != 0) {
    ::close(fd);
    return unreachable("is not a serial device (a terminal): give the printer's port, such as /dev/ttyACM0", path);
  }
  cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~static_cast<tcflag_t>(CRTSCTS | CSTOPB | PARENB);
  tio.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  // VMIN 1 with O_NONBLOCK: no data reads as EAGAIN, so a read of 0 bytes means the device hung up.
  tio.c_cc[VMIN] = 1;
  tio.c_cc[VTIME] = 0;
  bool standard = false;
  for (const Rate& r : kRates) {
    if (r.baud != baud) continue;
    cfsetispeed(&tio, r.constant);
    cfsetospeed(&tio, r.constant);
    standard = true;
  }
  if (tcsetattr(fd, TCSANOW, &tio) != 0) {
    const int error = errno;
    ::close(fd);
    return unreachable("cannot set the serial port to raw mode (" + std::string(std::strerror(error)) + ")", path);
  }
  if (!standard && !setCustomRate(fd, baud)) {
    ::close(fd);
    return unreachable("the serial driver refuses " + std::to_string(baud) + " baud: set the printer to 115200", path);
  }
  tcflush(fd, TCIOFLUSH);  // nothing left over from an earlier session
  return fd;
}

core::Status writeAll(int fd, const std::string& text, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
      return core::Error{core::ErrorCode::DeviceUnreachable,
                         "writing to the printer failed (" + std::string(std::strerror(errno)) +
                             "): was it unplugged or switched off?",
                         "serial"};
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0)
      return core::Error{core::ErrorCode::DeviceUnreachable,
                         "the printer took no data for " + std::to_string(timeout.count()) + " ms", "serial"};
    pollfd p{fd, POLLOUT, 0};
    ::poll(&p, 1, static_cast<int>(left.count()));
  }
  return core::Done{};
}

}  // namespace multidir::hardware::serial

// termios2 (Linux): a serial rate by number, for Marlin's 250000, which has no termios constant.
#include <asm/termbits.h>
#include <sys/ioctl.h>

#include "printer/serial_port.h"

namespace multidir::hardware::serial {

bool setCustomRate(int fd, int baud) {
  struct termios2 tio {};
  if (ioctl(fd, TCGETS2, &tio) != 0) return false;
  tio.c_cflag &= ~static_cast<tcflag_t>(CBAUD);
  tio.c_cflag |= BOTHER;
  tio.c_ispeed = static_cast<speed_t>(baud);
  tio.c_ospeed = static_cast<speed_t>(baud);
  return ioctl(fd, TCSETS2, &tio) == 0;
}

}  // namespace multidir::hardware::serial

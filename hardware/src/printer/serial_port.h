#pragma once
// A serial device (or pseudo-terminal) opened raw with POSIX termios, for the Marlin link: 8 data bits, no
// parity, one stop bit, no flow control, no echo or line editing, non-blocking.
#include <chrono>
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::hardware::serial {

// Whether `baud` is a rate the port can be set to (a termios constant, or 250000 through termios2).
bool supportedRate(int baud);

// The open descriptor. Errors: DeviceUnreachable naming the path and the system's reason (no such device,
// permission: the user must be in the dialout group, busy) or that it is not a terminal.
core::Result<int> openRaw(const std::string& path, int baud);

// Writes all of `text`, waiting at most `timeout` for the device to take it. Errors: DeviceUnreachable.
core::Status writeAll(int fd, const std::string& text, std::chrono::milliseconds timeout);

// Linux's termios2 (BOTHER) for a rate that is not a termios constant; false when the driver refuses it.
// In its own file: <asm/termbits.h> cannot be included beside <termios.h>.
bool setCustomRate(int fd, int baud);

}  // namespace multidir::hardware::serial

#pragma once
// One controller at a time (docs/hardware.md, "One controller at a time"). Each driver holds a session token
// for its whole life. On every (re)connect it claims the device with it (the device's CLAIM register) before
// anything but a latched stop is written, writes it with every command and heartbeat (SESSION), and gives the
// device back (the release command) when it disconnects. While a session holds it (OWNER), the device takes
// commands only from that session, and stops and e-stops from anyone; it frees itself when the holder has
// written nothing for the lock timeout (a run that crashed or lost its link).
#include <cstdint>
#include <string>

namespace multidir::hardware {

struct ControlLock {
  std::uint16_t session = 0;  // the token this driver claims the device with: 1..65535, fixed per driver
  std::uint16_t owner = 0;    // the device's OWNER as last read: the session in control, 0 when nobody is
  [[nodiscard]] bool held() const { return session != 0 && owner == session; }
};

// A new session token: random, never 0, and unlike every other this process made before (up to 65535).
std::uint16_t newControlSession();

// "session 1a2b", for messages and logs: the same words in both runs' output let the operator tell them apart.
std::string controlSessionText(std::uint16_t session);

}  // namespace multidir::hardware

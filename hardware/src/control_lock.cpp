#include "multidir/hardware/control_lock.h"

#include <atomic>
#include <cstdio>
#include <random>

namespace multidir::hardware {

std::uint16_t newControlSession() {
  // A random start per process, then steps of a number prime to 65535, so that the values 1..65535 all come
  // once before any comes again: two drivers of one process never share a token, two processes rarely do.
  static const std::uint32_t start = std::random_device{}() % 65535u;
  static std::atomic<std::uint32_t> made{0};
  const std::uint32_t k = made.fetch_add(1) % 65535u;
  return static_cast<std::uint16_t>((start + 40507u * k) % 65535u + 1u);
}

std::string controlSessionText(std::uint16_t session) {
  char text[24];
  std::snprintf(text, sizeof text, "session %04x", static_cast<unsigned>(session));
  return text;
}

}  // namespace multidir::hardware

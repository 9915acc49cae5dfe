#pragma once
// Shared by the hardware tests: a simulator on 127.0.0.1 with an ephemeral port, driver options with short
// intervals, and polling with a deadline instead of fixed sleeps.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <future>
#include <string>
#include <thread>

#include "multidir/core/common/result.h"
#include "multidir/hardware/connection.h"
#include "multidir/hardware/device_simulator.h"

namespace multidir::hardware::test {

using namespace std::chrono_literals;

// Polls `condition` every 2 ms until it holds or `limit` passes.
inline bool eventually(const std::function<bool()>& condition, std::chrono::milliseconds limit = 3000ms) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    if (condition()) return true;
    std::this_thread::sleep_for(2ms);
  }
  return condition();
}

// The command's outcome, waiting at most `limit` for the worker.
inline core::Status outcome(std::future<core::Status> future, std::chrono::milliseconds limit = 3000ms) {
  if (future.wait_for(limit) != std::future_status::ready)
    return core::Error{core::ErrorCode::Internal, "the test gave up waiting for the command", "test"};
  return future.get();
}

// Whether the future was ready at once: a refused command must not wait for the worker.
inline bool readyAtOnce(const std::future<core::Status>& future) {
  return future.wait_for(0ms) == std::future_status::ready;
}

inline ConnectionSettings fastSettings(int port, int unitId) {
  ConnectionSettings settings;
  settings.tcp.host = "127.0.0.1";
  settings.tcp.port = port;
  settings.slaveId = unitId;
  settings.responseTimeout = 150ms;
  settings.byteTimeout = 50ms;
  settings.pollInterval = 10ms;
  settings.heartbeatInterval = 30ms;
  settings.reconnectInitialDelay = 20ms;
  settings.reconnectMaxDelay = 200ms;
  return settings;
}

inline std::string messageOf(const core::Status& status) { return status.ok() ? "" : status.error().describe(); }

}  // namespace multidir::hardware::test

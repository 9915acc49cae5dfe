#include "printer/latched_emergency_stop.h"

namespace multidir::hardware {

std::future<core::Status> LatchedEmergencyStop::latch() {
  std::promise<core::Status> promise;
  std::future<core::Status> future = promise.get_future();
  m_stop.kind = StopKind::EmergencyStop;
  m_stop.confirmed = false;
  m_stop.problem = "not sent yet";
  ++m_generation;
  m_due = true;
  m_waiters.emplace_back(m_generation, std::move(promise));
  return future;
}

std::uint64_t LatchedEmergencyStop::take() {
  m_due = false;
  return m_generation;
}

void LatchedEmergencyStop::confirm(std::uint64_t generation) {
  ++m_stop.writes;
  if (generation == m_generation) {
    m_stop.confirmed = true;
    m_stop.problem.clear();
  }
  for (auto it = m_waiters.begin(); it != m_waiters.end();) {
    if (it->first <= generation) {
      it->second.set_value(core::Done{});
      it = m_waiters.erase(it);
    } else {
      ++it;
    }
  }
}

core::Status LatchedEmergencyStop::clear(const std::string& linkName) {
  if (!m_stop.latched()) return core::Done{};
  if (!m_stop.confirmed)
    return core::Error{core::ErrorCode::InvalidParameter,
                       "the printer has not confirmed the emergency stop yet (" + m_stop.problem +
                           "): it cannot be cleared before it took effect",
                       linkName};
  m_stop = StopLatch{};
  return core::Done{};
}

void LatchedEmergencyStop::cancelWaiters(const std::string& linkName) {
  for (auto& waiter : m_waiters)
    waiter.second.set_value(core::Error{core::ErrorCode::Cancelled,
                                        "disconnected before the printer confirmed the emergency stop (it stays "
                                        "latched and is sent first on the next connect)",
                                        linkName});
  m_waiters.clear();
}

}  // namespace multidir::hardware

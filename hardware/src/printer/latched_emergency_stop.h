#pragma once
// The emergency stop a printer link latches (printer_link.h, "Emergency stop"), with the futures of the
// emergencyStop() calls that wait for the printer's answer.
//
// Why a class of its own: every printer link (HTTP in http_printer_link.cpp, Marlin in marlin_link.cpp) must
// keep the same rule ("a stop must always reach the device: it is latched and resent until the device
// confirms it", docs/architecture.md): one copy of the latch, its generations and its waiters keeps the
// links from drifting apart. What confirms a stop stays with each protocol (an HTTP reply, Marlin's report of
// its halt); the Modbus drivers write their stop on their own worker (modbus/link_worker.h), where a refusal
// also counts as an answer, so they keep their own latch.
//
// Not locked itself: every call is made with the owning link's mutex held.
#include <cstdint>
#include <future>
#include <string>
#include <utility>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/stop_latch.h"

namespace multidir::hardware {

class LatchedEmergencyStop {
 public:
  // Latches an emergency stop (a new generation, due to be sent); the future ends once the printer confirmed
  // this generation or a later one (confirm), or when the link disconnects first (cancelWaiters).
  std::future<core::Status> latch();

  // The stop thread: true when the stop should be sent now.
  [[nodiscard]] bool due() const { return m_due; }
  // The stop thread takes the due stop: the generation it is about to send.
  std::uint64_t take();
  // The stop thread sends the stop again (after a failed send, a reconnect, a restarted printer).
  void markDue() { m_due = true; }
  // Why the printer has not confirmed the stop yet.
  void setProblem(std::string problem) { m_stop.problem = std::move(problem); }

  // The printer confirmed the stop sent as `generation`: one more write it answered; the latch is confirmed
  // when no later stop was asked for since; every waiter up to `generation` ends Done.
  void confirm(std::uint64_t generation);

  // clearStop(): refused (InvalidParameter naming `linkName`) until the printer confirmed the stop.
  core::Status clear(const std::string& linkName);
  // disconnect(): the waiters end Cancelled; the stop stays latched and is sent first on the next connect.
  void cancelWaiters(const std::string& linkName);

  [[nodiscard]] const StopLatch& state() const { return m_stop; }
  [[nodiscard]] bool latched() const { return m_stop.latched(); }
  [[nodiscard]] std::uint64_t generation() const { return m_generation; }

 private:
  StopLatch m_stop;
  std::uint64_t m_generation = 0;  // one per latch()
  bool m_due = false;              // to be sent (again) by the stop thread
  std::vector<std::pair<std::uint64_t, std::promise<core::Status>>> m_waiters;
};

}  // namespace multidir::hardware

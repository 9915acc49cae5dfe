#pragma once
// The thread that owns a device's libmodbus context: runs queued commands (urgent ones first), reads the
// status every poll interval, writes the heartbeat every heartbeat interval, and rebuilds a broken link with
// exponential backoff. Drivers supply what to do through hooks; everything here runs on the worker thread
// except start(), stop(), submit() and the stop latch's calls (latchStop, clearStop, stopLatch).
//
// The stop latch (stop_latch.h): a latched stop is written before anything else whenever the link is up and
// it is due, and again right after every reconnect, before onConnected; a write the device refuses (a Modbus
// exception: busy, device failure...) is written again every reconnectInitialDelay until the device takes it.
// Its futures end when the device first answered the write (took it, or refused it: the refusal says that it
// is written again), never because the link was down.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "modbus/modbus_port.h"
#include "multidir/core/common/result.h"
#include "multidir/hardware/connection.h"
#include "multidir/hardware/stop_latch.h"

namespace multidir::hardware {

struct LinkHooks {
  std::function<core::Status(ModbusPort&)> onConnected;  // configure the device after each (re)connect
  std::function<core::Status(ModbusPort&)> poll;         // read the status
  std::function<core::Status(ModbusPort&)> heartbeat;    // write the heartbeat
  std::function<void(LinkState, const std::string& problem)> linkChanged;
  std::function<void()> stopLatchChanged;  // after a latched stop was written or failed
  std::function<void(ModbusPort&)> beforeClose;  // stop(): the link is up for one last request (give control back)
};

class LinkWorker {
 public:
  using Command = std::function<core::Status(ModbusPort&)>;

  LinkWorker(ConnectionSettings settings, std::string deviceLabel, LinkHooks hooks);
  ~LinkWorker();
  LinkWorker(const LinkWorker&) = delete;
  LinkWorker& operator=(const LinkWorker&) = delete;

  // Starts the thread and waits for the outcome of the first connection (connect, onConnected, first poll).
  core::Status start();
  void stop();
  [[nodiscard]] bool running() const;

  // Queues a command. Urgent commands run before anything queued, which is cancelled (Cancelled).
  std::future<core::Status> submit(Command command, bool urgent, const std::string& what);

  // Latches a stop: cancels every queued command (Cancelled) and has `command` written first, now if the link
  // is up, else as soon as it is back, and again after every reconnect until clearStop(). An e-stop already
  // latched is kept when a plain stop is asked for (the stop's future then waits for the e-stop). The future
  // ends Done once the device took the write, with the device's first refusal (Modbus exception), or Cancelled
  // when the worker is stopped first (the latch stays and is written first on the next start()). A refused
  // stop stays latched and unconfirmed and is written again every reconnectInitialDelay until the device
  // takes it: only that confirms it.
  std::future<core::Status> latchStop(StopKind kind, Command command, const std::string& what);
  // The operator allows moves again. Refused (InvalidParameter) while the device has not confirmed the stop.
  core::Status clearStop();
  [[nodiscard]] StopLatch stopLatch() const;

 private:
  struct Pending {
    Command command;
    std::promise<core::Status> promise;
    std::string what;
  };

  void run();
  bool tryConnect();
  void linkBroken(const std::string& problem);
  void failQueued(const core::Error& error);
  // Waits until the deadline, a stop of the worker, a queued command or (link up) a due stop; true when a new
  // stop request woke it.
  bool waitUntil(std::chrono::steady_clock::time_point deadline, bool linkUp);
  // Writes the latched stop (if any) and settles its futures; the write's outcome.
  core::Status sendLatchedStop();
  void cancelStopWaiters(const std::string& why);
  // A latched stop is due and its retry time (after a refusal) has come. Called under m_mutex.
  [[nodiscard]] bool stopDueNow() const;

  ConnectionSettings m_settings;
  std::string m_label;
  LinkHooks m_hooks;
  ModbusPort m_port;

  mutable std::mutex m_mutex;
  std::condition_variable m_wake;
  std::deque<Pending> m_queue;
  bool m_stopRequested = false;
  bool m_running = false;
  bool m_firstAttemptDone = false;
  core::Status m_firstAttempt = core::Done{};

  // The stop latch, guarded by m_mutex.
  StopLatch m_stop;
  Command m_stopCommand;
  std::string m_stopWhat;
  std::uint64_t m_stopGeneration = 0;      // one per latchStop() call
  std::uint64_t m_stopSentGeneration = 0;  // the generation the last successful write carried
  bool m_stopDue = false;                  // asked for and not taken by the device since
  std::chrono::steady_clock::time_point m_stopRetryAt{};  // not before: the device refused the last write
  bool m_stopWake = false;                 // a new stop request the worker has not woken for yet
  bool m_linkUp = false;                   // set by the worker: connected and configured
  std::vector<std::pair<std::uint64_t, std::promise<core::Status>>> m_stopWaiters;
  std::thread m_thread;

  // Worker thread only.
  std::chrono::milliseconds m_backoff{0};
  std::chrono::steady_clock::time_point m_nextAttempt{};
};

}  // namespace multidir::hardware

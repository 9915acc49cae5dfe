#pragma once
// The thread that owns a device's libmodbus context: runs queued commands (urgent ones first), reads the
// status every poll interval, writes the heartbeat every heartbeat interval, and rebuilds a broken link with
// exponential backoff. Drivers supply what to do through hooks; everything here runs on the worker thread
// except start(), stop() and submit().
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <string>
#include <thread>

#include "modbus/modbus_port.h"
#include "multidir/core/common/result.h"
#include "multidir/hardware/connection.h"

namespace multidir::hardware {

struct LinkHooks {
  std::function<core::Status(ModbusPort&)> onConnected;  // configure the device after each (re)connect
  std::function<core::Status(ModbusPort&)> poll;         // read the status
  std::function<core::Status(ModbusPort&)> heartbeat;    // write the heartbeat
  std::function<void(LinkState, const std::string& problem)> linkChanged;
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
  void waitUntil(std::chrono::steady_clock::time_point deadline);

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
  std::thread m_thread;

  // Worker thread only.
  std::chrono::milliseconds m_backoff{0};
  std::chrono::steady_clock::time_point m_nextAttempt{};
};

}  // namespace multidir::hardware

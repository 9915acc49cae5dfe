#pragma once
// The two threads of a printer link (printer_link.h, "Thread model"): the worker, which polls the printer and
// runs the queued commands, and the stop thread, which only sends the latched emergency stop; and the
// handshake connect() waits on (the outcome of the first status read).
//
// Why a class of its own: the HTTP links (http_printer_link.cpp) and the Marlin link (marlin_link.cpp) start,
// wake and stop these threads the same way; one copy keeps connect() and disconnect() alike for every
// protocol. What the threads do stays with each link.
//
// The link's mutex guards this object's state: calls marked "mutex held" need it, start() and stop() must be
// called without it.
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

#include "multidir/core/common/result.h"

namespace multidir::hardware {

class PrinterLinkThreads {
 public:
  explicit PrinterLinkThreads(std::mutex& mutex) : m_mutex(mutex) {}
  PrinterLinkThreads(const PrinterLinkThreads&) = delete;
  PrinterLinkThreads& operator=(const PrinterLinkThreads&) = delete;

  // Mutex held, not running: the link counts as connected from now on (commands are queued), no outcome yet.
  void begin();
  // Starts both threads and waits until the worker reported the first outcome; that outcome.
  core::Status start(std::function<void()> worker, std::function<void()> stopper);
  // False when not running. Else asks both threads to end, wakes them and waits for them; running() stays
  // true until finish(), so that the link settles what is left under its mutex first.
  bool stop();
  // Mutex held: disconnected.
  void finish() { m_running = false; }

  // Mutex held.
  [[nodiscard]] bool running() const { return m_running; }
  [[nodiscard]] bool quitting() const { return m_quit; }
  // The outcome connect() returns: the first one reported; later ones are ignored.
  void reportFirst(core::Status outcome);
  [[nodiscard]] bool firstReported() const { return m_firstDone; }

  // Wake the worker (a command was queued) or the stop thread (a stop is due).
  std::condition_variable& workerWake() { return m_wake; }
  std::condition_variable& stopWake() { return m_stopWake; }

 private:
  std::mutex& m_mutex;
  std::condition_variable m_wake;
  std::condition_variable m_stopWake;
  std::condition_variable m_firstCondition;
  bool m_quit = false;
  bool m_running = false;
  bool m_firstDone = false;
  core::Status m_first = core::Done{};
  std::thread m_worker;
  std::thread m_stopper;
};

}  // namespace multidir::hardware

#include "printer/printer_link_threads.h"

#include <utility>

namespace multidir::hardware {

void PrinterLinkThreads::begin() {
  m_quit = false;
  m_running = true;
  m_firstDone = false;
}

core::Status PrinterLinkThreads::start(std::function<void()> worker, std::function<void()> stopper) {
  m_worker = std::thread(std::move(worker));
  m_stopper = std::thread(std::move(stopper));
  std::unique_lock<std::mutex> lock(m_mutex);
  m_firstCondition.wait(lock, [this] { return m_firstDone; });
  return m_first;
}

bool PrinterLinkThreads::stop() {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_running) return false;
    m_quit = true;
  }
  m_wake.notify_all();
  m_stopWake.notify_all();
  if (m_worker.joinable()) m_worker.join();
  if (m_stopper.joinable()) m_stopper.join();
  return true;
}

void PrinterLinkThreads::reportFirst(core::Status outcome) {
  if (m_firstDone) return;
  m_first = std::move(outcome);
  m_firstDone = true;
  m_firstCondition.notify_all();
}

}  // namespace multidir::hardware

#include "modbus/link_worker.h"

#include <algorithm>
#include <optional>
#include <utility>

namespace multidir::hardware {

using Clock = std::chrono::steady_clock;

LinkWorker::LinkWorker(ConnectionSettings settings, std::string deviceLabel, LinkHooks hooks)
    : m_settings(std::move(settings)),
      m_label(std::move(deviceLabel)),
      m_hooks(std::move(hooks)),
      m_port(m_settings, m_label) {}

LinkWorker::~LinkWorker() { stop(); }

bool LinkWorker::running() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_running;
}

core::Status LinkWorker::start() {
  std::unique_lock<std::mutex> lock(m_mutex);
  if (m_running) return core::Done{};
  m_stopRequested = false;
  m_firstAttemptDone = false;
  m_running = true;
  m_thread = std::thread([this] { run(); });
  m_wake.wait(lock, [this] { return m_firstAttemptDone; });
  return m_firstAttempt;
}

void LinkWorker::stop() {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_running) return;
    m_stopRequested = true;
  }
  m_wake.notify_all();
  if (m_thread.joinable()) m_thread.join();
  std::lock_guard<std::mutex> lock(m_mutex);
  m_running = false;
}

std::future<core::Status> LinkWorker::submit(Command command, bool urgent, const std::string& what) {
  Pending pending{std::move(command), {}, what};
  std::future<core::Status> future = pending.promise.get_future();
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_running || m_stopRequested) {
      pending.promise.set_value(core::Error{core::ErrorCode::InvalidParameter,
                                            m_label + " is not connected: connect first", m_label});
      return future;
    }
    if (urgent) {
      for (Pending& queued : m_queue)
        queued.promise.set_value(core::Error{core::ErrorCode::Cancelled,
                                             queued.what + " was cancelled by " + what + " before it was sent",
                                             m_label});
      m_queue.clear();
      m_queue.push_front(std::move(pending));
    } else {
      m_queue.push_back(std::move(pending));
    }
  }
  m_wake.notify_all();
  return future;
}

void LinkWorker::failQueued(const core::Error& error) {
  std::deque<Pending> failed;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    failed.swap(m_queue);
  }
  for (Pending& pending : failed)
    pending.promise.set_value(core::Error{error.code, pending.what + " was not sent: " + error.message, error.where});
}

void LinkWorker::waitUntil(Clock::time_point deadline) {
  std::unique_lock<std::mutex> lock(m_mutex);
  m_wake.wait_until(lock, deadline, [this] { return m_stopRequested || !m_queue.empty(); });
}

void LinkWorker::linkBroken(const std::string& problem) {
  m_port.close();
  m_backoff = m_backoff.count() == 0 ? m_settings.reconnectInitialDelay
                                     : std::min(m_backoff * 2, m_settings.reconnectMaxDelay);
  m_nextAttempt = Clock::now() + m_backoff;
  if (m_hooks.linkChanged) m_hooks.linkChanged(LinkState::Reconnecting, problem);
  // Commands are never replayed after a reconnect: the situation they were meant for may have changed.
  failQueued(core::Error{core::ErrorCode::DeviceUnreachable, problem, m_label});
}

bool LinkWorker::tryConnect() {
  core::Status status = m_port.open();
  if (status.ok() && m_hooks.onConnected) status = m_hooks.onConnected(m_port);
  if (status.ok() && m_hooks.poll) status = m_hooks.poll(m_port);
  if (status.ok()) {
    m_backoff = std::chrono::milliseconds(0);
    if (m_hooks.linkChanged) m_hooks.linkChanged(LinkState::Connected, "");
  } else {
    linkBroken(status.error().message);
  }
  bool first = false;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_firstAttemptDone) {
      m_firstAttemptDone = true;
      m_firstAttempt = status;
      first = true;
    }
  }
  if (first) m_wake.notify_all();
  return status.ok();
}

void LinkWorker::run() {
  if (m_hooks.linkChanged) m_hooks.linkChanged(LinkState::Connecting, "");
  m_backoff = std::chrono::milliseconds(0);
  m_nextAttempt = Clock::now();
  Clock::time_point nextPoll = Clock::now();
  Clock::time_point nextHeartbeat = Clock::now();
  for (;;) {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (m_stopRequested) break;
    }
    if (!m_port.isOpen()) {
      if (Clock::now() < m_nextAttempt) {
        failQueued(core::Error{core::ErrorCode::DeviceUnreachable,
                               m_label + " is reconnecting: wait until the link is back", m_label});
        waitUntil(m_nextAttempt);
        continue;
      }
      if (!tryConnect()) continue;
      nextPoll = Clock::now() + m_settings.pollInterval;
      nextHeartbeat = Clock::now();
    }

    std::optional<Pending> pending;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (!m_queue.empty()) {
        pending.emplace(std::move(m_queue.front()));
        m_queue.pop_front();
      }
    }
    if (pending) {
      core::Status result = pending->command(m_port);
      const bool broken = !result.ok() && m_port.lastFailureBreaksLink();
      pending->promise.set_value(result);
      if (broken) linkBroken(result.error().message);
      continue;
    }

    const Clock::time_point now = Clock::now();
    if (now >= nextHeartbeat && m_hooks.heartbeat) {
      nextHeartbeat = now + m_settings.heartbeatInterval;
      core::Status result = m_hooks.heartbeat(m_port);
      if (!result.ok() && m_port.lastFailureBreaksLink()) {
        linkBroken(result.error().message);
        continue;
      }
    }
    if (now >= nextPoll && m_hooks.poll) {
      nextPoll = now + m_settings.pollInterval;
      core::Status result = m_hooks.poll(m_port);
      if (!result.ok() && m_port.lastFailureBreaksLink()) {
        linkBroken(result.error().message);
        continue;
      }
    }
    waitUntil(std::min(nextPoll, nextHeartbeat));
  }
  m_port.close();
  failQueued(core::Error{core::ErrorCode::Cancelled, m_label + " was disconnected", m_label});
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_firstAttemptDone) {
      m_firstAttemptDone = true;
      m_firstAttempt = core::Error{core::ErrorCode::Cancelled, m_label + " was disconnected", m_label};
    }
  }
  m_wake.notify_all();
  if (m_hooks.linkChanged) m_hooks.linkChanged(LinkState::Disconnected, "");
}

}  // namespace multidir::hardware

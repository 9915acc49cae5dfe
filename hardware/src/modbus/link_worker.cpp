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

std::future<core::Status> LinkWorker::latchStop(StopKind kind, Command command, const std::string& what) {
  std::promise<core::Status> promise;
  std::future<core::Status> future = promise.get_future();
  std::deque<Pending> cancelled;
  bool running = false;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    running = m_running && !m_stopRequested;
    if (!(m_stop.kind == StopKind::EmergencyStop && kind == StopKind::Stop)) {
      m_stop.kind = kind;
      m_stopCommand = std::move(command);
      m_stopWhat = what;
    }
    m_stop.confirmed = false;
    if (!running)
      m_stop.problem =
          m_label + " is not connected: the " + stopKindName(m_stop.kind) + " is sent first when you connect";
    else if (!m_linkUp)
      m_stop.problem =
          m_label + " is reconnecting: the " + stopKindName(m_stop.kind) + " is sent first when the link is back";
    else
      m_stop.problem = "the " + std::string(stopKindName(m_stop.kind)) + " is being written to " + m_label;
    m_stopDue = true;
    m_stopRetryAt = Clock::time_point{};  // a new request is written at once, even after a refusal
    m_stopWake = true;
    ++m_stopGeneration;
    if (running) m_stopWaiters.emplace_back(m_stopGeneration, std::move(promise));
    cancelled.swap(m_queue);
  }
  for (Pending& queued : cancelled)
    queued.promise.set_value(core::Error{core::ErrorCode::Cancelled,
                                         queued.what + " was cancelled by " + what + " before it was sent", m_label});
  if (!running) {
    promise.set_value(core::Error{
        core::ErrorCode::InvalidParameter,
        m_label + " is not connected: " + what + " was not sent; it stays latched and is sent first when you connect",
        m_label});
    return future;
  }
  m_wake.notify_all();
  return future;
}

core::Status LinkWorker::clearStop() {
  std::lock_guard<std::mutex> lock(m_mutex);
  if (!m_stop.latched()) return core::Done{};
  if (!m_stop.confirmed)
    return core::Error{core::ErrorCode::InvalidParameter,
                       m_label + ": the " + stopKindName(m_stop.kind) +
                           " cannot be cleared yet: the device has not confirmed it (" + m_stop.problem +
                           "); wait until the link is back and the device took it",
                       m_label};
  m_stop = StopLatch{};
  m_stopCommand = nullptr;
  m_stopWhat.clear();
  m_stopDue = false;
  return core::Done{};
}

StopLatch LinkWorker::stopLatch() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_stop;
}

core::Status LinkWorker::sendLatchedStop() {
  Command command;
  std::uint64_t generation = 0;
  StopKind kind = StopKind::None;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_stop.latched()) return core::Done{};
    kind = m_stop.kind;
    command = m_stopCommand;
    generation = m_stopGeneration;
    m_stopDue = false;
  }
  core::Status result = command(m_port);
  const bool linkFailure = !result.ok() && m_port.lastFailureBreaksLink();
  if (!result.ok() && !linkFailure) {
    // The device refused it (busy, device failure...): it has not stopped, so the stop stays due.
    core::Error refused = result.error();
    refused.message += "; the " + std::string(stopKindName(kind)) + " stays latched and MultiDir writes it again " +
                       "every " + std::to_string(m_settings.reconnectInitialDelay.count()) + " ms until " +
                       m_label + " takes it";
    result = refused;
  }
  std::vector<std::promise<core::Status>> settled;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_stop.latched()) {  // the operator may have cleared it while it was written again
      if (result.ok()) {
        ++m_stop.writes;
        m_stopSentGeneration = std::max(m_stopSentGeneration, generation);
        if (m_stopSentGeneration == m_stopGeneration) {
          m_stop.confirmed = true;
          m_stop.problem.clear();
        }
      } else {
        if (!m_stop.confirmed) m_stop.problem = result.error().message;
        // Written again until the device takes it: after the reconnect when the link was lost, after a short
        // delay when the device refused it (whatever it answers, only taking the write confirms the stop).
        m_stopDue = true;
        if (!linkFailure) m_stopRetryAt = Clock::now() + m_settings.reconnectInitialDelay;
      }
    }
    // The futures end with the device's first answer, taken or refused (a refusal goes on being written).
    if (result.ok() || !linkFailure) {
      for (auto it = m_stopWaiters.begin(); it != m_stopWaiters.end();) {
        if (it->first > generation) {
          ++it;
          continue;
        }
        settled.push_back(std::move(it->second));
        it = m_stopWaiters.erase(it);
      }
    }
  }
  for (std::promise<core::Status>& promise : settled) promise.set_value(result);
  if (m_hooks.stopLatchChanged) m_hooks.stopLatchChanged();
  return result;
}

void LinkWorker::cancelStopWaiters(const std::string& why) {
  std::vector<std::pair<std::uint64_t, std::promise<core::Status>>> waiters;
  std::string what;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    waiters.swap(m_stopWaiters);
    what = m_stopWhat;
    if (m_stop.latched() && !m_stop.confirmed) m_stop.problem = why;
  }
  for (auto& waiter : waiters)
    waiter.second.set_value(core::Error{
        core::ErrorCode::Cancelled,
        what + " was not confirmed: " + why + "; it stays latched and is sent first when you connect again", m_label});
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

bool LinkWorker::stopDueNow() const {
  return m_stopDue && m_stop.latched() && Clock::now() >= m_stopRetryAt;
}

bool LinkWorker::waitUntil(Clock::time_point deadline, bool linkUp) {
  std::unique_lock<std::mutex> lock(m_mutex);
  // Link up: a due stop is written at once. Link down: a new stop request cuts the backoff short.
  m_wake.wait_until(lock, deadline, [this, linkUp] {
    return m_stopRequested || !m_queue.empty() || (linkUp ? stopDueNow() : m_stopWake);
  });
  const bool newStop = m_stopWake;
  m_stopWake = false;
  return newStop;
}

void LinkWorker::linkBroken(const std::string& problem) {
  m_port.close();
  bool stopWaiting = false;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_linkUp = false;
    if (m_stop.latched() && !m_stop.confirmed) {
      stopWaiting = true;
      m_stop.problem =
          "the link is down (" + problem + "); the " + stopKindName(m_stop.kind) + " is sent first when it is back";
    }
  }
  // An unconfirmed stop keeps the retries at the shortest delay.
  m_backoff = m_backoff.count() == 0 || stopWaiting ? m_settings.reconnectInitialDelay
                                                    : std::min(m_backoff * 2, m_settings.reconnectMaxDelay);
  m_nextAttempt = Clock::now() + m_backoff;
  if (m_hooks.linkChanged) m_hooks.linkChanged(LinkState::Reconnecting, problem);
  // Commands are never replayed after a reconnect: the situation they were meant for may have changed.
  failQueued(core::Error{core::ErrorCode::DeviceUnreachable, problem, m_label});
}

bool LinkWorker::tryConnect() {
  core::Status status = m_port.open();
  // A latched stop goes first, before the heartbeat or anything else: the device may still be finishing the
  // move the stop was meant to end. Only a lost link fails the attempt; a refusal was reported to the caller.
  if (status.ok() && stopLatch().latched()) {
    core::Status stopped = sendLatchedStop();
    if (!stopped.ok() && m_port.lastFailureBreaksLink()) status = stopped;
  }
  if (status.ok() && m_hooks.onConnected) status = m_hooks.onConnected(m_port);
  if (status.ok() && m_hooks.poll) status = m_hooks.poll(m_port);
  if (status.ok()) {
    m_backoff = std::chrono::milliseconds(0);
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_linkUp = true;
    }
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
        // A stop asked for while the link is down: try to reconnect now rather than after the backoff.
        if (waitUntil(m_nextAttempt, false)) {
          m_nextAttempt = Clock::now();
          if (m_hooks.stopLatchChanged) m_hooks.stopLatchChanged();
        }
        continue;
      }
      if (!tryConnect()) continue;
      nextPoll = Clock::now() + m_settings.pollInterval;
      nextHeartbeat = Clock::now();
    }

    bool stopDue = false;
    Clock::time_point stopRetryAt = Clock::time_point::max();
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      stopDue = stopDueNow();
      if (m_stopDue && m_stop.latched()) stopRetryAt = m_stopRetryAt;
    }
    if (stopDue) {
      core::Status result = sendLatchedStop();
      if (!result.ok() && m_port.lastFailureBreaksLink()) linkBroken(result.error().message);
      continue;
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
    waitUntil(std::min({nextPoll, nextHeartbeat, stopRetryAt}), true);
  }
  if (m_port.isOpen() && m_hooks.beforeClose) m_hooks.beforeClose(m_port);
  m_port.close();
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_linkUp = false;
  }
  failQueued(core::Error{core::ErrorCode::Cancelled, m_label + " was disconnected", m_label});
  cancelStopWaiters(m_label + " was disconnected");
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

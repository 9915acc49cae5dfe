#include "ui/device/printer_link_owner.h"

#include <QThread>
#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <utility>

#include "multidir/hardware/printer_url.h"

namespace multidir::ui {

// One link's connect and disconnect, run on helper threads: the disconnect waits until the connect returned
// (a link's disconnect must not race its connect's first read).
struct PrinterLinkOwner::Session {
  std::shared_ptr<hardware::PrinterLink> link;
  std::mutex mutex;
  std::condition_variable connected;
  bool connectReturned = false;

  void waitConnectReturned() {
    std::unique_lock<std::mutex> lock(mutex);
    connected.wait(lock, [this] { return connectReturned; });
  }
};

PrinterLinkOwner::PrinterLinkOwner(QObject* parent) : QObject(parent) {
  m_readTimer.setInterval(100);
  connect(&m_readTimer, &QTimer::timeout, this, &PrinterLinkOwner::readStatus);
}

PrinterLinkOwner::~PrinterLinkOwner() {
  disconnectPrinter();
  for (QThread* thread : m_threads) {
    thread->wait();
    delete thread;
  }
}

void PrinterLinkOwner::setReadInterval(std::chrono::milliseconds interval) {
  m_readTimer.setInterval(static_cast<int>(interval.count()));
}

void PrinterLinkOwner::runInBackground(std::function<void()> work, std::function<void()> done) {
  QThread* thread = QThread::create([work = std::move(work)] {
    try {
      work();
    } catch (...) {  // the link reports its problems as values; nothing may escape a helper thread
    }
  });
  m_threads.push_back(thread);
  connect(thread, &QThread::finished, this, [this, thread, done = std::move(done)] {
    m_threads.erase(std::remove(m_threads.begin(), m_threads.end(), thread), m_threads.end());
    thread->deleteLater();
    if (done) done();
  });
  thread->start();
}

core::Status PrinterLinkOwner::connectPrinter(const QString& url, const QString& apiKey) {
  core::Result<std::unique_ptr<hardware::PrinterLink>> made =
      hardware::makePrinterLinkFromUrl(url.trimmed().toStdString(), apiKey.toStdString(), m_options);
  if (!made) return made.error();
  disconnectPrinter();
  const std::uint64_t generation = ++m_generation;
  auto session = std::make_shared<Session>();
  session->link = std::shared_ptr<hardware::PrinterLink>(std::move(*made));
  m_session = session;
  m_link = session->link;
  m_status = hardware::PrinterStatus{};
  m_status.link = hardware::LinkState::Connecting;
  m_hasRead = false;
  m_staleSince.reset();

  auto outcome = std::make_shared<core::Status>(core::Done{});
  runInBackground(
      [session, outcome] {
        *outcome = session->link->connect();
        std::lock_guard<std::mutex> lock(session->mutex);
        session->connectReturned = true;
        session->connected.notify_all();
      },
      [this, outcome, generation] {
        if (generation != m_generation || !m_link) return;  // superseded or disconnected meanwhile
        readStatus();
        if (outcome->ok())
          emit connectFinished(true, {});
        else
          emit connectFinished(false, tr("The printer does not answer yet; MultiDir keeps trying. %1")
                                          .arg(QString::fromStdString(outcome->error().describe())));
      });
  m_readTimer.start();
  emit openChanged(true);
  emit statusChanged();
  return core::Done{};
}

void PrinterLinkOwner::disconnectPrinter() {
  if (!m_session) return;
  ++m_generation;
  std::shared_ptr<Session> session = std::move(m_session);
  runInBackground([session] {
    session->waitConnectReturned();
    session->link->disconnect();
  });
  m_session.reset();
  m_link.reset();
  m_readTimer.stop();
  m_status = hardware::PrinterStatus{};
  m_hasRead = false;
  m_staleSince.reset();
  m_stop = {};
  m_restart = {};
  emit openChanged(false);
  emit statusChanged();
}

void PrinterLinkOwner::emergencyStop() {
  const QString name = tr("Printer E-STOP");
  if (!m_link) {
    emit commandFailed(name, tr("%1 refused: no printer is connected.").arg(name));
    return;
  }
  m_stop = m_link->emergencyStop();
  readStatus();
}

core::Status PrinterLinkOwner::clearStop() {
  if (!m_link)
    return core::Error{core::ErrorCode::InvalidParameter, "no printer is connected", "printer"};
  const core::Status cleared = m_link->clearStop();
  readStatus();
  return cleared;
}

void PrinterLinkOwner::restartFirmware() {
  if (!m_link) {
    emit commandFailed(tr("Restart firmware"), tr("Restart firmware refused: no printer is connected."));
    return;
  }
  m_restart = m_link->restartFirmware();
  readStatus();
}

QString PrinterLinkOwner::printerName() const {
  return m_link ? QString::fromStdString(m_link->name()) : QString();
}

void PrinterLinkOwner::readStatus() {
  if (!m_link) return;
  m_status = m_link->status();
  if (!m_status.linkLost) {
    m_hasRead = true;
    m_staleSince.reset();
  } else if (m_hasRead && !m_staleSince) {
    m_staleSince = QDateTime::currentDateTime();
  }
  if (m_stop.valid() && m_stop.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    core::Status sent = core::Done{};
    try {
      sent = m_stop.get();
    } catch (const std::exception& e) {  // a broken promise: the link went away
      sent = core::Error{core::ErrorCode::Cancelled, e.what(), "printer"};
    }
    if (!sent.ok()) emit commandFailed(tr("Printer E-STOP"), QString::fromStdString(sent.error().describe()));
  }
  if (m_restart.valid() && m_restart.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    core::Status restarted = core::Done{};
    try {
      restarted = m_restart.get();
    } catch (const std::exception& e) {  // a broken promise: the link went away
      restarted = core::Error{core::ErrorCode::Cancelled, e.what(), "printer"};
    }
    emit firmwareRestartFinished(restarted.ok() ? QString() : QString::fromStdString(restarted.error().describe()));
  }
  emit statusChanged();
}

}  // namespace multidir::ui

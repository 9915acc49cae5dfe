#include "ui/jobs/cell_job.h"

#include <QThread>
#include <exception>
#include <memory>

namespace multidir::ui {

CellJob::CellJob(QObject* parent) : QObject(parent) {}

CellJob::~CellJob() {
  if (m_thread) {
    m_job.cancel();
    m_thread->wait();
    delete m_thread;
  }
}

bool CellJob::start(Work work) {
  if (m_thread) return false;
  const int generation = ++m_generation;
  m_job = core::JobContext([this, generation](double fraction, const std::string&) {
    // From the worker: queued to the GUI thread; `this` outlives the worker (the destructor waits).
    QMetaObject::invokeMethod(
        this, [this, generation, fraction] {
          if (generation == m_generation && m_thread) emit progressed(fraction);
        },
        Qt::QueuedConnection);
  });
  auto error = std::make_shared<QString>();
  core::JobContext job = m_job;  // copies share the cancellation flag
  m_thread = QThread::create([work = std::move(work), job, error]() {
    try {
      *error = work(job);
    } catch (const std::exception& e) {
      *error = QString::fromUtf8(e.what());
    }
  });
  connect(m_thread, &QThread::finished, this, [this, error, job] {
    QThread* thread = m_thread;
    m_thread = nullptr;
    thread->deleteLater();
    if (job.isCancelled()) {
      emit cancelled();
    } else {
      emit finished(*error);
    }
  });
  m_thread->start();
  return true;
}

void CellJob::cancel() {
  if (m_thread) m_job.cancel();
}

}  // namespace multidir::ui

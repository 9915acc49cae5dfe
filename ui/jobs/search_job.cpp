#include "ui/jobs/search_job.h"

#include <QThread>
#include <exception>
#include <mutex>
#include <new>
#include <optional>

#include "multidir/core/search/decompose.h"
#include "ui/common/error_text.h"
#include "ui/jobs/support_growth.h"

namespace multidir::ui {

// State the worker writes and the GUI thread reads. Reports are coalesced: the worker stores the latest one
// and posts a delivery only when none is pending, so a fast search cannot flood the event queue.
struct SearchJob::Shared {
  std::mutex mutex;
  std::optional<core::SearchProgress> progress;
  double fraction = 0.0;
  std::string phase;
  bool fractionChanged = false;
  bool deliveryPending = false;

  // Outcome, read after the thread finished.
  std::optional<core::Result<core::Decomposition>> result;
  GrownSupports supports;
  QString headline;
  QString detail;
};

SearchJob::SearchJob(QObject* parent) : QObject(parent) {
  static const int registered = qRegisterMetaType<multidir::core::SearchProgress>() +
                                qRegisterMetaType<multidir::ui::SearchRun>();
  (void)registered;
}

SearchJob::~SearchJob() {
  if (m_thread) {
    m_job.cancel();
    m_supportsJob.cancel();
    m_thread->wait();
    delete m_thread;
  }
}

bool SearchJob::start(std::shared_ptr<const core::TriangleMesh> model, const core::MachineSpec& machine,
                      const core::SearchOptions& options, int axisSearchCount) {
  if (m_thread || !model) return false;
  m_job = core::JobContext();
  auto shared = std::make_shared<Shared>();
  m_shared = shared;
  // `this` outlives the worker (the destructor waits for it); a queued call whose context object is gone
  // is dropped by Qt, and one from an earlier search is ignored.
  auto post = [shared, this] {
    // Called with shared->mutex held.
    if (shared->deliveryPending) return;
    shared->deliveryPending = true;
    QMetaObject::invokeMethod(
        this,
        [this, shared] {
          if (m_shared == shared) deliverProgress();
        },
        Qt::QueuedConnection);
  };
  auto report = [shared, post](double fraction, const std::string& phase) {
    std::lock_guard<std::mutex> lock(shared->mutex);
    shared->fraction = fraction;
    shared->phase = phase;
    shared->fractionChanged = true;
    post();
  };
  // The search's own phases ("search done" even when cancelled) say less than its read-out
  // (SearchProgress): only the phases after it are named.
  m_job = core::JobContext([report](double fraction, const std::string&) { report(kSearchShare * fraction, {}); });
  m_supportsJob = core::JobContext([report](double fraction, const std::string& phase) {
    report(kSearchShare + (1.0 - kSearchShare) * fraction, phase);
  });
  const core::SearchProgressSink sink = [shared, post](const core::SearchProgress& progress) {
    std::lock_guard<std::mutex> lock(shared->mutex);
    shared->progress = progress;
    // One bar over the search's stages (the apart machine runs two searches): their share of the search's.
    if (kSearchShare * progress.fraction > shared->fraction) {
      shared->fraction = kSearchShare * progress.fraction;
      shared->fractionChanged = true;
    }
    post();
  };

  SearchRun run;
  run.machine = machine;
  run.options = options;
  run.axisSearchCount = machine.kind == core::MachineKind::RotaryPlatform ? std::max(0, axisSearchCount) : 0;
  core::JobContext job = m_job;  // copies share the cancellation flag
  core::JobContext supportsJob = m_supportsJob;
  const std::string supportsPhase = tr("growing supports").toStdString();
  m_thread = QThread::create([shared, model, run, job, supportsJob, supportsPhase, sink]() mutable {
    // Nothing may escape a worker thread: whatever goes wrong becomes a message.
    try {
      if (run.axisSearchCount > 0) {
        shared->result = core::decomposeWithAxisSearch(*model, run.machine, run.options, run.axisSearchCount, job, sink);
      } else {
        shared->result = core::decompose(*model, run.machine, run.options, job, sink);
      }
    } catch (const std::bad_alloc&) {
      shared->result.reset();
      shared->headline = tr("Not enough memory for this search: lower the beam width or the number of normals.");
    } catch (const std::exception& e) {
      shared->result.reset();
      shared->headline = tr("Unexpected error during the search.");
      shared->detail = QString::fromLocal8Bit(e.what());
    } catch (...) {
      shared->result.reset();
      shared->headline = tr("Unexpected error during the search.");
    }
    if (shared->result && shared->result->ok()) {
      shared->supports = growSupports(*model, shared->result->value(), run.machine, supportsJob, supportsPhase);
    }
  });
  connect(m_thread, &QThread::finished, this, [this, shared, run]() mutable {
    if (m_shared != shared) return;
    m_thread->deleteLater();
    m_thread = nullptr;
    deliverProgress();  // the last report, before the result
    if (shared->result && shared->result->ok()) {
      run.plan = std::make_shared<const core::Decomposition>(std::move(shared->result->value()));
      run.supports = std::move(shared->supports.sets);
      run.supportsNote = shared->supports.note;
      emit runningChanged(false);
      emit finished(run);
      return;
    }
    QString headline = shared->headline;
    QString detail = shared->detail;
    if (shared->result) {
      headline = errorHeadline(shared->result->error().code);
      detail = QString::fromStdString(shared->result->error().describe());
    }
    emit runningChanged(false);
    emit failed(headline, detail);
  });
  m_thread->start();
  emit runningChanged(true);
  return true;
}

void SearchJob::cancel() {
  if (!m_thread) return;
  m_job.cancel();
  m_supportsJob.cancel();
}

void SearchJob::deliverProgress() {
  if (!m_shared) return;
  std::optional<core::SearchProgress> progress;
  std::optional<std::pair<double, QString>> fraction;
  {
    std::lock_guard<std::mutex> lock(m_shared->mutex);
    m_shared->deliveryPending = false;
    progress = m_shared->progress;
    m_shared->progress.reset();
    if (m_shared->fractionChanged) {
      fraction = std::make_pair(m_shared->fraction, QString::fromStdString(m_shared->phase));
      m_shared->fractionChanged = false;
    }
  }
  if (fraction) emit fractionChanged(fraction->first, fraction->second);
  if (progress) emit progressed(*progress);
}

}  // namespace multidir::ui

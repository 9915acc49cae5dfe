#include "ui/jobs/pose_search_job.h"

#include <QThread>
#include <exception>
#include <mutex>
#include <new>
#include <optional>

#include "ui/common/error_text.h"

namespace multidir::ui {
namespace {

PoseSearchJob::Phase phaseOf(const std::string& name) {
  if (name == "given up search") return PoseSearchJob::Phase::GivenUpSearch;
  if (name == "pose searches") return PoseSearchJob::Phase::FullSearches;
  if (name == "pose search done") return PoseSearchJob::Phase::Done;
  return PoseSearchJob::Phase::CheapScores;
}

}  // namespace

// State the worker writes and the GUI thread reads; reports are coalesced as in SearchJob.
struct PoseSearchJob::Shared {
  std::mutex mutex;
  double fraction = 0.0;
  Phase phase = Phase::GivenUpSearch;
  bool changed = false;
  bool deliveryPending = false;

  // Outcome, read after the thread finished.
  std::optional<core::Result<core::PoseSearchResult>> result;
  QString headline;
  QString detail;
};

PoseSearchJob::PoseSearchJob(QObject* parent) : QObject(parent) {
  static const int registered = qRegisterMetaType<multidir::ui::PoseRun>();
  (void)registered;
}

PoseSearchJob::~PoseSearchJob() {
  if (m_thread) {
    m_job.cancel();
    m_thread->wait();
    delete m_thread;
  }
}

bool PoseSearchJob::start(std::shared_ptr<const core::TriangleMesh> model, const core::MachineSpec& machine,
                          const core::SearchOptions& options, const core::PoseOptions& poseOptions) {
  if (m_thread || !model) return false;
  auto shared = std::make_shared<Shared>();
  m_shared = shared;
  // `this` outlives the worker (the destructor waits for it); a delivery from an earlier search is ignored.
  m_job = core::JobContext([shared, this](double fraction, const std::string& phase) {
    std::lock_guard<std::mutex> lock(shared->mutex);
    shared->fraction = fraction;
    shared->phase = phaseOf(phase);
    shared->changed = true;
    if (shared->deliveryPending) return;
    shared->deliveryPending = true;
    QMetaObject::invokeMethod(
        this,
        [this, shared] {
          if (m_shared == shared) deliverProgress();
        },
        Qt::QueuedConnection);
  });

  PoseRun run;
  run.model = model;
  run.machine = machine;
  run.options = options;
  run.poseOptions = poseOptions;
  core::JobContext job = m_job;  // copies share the cancellation flag
  m_thread = QThread::create([shared, run, job]() mutable {
    // Nothing may escape a worker thread: whatever goes wrong becomes a message.
    try {
      shared->result = core::decomposeWithPoseSearch(*run.model, run.machine, run.options, run.poseOptions, job);
    } catch (const std::bad_alloc&) {
      shared->result.reset();
      shared->headline = tr("Not enough memory for the pose search: lower the beam width, the number of normals "
                            "or the number of poses.");
    } catch (const std::exception& e) {
      shared->result.reset();
      shared->headline = tr("Unexpected error during the pose search.");
      shared->detail = QString::fromLocal8Bit(e.what());
    } catch (...) {
      shared->result.reset();
      shared->headline = tr("Unexpected error during the pose search.");
    }
  });
  connect(m_thread, &QThread::finished, this, [this, shared, run]() mutable {
    if (m_shared != shared) return;
    m_thread->deleteLater();
    m_thread = nullptr;
    deliverProgress();  // the last report, before the result
    if (shared->result && shared->result->ok()) {
      auto result = std::make_shared<core::PoseSearchResult>(std::move(shared->result->value()));
      run.chosenRun.machine = core::machineForPose(run.machine, result->chosen.up);
      run.chosenRun.options = run.options;
      run.chosenRun.plan = std::make_shared<const core::Decomposition>(std::move(result->plan));
      result->plan = core::Decomposition();  // held once, by chosenRun
      run.result = std::move(result);
      emit runningChanged(false);
      emit finished(run);
      return;
    }
    QString headline = shared->headline;
    QString detail = shared->detail;
    bool cancelled = false;
    if (shared->result) {
      cancelled = shared->result->error().code == core::ErrorCode::Cancelled;
      headline = cancelled ? tr("The pose search was cancelled before any pose finished.")
                           : errorHeadline(shared->result->error().code);
      detail = QString::fromStdString(shared->result->error().describe());
    }
    emit runningChanged(false);
    emit failed(headline, detail, cancelled);
  });
  m_thread->start();
  emit runningChanged(true);
  return true;
}

void PoseSearchJob::cancel() {
  if (m_thread) m_job.cancel();
}

void PoseSearchJob::deliverProgress() {
  if (!m_shared) return;
  std::optional<std::pair<double, Phase>> report;
  {
    std::lock_guard<std::mutex> lock(m_shared->mutex);
    m_shared->deliveryPending = false;
    if (m_shared->changed) report = std::make_pair(m_shared->fraction, m_shared->phase);
    m_shared->changed = false;
  }
  if (report) emit progressed(report->first, report->second);
}

}  // namespace multidir::ui

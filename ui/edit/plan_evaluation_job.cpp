#include "ui/edit/plan_evaluation_job.h"

#include <QThread>
#include <QTimer>
#include <exception>
#include <new>

#include "multidir/core/search/plan_from_planes.h"
#include "ui/jobs/support_growth.h"

namespace multidir::ui {

// Written by the worker, read on the GUI thread after QThread::finished (which orders the two).
struct PlanEvaluationJob::Outcome {
  std::optional<core::Error> error;
  EvaluatedPlan evaluated;
};

PlanEvaluationJob::PlanEvaluationJob(QObject* parent) : QObject(parent) {
  static const int registered =
      qRegisterMetaType<multidir::core::Error>() + qRegisterMetaType<multidir::ui::EvaluatedPlan>();
  (void)registered;
}

PlanEvaluationJob::~PlanEvaluationJob() {
  if (m_thread) {
    m_supportsJob.cancel();
    m_thread->wait();
    delete m_thread;
  }
}

quint64 PlanEvaluationJob::evaluate(PlanEvaluationRequest request) {
  const quint64 ticket = ++m_lastTicket;
  setAwaited(ticket);
  if (m_thread) m_supportsJob.cancel();  // its outcome is dropped: do not finish its supports
  if (!request.model) {
    m_waiting.reset();
    // Reported from the event loop like every other outcome, so callers see one order of events.
    QTimer::singleShot(0, this, [this, ticket] {
      if (m_awaited != ticket) return;
      setAwaited(0);
      emit refused(ticket,
                   core::Error{core::ErrorCode::EmptyMesh, "there is no model to cut: open the plan's model", "model"});
    });
    return ticket;
  }
  if (m_thread) {
    m_waiting.emplace(ticket, std::move(request));
  } else {
    start(ticket, std::move(request));
  }
  return ticket;
}

void PlanEvaluationJob::discard() {
  m_waiting.reset();
  if (m_thread) m_supportsJob.cancel();
  setAwaited(0);
}

void PlanEvaluationJob::setAwaited(quint64 ticket) {
  const bool wasBusy = isBusy();
  m_awaited = ticket;
  if (wasBusy != isBusy()) emit busyChanged(isBusy());
}

void PlanEvaluationJob::start(quint64 ticket, PlanEvaluationRequest request) {
  auto outcome = std::make_shared<Outcome>();
  m_outcome = outcome;
  m_runningTicket = ticket;
  m_supportsJob = core::JobContext();
  ++m_started;
  core::JobContext supportsJob = m_supportsJob;  // copies share the cancellation flag
  m_thread = QThread::create([outcome, request = std::move(request), supportsJob]() mutable {
    // Nothing may escape a worker thread: whatever goes wrong becomes an error value.
    try {
      core::Result<core::Decomposition> plan =
          core::planFromClippingPlanes(*request.model, request.machine, request.options, request.planes);
      if (!plan) {
        outcome->error = plan.error();
        return;
      }
      outcome->evaluated.plan = std::make_shared<const core::Decomposition>(std::move(plan.value()));
    } catch (const std::bad_alloc&) {
      outcome->error = core::Error{core::ErrorCode::TooLarge, "there is not enough memory to rebuild the plan", "plan"};
      return;
    } catch (const std::exception& e) {
      outcome->error =
          core::Error{core::ErrorCode::Internal, std::string("rebuilding the plan failed: ") + e.what(), "plan"};
      return;
    } catch (...) {
      outcome->error = core::Error{core::ErrorCode::Internal, "rebuilding the plan failed", "plan"};
      return;
    }
    // The note growSupports leaves when cancelled is never shown: a cancelled evaluation's outcome is dropped.
    GrownSupports grown = growSupports(*request.model, *outcome->evaluated.plan, request.machine, supportsJob);
    outcome->evaluated.supports = std::move(grown.sets);
    outcome->evaluated.supportsNote = grown.note;
  });
  connect(m_thread, &QThread::finished, this, &PlanEvaluationJob::finishRunning);
  m_thread->start();
}

void PlanEvaluationJob::finishRunning() {
  m_thread->deleteLater();
  m_thread = nullptr;
  const std::shared_ptr<Outcome> outcome = std::move(m_outcome);
  const quint64 ticket = m_runningTicket;
  if (m_waiting) {
    auto waiting = std::move(*m_waiting);
    m_waiting.reset();
    start(waiting.first, std::move(waiting.second));
  }
  if (ticket != m_awaited || !outcome) return;
  setAwaited(0);
  if (outcome->evaluated.plan) {
    emit evaluated(ticket, outcome->evaluated);
  } else {
    emit refused(ticket, outcome->error.value_or(core::Error{core::ErrorCode::Internal, "no plan came back", "plan"}));
  }
}

}  // namespace multidir::ui

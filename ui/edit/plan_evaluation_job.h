#pragma once
// Rebuilds edited plans off the GUI thread: core::planFromClippingPlanes on a QThread of its own, then, for a
// plan with risky area left, its supports (core::generateSupports with default SupportOptions, as a search
// grows them), one evaluation at a time. The latest request wins: a request still waiting is replaced by a
// newer one, and the outcome of one already running when a newer one came is dropped (its supports are
// cancelled). So a drag that asks for a plan at every mouse move has at most one evaluation running and one
// waiting, and the GUI thread never waits for core (the destructor waits for the one running).
//
// Thread: create and call from the GUI thread; the signals are emitted there too.
#include <QMetaType>
#include <QObject>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/core/supports/support_set.h"

class QThread;

namespace multidir::ui {

// What to evaluate: the model, the machine with the plan's rotation axis, the options the plan was made
// with (alpha_max, supported band, platform tolerance) and the planes in clipping order.
struct PlanEvaluationRequest {
  std::shared_ptr<const core::TriangleMesh> model;
  core::MachineSpec machine;
  core::SearchOptions options;
  std::vector<core::Plane> planes;
};

// A plan core accepted, with its supports.
struct EvaluatedPlan {
  std::shared_ptr<const core::Decomposition> plan;  // never null in evaluated()
  // One set per region in printing order; null when none were grown (J_G = 0, or supportsNote says why).
  std::shared_ptr<const std::vector<core::SupportSet>> supports;
  QString supportsNote;  // translated; empty when supports were grown or not needed
};

class PlanEvaluationJob : public QObject {
  Q_OBJECT

 public:
  explicit PlanEvaluationJob(QObject* parent = nullptr);
  // Waits for the evaluation running, if any; its outcome is dropped.
  ~PlanEvaluationJob() override;
  PlanEvaluationJob(const PlanEvaluationJob&) = delete;
  PlanEvaluationJob& operator=(const PlanEvaluationJob&) = delete;

  // Asks for `request` to be evaluated and returns its ticket (increasing); every earlier request's outcome
  // is dropped. A request without a model is refused at once (through refused(), later in the event loop).
  quint64 evaluate(PlanEvaluationRequest request);
  // Drops every outcome still to come (a new plan replaced the one being edited).
  void discard();
  // An outcome is still to come.
  [[nodiscard]] bool isBusy() const { return m_awaited != 0; }
  // Evaluations started so far (dropped ones included): lets a caller check that edits were coalesced.
  [[nodiscard]] int evaluationsStarted() const { return m_started; }

 signals:
  // The plan for the latest request.
  void evaluated(quint64 ticket, const multidir::ui::EvaluatedPlan& plan);
  // Core refused the latest request's planes (or could not evaluate them); `error.where` names the plane.
  void refused(quint64 ticket, const multidir::core::Error& error);
  void busyChanged(bool busy);

 private:
  struct Outcome;
  void start(quint64 ticket, PlanEvaluationRequest request);
  void finishRunning();
  void setAwaited(quint64 ticket);

  QThread* m_thread = nullptr;
  quint64 m_runningTicket = 0;
  std::shared_ptr<Outcome> m_outcome;
  core::JobContext m_supportsJob;  // the running evaluation's supports: cancelled when it is superseded
  std::optional<std::pair<quint64, PlanEvaluationRequest>> m_waiting;
  quint64 m_lastTicket = 0;
  quint64 m_awaited = 0;  // the ticket whose outcome will be reported; 0: none
  int m_started = 0;
};

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::core::Error)
Q_DECLARE_METATYPE(multidir::ui::EvaluatedPlan)

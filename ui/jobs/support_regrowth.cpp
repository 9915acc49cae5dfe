#include "ui/jobs/support_regrowth.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>

namespace multidir::ui {

SupportRegrowth::SupportRegrowth(QObject* parent) : QObject(parent) {}

SupportRegrowth::~SupportRegrowth() {
  m_job.cancel();
  for (QFuture<GrownSupports>& future : m_futures) future.waitForFinished();
}

void SupportRegrowth::start(std::shared_ptr<const core::TriangleMesh> model,
                            std::shared_ptr<const core::Decomposition> plan, const core::MachineSpec& machine) {
  cancel();
  if (!model || !plan) return;
  m_job = core::JobContext();
  m_plan = plan;
  const quint64 generation = ++m_generation;
  m_futures.erase(std::remove_if(m_futures.begin(), m_futures.end(),
                                 [](const QFuture<GrownSupports>& f) { return f.isFinished(); }),
                  m_futures.end());
  auto* watcher = new QFutureWatcher<GrownSupports>(this);
  connect(watcher, &QFutureWatcher<GrownSupports>::finished, this, [this, watcher, generation, plan] {
    const GrownSupports grownSupports = watcher->result();
    watcher->deleteLater();
    if (generation != m_generation) return;  // cancelled, or replaced by a newer growth
    m_plan.reset();
    emit grown(plan, grownSupports.sets, grownSupports.note);
  });
  core::JobContext job = m_job;  // copies share the cancellation flag
  QFuture<GrownSupports> future = QtConcurrent::run([model, plan, machine, job]() mutable {
    return growSupports(*model, *plan, machine, job, {}, /*growForCancelledPlan=*/true);
  });
  m_futures.push_back(future);
  watcher->setFuture(future);
}

void SupportRegrowth::cancel() {
  if (!m_plan) return;
  m_job.cancel();
  m_plan.reset();
  ++m_generation;
}

}  // namespace multidir::ui

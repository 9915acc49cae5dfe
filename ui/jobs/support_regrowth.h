#pragma once
// Supports for a plan that is shown without them: a project reopened or recovered (its plan rebuilt from
// its planes), a plan folder saved without supports, or a cancelled search's best plan. Grown off the GUI
// thread (growSupports on QtConcurrent) so that what is shown and what File > Export plan writes always
// carries the supports the risky area left needs.
//
// One growth at a time: starting another cancels the earlier one, whose result is then dropped.
//
// Thread: create and call from the GUI thread; grown() is emitted there.
#include <QFuture>
#include <QList>
#include <QObject>
#include <QString>
#include <memory>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/core/supports/support_set.h"
#include "ui/jobs/support_growth.h"

namespace multidir::ui {

class SupportRegrowth : public QObject {
  Q_OBJECT

 public:
  explicit SupportRegrowth(QObject* parent = nullptr);
  // Cancels a growth under way and waits for it.
  ~SupportRegrowth() override;
  SupportRegrowth(const SupportRegrowth&) = delete;
  SupportRegrowth& operator=(const SupportRegrowth&) = delete;

  // Starts growing supports for `plan`, cut from `model` for `machine`.
  void start(std::shared_ptr<const core::TriangleMesh> model, std::shared_ptr<const core::Decomposition> plan,
             const core::MachineSpec& machine);
  // Stops the growth under way; nothing is emitted for it.
  void cancel();
  // The plan supports are being grown for (null: none).
  [[nodiscard]] std::shared_ptr<const core::Decomposition> growingFor() const { return m_plan; }

 signals:
  // The supports for `plan` (null sets with a note when they could not be grown).
  void grown(const std::shared_ptr<const core::Decomposition>& plan,
             const std::shared_ptr<const std::vector<core::SupportSet>>& supports, const QString& note);

 private:
  core::JobContext m_job;
  std::shared_ptr<const core::Decomposition> m_plan;
  quint64 m_generation = 0;
  QList<QFuture<GrownSupports>> m_futures;  // waited for on destruction
};

}  // namespace multidir::ui

#pragma once
// Long work on the robot cell off the GUI thread (the reach map, the job's motion): the work runs on its own
// QThread with a core::JobContext whose progress arrives here as queued signals; cancel() asks it to stop. The
// work keeps its result in state the caller shares with it and reads on finished().
//
// Thread: create and call from the GUI thread; the signals are emitted there too.
#include <QObject>
#include <QString>
#include <functional>

#include "multidir/core/common/job_context.h"

class QThread;

namespace multidir::ui {

class CellJob : public QObject {
  Q_OBJECT

 public:
  // The work: returns an empty string when done, else what went wrong (shown as is). It must not throw.
  using Work = std::function<QString(core::JobContext)>;

  explicit CellJob(QObject* parent = nullptr);
  // Cancels a running job and waits for it.
  ~CellJob() override;
  CellJob(const CellJob&) = delete;
  CellJob& operator=(const CellJob&) = delete;

  // False (nothing started) while another job runs.
  bool start(Work work);
  void cancel();
  [[nodiscard]] bool isRunning() const { return m_thread != nullptr; }

 signals:
  void progressed(double fraction);
  // The work ended: `error` empty when it succeeded.
  void finished(const QString& error);
  void cancelled();

 private:
  QThread* m_thread = nullptr;
  core::JobContext m_job;
  int m_generation = 0;  // progress of an older job than the running one is dropped
};

}  // namespace multidir::ui

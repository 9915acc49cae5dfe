#pragma once
// Runs the decomposition search off the GUI thread: core::decompose, or core::decomposeWithAxisSearch for a
// 4-DOF machine when axes are to be searched, on its own QThread. Core's progress callbacks (which come
// from worker threads) are coalesced and delivered as queued signals, so core never calls Qt and the GUI
// thread is never blocked; the plan comes back to the GUI thread as a value.
//
// Cancel() asks core to stop (JobContext::cancel); core then returns the best plan found so far, which
// arrives through finished() with `cancelled` set in the decomposition.
//
// Thread: create and call from the GUI thread; the signals are emitted there too.
#include <QMetaType>
#include <QObject>
#include <QString>
#include <memory>

#include "multidir/core/common/job_context.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/decomposition.h"

class QThread;

namespace multidir::ui {

// What one search was asked to do, and what it found.
struct SearchRun {
  core::MachineSpec machine;
  core::SearchOptions options;
  int axisSearchCount = 0;  // 4-DOF axes tried; 0: the machine's own axis only
  std::shared_ptr<const core::Decomposition> plan;  // set in finished(); never null there
};

class SearchJob : public QObject {
  Q_OBJECT

 public:
  explicit SearchJob(QObject* parent = nullptr);
  // Cancels a running search and waits for it (its result is dropped).
  ~SearchJob() override;
  SearchJob(const SearchJob&) = delete;
  SearchJob& operator=(const SearchJob&) = delete;

  // Starts a search of `model`. Returns false (and does nothing) while another search is running or when
  // `model` is null. `axisSearchCount` > 0 searches that many rotation axes (4-DOF machines only).
  bool start(std::shared_ptr<const core::TriangleMesh> model, const core::MachineSpec& machine,
             const core::SearchOptions& options, int axisSearchCount = 0);
  // Asks the running search to stop; it then finishes with the best plan found so far.
  void cancel();

  [[nodiscard]] bool isRunning() const { return m_thread != nullptr; }
  [[nodiscard]] bool isCancelling() const { return m_thread != nullptr && m_job.isCancelled(); }

 signals:
  // The search's latest report (level, beams alive, best J_G, candidates, axis).
  void progressed(const multidir::core::SearchProgress& progress);
  // Fraction done in [0, 1] and the phase core names.
  void fractionChanged(double fraction, const QString& phase);
  // The plan (complete, or the best so far when cancelled).
  void finished(const multidir::ui::SearchRun& run);
  // The search could not run: `headline` translated, `detail` core's description.
  void failed(const QString& headline, const QString& detail);
  void runningChanged(bool running);

 private:
  struct Shared;
  void deliverProgress();

  QThread* m_thread = nullptr;
  core::JobContext m_job;
  std::shared_ptr<Shared> m_shared;
};

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::core::SearchProgress)
Q_DECLARE_METATYPE(multidir::ui::SearchRun)

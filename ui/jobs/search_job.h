#pragma once
// Runs the decomposition search off the GUI thread: core::decompose, or core::decomposeWithAxisSearch for a
// 4-DOF machine when axes are to be searched, on its own QThread. Core's progress callbacks (which come
// from worker threads) are coalesced and delivered as queued signals, so core never calls Qt and the GUI
// thread is never blocked; the plan comes back to the GUI thread as a value.
//
// Cancel() asks core to stop (JobContext::cancel); core then returns the best plan found so far, which
// arrives through finished() with `cancelled` set in the decomposition.
//
// A complete plan with risky area left (J_G > 0) gets supports next, on the same thread: core::generateSupports
// with default SupportOptions and the machine searched for (its axis the one the plan uses), reported as the
// phase "growing supports" in the last tenth of the progress. Cancelling then delivers the plan without
// supports (SearchRun::supportsNote says why).
//
// Thread: create and call from the GUI thread; the signals are emitted there too.
#include <QMetaType>
#include <QObject>
#include <QString>
#include <memory>

#include "multidir/core/common/job_context.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/core/supports/support_set.h"
#include "ui/document/search_run.h"

class QThread;

namespace multidir::ui {

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

  // The share of the progress bar the search takes; supports take the rest.
  static constexpr double kSearchShare = 0.9;

 signals:
  // The search's latest report (level, beams alive, best J_G, candidates, axis).
  void progressed(const multidir::core::SearchProgress& progress);
  // Fraction done in [0, 1] and the phase after the search itself ("growing supports"); empty during it.
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
  core::JobContext m_supportsJob;  // its own context: the search's progress has reached 1 when supports start
  std::shared_ptr<Shared> m_shared;
};

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::core::SearchProgress)

#pragma once
// Runs the best-pose search (core::decomposeWithPoseSearch) off the GUI thread, like SearchJob runs one search:
// on its own QThread, core's progress coalesced and delivered as queued signals, the result handed back to the
// GUI thread as a value. No supports are grown here: the window grows them for the plan it shows
// (SupportRegrowth), and only for the pose that is used.
//
// Cancel() asks core to stop; core then returns the best plan that finished (at least one pose's cheap plan)
// with `cancelled` set, or fails with ErrorCode::Cancelled when no pose had finished. Either way the result is
// one model's: the trials and the plan all come from the run that was started.
//
// Thread: create and call from the GUI thread; the signals are emitted there too.
#include <QMetaType>
#include <QObject>
#include <QString>
#include <memory>

#include "multidir/core/common/job_context.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/pose_search.h"
#include "ui/jobs/search_job.h"

class QThread;

namespace multidir::ui {

// What one pose search was asked to do, and what it found.
struct PoseRun {
  std::shared_ptr<const core::TriangleMesh> model;  // the model searched
  core::MachineSpec machine;                        // as entered, with the up the search started from
  core::SearchOptions options;
  core::PoseOptions poseOptions;
  // Set in finished(): every trial, the chosen one, and its plan (plan.plan) for machineForPose(machine, up).
  std::shared_ptr<const core::PoseSearchResult> result;
  // The chosen pose's plan as the window shows plans: its machine turned to the pose (machineForPose).
  SearchRun chosenRun;
};

class PoseSearchJob : public QObject {
  Q_OBJECT

 public:
  // The phases of a pose search, as fractionChanged() names them: the given up searched in full first, then
  // the other poses ruled out or scored, then the best of them searched in full.
  enum class Phase { GivenUpSearch, CheapScores, FullSearches, Done };
  Q_ENUM(Phase)

  explicit PoseSearchJob(QObject* parent = nullptr);
  // Cancels a running search and waits for it (its result is dropped).
  ~PoseSearchJob() override;
  PoseSearchJob(const PoseSearchJob&) = delete;
  PoseSearchJob& operator=(const PoseSearchJob&) = delete;

  // Starts a pose search of `model` with `machine` (its up: the pose to start from). False (and nothing done)
  // while another runs or when `model` is null.
  bool start(std::shared_ptr<const core::TriangleMesh> model, const core::MachineSpec& machine,
             const core::SearchOptions& options, const core::PoseOptions& poseOptions);
  // Asks the running search to stop; it finishes with the best plan that finished, or fails when none had.
  void cancel();

  [[nodiscard]] bool isRunning() const { return m_thread != nullptr; }
  [[nodiscard]] bool isCancelling() const { return m_thread != nullptr && m_job.isCancelled(); }

 signals:
  // Fraction done in [0, 1] and the phase it is in.
  void progressed(double fraction, multidir::ui::PoseSearchJob::Phase phase);
  void finished(const multidir::ui::PoseRun& run);
  // The search could not run, failed, or was cancelled before any pose finished (`cancelled` then).
  void failed(const QString& headline, const QString& detail, bool cancelled);
  void runningChanged(bool running);

 private:
  struct Shared;
  void deliverProgress();

  QThread* m_thread = nullptr;
  core::JobContext m_job;
  std::shared_ptr<Shared> m_shared;
};

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::ui::PoseRun)

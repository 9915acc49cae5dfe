#pragma once
// The worker-thread plumbing every job that writes a folder of files shares (slicing a plan, printing it apart):
// the work runs on its own QThread into a private temporary folder, its progress comes back as queued signals,
// cancel() raises the JobContext's flag, and the end comes back to the GUI thread once: the caller's `finished`
// with the folder (removed when its last owner lets go), or cancelled() or failed() with the folder already
// removed, so that a cancelled or failed job leaves nothing behind. Signals of an older job than the running one
// are dropped.
//
// The typed result stays with the caller: its `work` fills whatever it captured, and its `finished` reads that.
//
// Thread: create and call from the GUI thread; the signals are emitted there too.
#include <QObject>
#include <QString>
#include <functional>
#include <memory>
#include <string>

#include "multidir/core/common/job_context.h"
#include "multidir/core/common/result.h"

class QTemporaryDir;
class QThread;

namespace multidir::ui {

class FolderJob : public QObject {
  Q_OBJECT

 public:
  // The work, on the worker thread: write into `folder` (an existing, empty directory), honour `job`'s
  // cancellation, and return its status (ErrorCode::Cancelled when cancelled).
  using Work = std::function<core::Status(const std::string& folder, core::JobContext& job)>;
  // The stage's words for a progress report (on the worker thread: keep it free of shared state).
  using StageText = std::function<QString(double fraction, const std::string& phase)>;
  // What the user reads when the work fails, translated by the caller: a headline for the library's error (whose
  // whole message becomes the detail), and one for an exception escaping the work.
  struct FailureTexts {
    std::function<QString(const core::Error&)> headline;
    QString outOfMemory;
    QString unexpected;
  };
  // On the GUI thread when the work succeeded, with the folder it wrote.
  using Finished = std::function<void(std::shared_ptr<QTemporaryDir> folder)>;

  explicit FolderJob(QObject* parent = nullptr);
  // Cancels a running job and waits for it (its end is not reported).
  ~FolderJob() override;
  FolderJob(const FolderJob&) = delete;
  FolderJob& operator=(const FolderJob&) = delete;

  // Starts `work` in a new temporary folder named after `folderPattern` (QTemporaryDir's, e.g.
  // "multidir-slice-XXXXXX", under the system's temporary folder). False (nothing started) when no folder can
  // be made: *folderError then holds QTemporaryDir's reason. The caller refuses a second start while one runs.
  bool start(const QString& folderPattern, Work work, StageText stageText, FailureTexts texts, Finished finished,
             QString* folderError = nullptr);
  void cancel();
  [[nodiscard]] bool isRunning() const { return m_thread != nullptr; }
  // The running job's temporary folder (empty when none runs).
  [[nodiscard]] QString workFolder() const { return m_workFolder; }

 signals:
  void progressed(double fraction, const QString& stage);
  // `headline` translated (what went wrong and what to do), `detail` the library's whole message.
  void failed(const QString& headline, const QString& detail);
  void cancelled();
  void runningChanged(bool running);

 private:
  QThread* m_thread = nullptr;
  core::JobContext m_job;
  QString m_workFolder;
  int m_generation = 0;
};

}  // namespace multidir::ui

#pragma once
// Slices a plan off the GUI thread: slicing::slicePlan (the same code as `multidir slice`) on its own
// QThread, into a private temporary folder, then reads every step's G-code back for the preview and audits it
// (ui/jobs/preview_audit.h: the unsupported extrusions marked). Progress
// arrives as queued signals saying which step is being sliced; the result comes back to the GUI thread as a
// value holding the folder (removed when the last copy of the result goes).
//
// cancel() asks the library to stop (JobContext::cancel): the running prusa-slicer is terminated within a
// moment and the job ends with cancelled(); its temporary folder is removed, nothing else was written.
//
// Thread: create and call from the GUI thread; the signals are emitted there too.
#include <QMetaType>
#include <QObject>
#include <QString>
#include <memory>

#include "multidir/core/plan/plan_file.h"
#include "multidir/slicing/slice_job.h"

class QTemporaryDir;

namespace multidir::ui {

class FolderJob;
struct GcodePreview;

// A finished slicing.
struct SliceOutcome {
  std::shared_ptr<const slicing::SlicedJob> job;
  std::shared_ptr<const GcodePreview> preview;
  // Where the job's files are (step-NN.gcode, job.gcode, print-job.json and the step meshes); removed with
  // the last copy of the outcome.
  std::shared_ptr<QTemporaryDir> folder;
  // Empty, or why the audit that marks the preview's unsupported extrusions failed (translated, with the
  // audit's message naming the file and line): the preview is then shown without marks.
  QString auditError;
  [[nodiscard]] QString folderPath() const;
};

class SliceJobRunner : public QObject {
  Q_OBJECT

 public:
  explicit SliceJobRunner(QObject* parent = nullptr);
  // Cancels a running job and waits for it (its result is dropped).
  ~SliceJobRunner() override;
  SliceJobRunner(const SliceJobRunner&) = delete;
  SliceJobRunner& operator=(const SliceJobRunner&) = delete;

  // Starts slicing `plan` for `profile`. False (nothing started, the reason in *error) while another job
  // runs or when no temporary folder can be made.
  bool start(const core::LoadedPlan& plan, const slicing::PrinterProfile& profile,
             const slicing::SliceJobOptions& options, QString* error = nullptr);
  void cancel();
  [[nodiscard]] bool isRunning() const;
  // The running job's temporary folder (empty when none runs).
  [[nodiscard]] QString workFolder() const;

 signals:
  // `fraction` in [0, 1]; `stage` says what is being done ("Slicing step 2 of 3"), translated.
  void progressed(double fraction, const QString& stage);
  void finished(const multidir::ui::SliceOutcome& outcome);
  // The slicer is missing or failed, or a check refused the G-code: `headline` translated, `detail` the
  // library's whole message (the command, the slicer's last lines; the step, line and reason of a check).
  void failed(const QString& headline, const QString& detail);
  void cancelled();
  void runningChanged(bool running);

 private:
  FolderJob* m_job;  // the thread, the folder, progress and cancel (ui/jobs/folder_job.h)
};

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::ui::SliceOutcome)

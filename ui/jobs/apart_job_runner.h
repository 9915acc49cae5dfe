#pragma once
// Prints a plan apart off the GUI thread: apart::printApart (the same pipeline as `multidir apart`) on its own
// QThread, into a private temporary folder. Progress arrives as queued signals saying which stage runs ("Slicing
// plate 2 of 3"); the result comes back to the GUI thread as an ApartPrint holding the folder (removed when the
// last copy goes). cancel() stops the pipeline between stages, between plates and inside the slicer; the job
// then ends with cancelled() and its temporary folder is removed: nothing else was written.
//
// Thread: create and call from the GUI thread; the signals are emitted there too.
#include <QObject>
#include <QString>
#include <memory>

#include "multidir/apart/print_apart.h"
#include "ui/document/apart_print.h"

namespace multidir::ui {

class FolderJob;

class ApartJobRunner : public QObject {
  Q_OBJECT

 public:
  explicit ApartJobRunner(QObject* parent = nullptr);
  // Cancels a running job and waits for it (its result is dropped).
  ~ApartJobRunner() override;
  ApartJobRunner(const ApartJobRunner&) = delete;
  ApartJobRunner& operator=(const ApartJobRunner&) = delete;

  // Starts printing `plan` apart. False (nothing started, the reason in *error) while another job runs or when
  // no temporary folder can be made.
  bool start(std::shared_ptr<const core::Decomposition> plan, const apart::PrintApartOptions& options,
             QString* error = nullptr);
  void cancel();
  [[nodiscard]] bool isRunning() const;
  // The running job's temporary folder (empty when none runs).
  [[nodiscard]] QString workFolder() const;

 signals:
  // `fraction` in [0, 1]; `stage` what the pipeline does now.
  void progressed(double fraction, const QString& stage);
  void finished(const multidir::ui::ApartPrint& print);
  // `headline` translated (what went wrong and what to do), `detail` the library's whole message.
  void failed(const QString& headline, const QString& detail);
  void cancelled();
  void runningChanged(bool running);

 private:
  FolderJob* m_job;  // the thread, the folder, progress and cancel (ui/jobs/folder_job.h)
};

}  // namespace multidir::ui

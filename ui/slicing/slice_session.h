#pragma once
// Slicing in the studio: the plan shown (with its supports, the same inputs as `multidir slice`) sliced off
// the GUI thread by SliceJobRunner, its estimates and controls in the SlicePanel under the Plan dock, the
// G-code preview in the viewer, and Export G-code.
//
// What drops a result: another plan shown (searched, opened or edited), supports attached to the plan later,
// the plan view closed. A job running then is cancelled and its result dropped. Nothing is written where the
// user can see it until Export G-code: a job slices into its own temporary folder, which a cancel or failure
// removes.
//
// Thread: GUI thread.
#include <QObject>
#include <QString>
#include <memory>
#include <optional>

#include "ui/jobs/slice_job_runner.h"
#include "ui/slicing/slice_dialog.h"

namespace multidir::core {
struct Decomposition;
struct SupportSet;
}  // namespace multidir::core

namespace multidir::ui {

class MainWindow;
class SlicePanel;

class SliceSession : public QObject {
  Q_OBJECT

 public:
  // Follows `window`'s plan (planShown, planCleared, supportsRegrown) and drives `panel` and the window's
  // viewer.
  SliceSession(MainWindow& window, SlicePanel* panel);

  // The Slice dialog (window-modal, it does not block), then slice() with what it collected.
  void chooseAndSlice();
  // Starts slicing the plan shown; false with the reason in the panel (no plan, supports still growing, a job
  // running, no temporary folder).
  bool slice(const SliceChoice& choice);
  void cancel();
  [[nodiscard]] bool isSlicing() const { return m_runner->isRunning(); }
  [[nodiscard]] SliceJobRunner* runner() const { return m_runner; }
  // The last finished job for the plan shown (nullopt: none).
  [[nodiscard]] const std::optional<SliceOutcome>& outcome() const { return m_outcome; }

  // Export G-code: writes the job's files into `directory` (exportSlicedFiles: the whole job swapped in once
  // complete; a folder holding other files only when `intoOtherFolder`). False with the message.
  bool exportGcode(const QString& directory, QString* error = nullptr, bool intoOtherFolder = false);
  // The same, asking for the folder (an existing one, or a new name that is created), and asking before it
  // writes into a folder that holds files other than a MultiDir job's.
  void chooseExportGcode();

  // The viewer shows the toolpaths (true) or the plan view (false); false when there is no result.
  bool setPreviewShown(bool shown);

 signals:
  void sliced();
  // `message`: the headline and the detail, as the panel shows them.
  void sliceFailed(const QString& message);
  void sliceCancelled();
  // A result is there to export (or no longer is).
  void resultAvailable(bool available);
  // Slicing can be started now (a plan is shown, its supports are ready and no job runs), or no longer can.
  void sliceableChanged(bool sliceable);

 private:
  void onPlanChanged();
  void dropResult();
  void updateSliceable();
  void onFinished(const SliceOutcome& outcome);
  void showLayer(int layers);

  MainWindow& m_window;
  SlicePanel* m_panel;
  SliceJobRunner* m_runner;
  std::optional<SliceOutcome> m_outcome;
  // The plan and supports the running or finished job was sliced from.
  std::shared_ptr<const core::Decomposition> m_plan;
  std::shared_ptr<const std::vector<core::SupportSet>> m_supports;
};

}  // namespace multidir::ui

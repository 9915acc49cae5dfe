#pragma once
// Drives the print-run sequencer (hardware::PrintRun) from the GUI thread: a timer calls tick() while a run
// is under way, operator events go straight to the sequencer, and its callbacks become signals. The
// positioner is held (shared) for the run's lifetime, so the device's driver outlives the run even when the
// panel disconnects mid-run.
//
// A lost link pauses the run (the driver's policy, on top of the sequencer's): a move under way stops, a
// region being printed may finish, and no next step starts until the operator presses Resume once the link
// is back. Without it the sequencer would stay "printing" with the device out of reach.
//
// With a printer link the sequencer uploads and starts each step's G-code and follows the printer's job (the
// link is held, shared, for the run's lifetime); steps without G-code stay with the operator's Region done.
//
// Thread: GUI thread only, like PrintRun itself.
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>
#include <chrono>
#include <cstddef>
#include <memory>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/print_run.h"

namespace multidir::ui {

class PrintRunDriver : public QObject {
  Q_OBJECT

 public:
  explicit PrintRunDriver(QObject* parent = nullptr);
  ~PrintRunDriver() override;
  PrintRunDriver(const PrintRunDriver&) = delete;
  PrintRunDriver& operator=(const PrintRunDriver&) = delete;

  // Starts a new run of `steps` on `positioner`, printing the steps with G-code on `printer` when given (a
  // finished run is replaced), from step `firstStep` (0-based: the steps before it were printed by a run that
  // was aborted). InvalidParameter when a run is still under way, there is no positioner or no
  // step; the sequencer's own refusal otherwise.
  core::Status start(std::shared_ptr<hardware::Positioner> positioner, std::vector<hardware::PrintStep> steps,
                     hardware::PrintRunOptions options = {}, std::shared_ptr<hardware::PrinterLink> printer = nullptr,
                     std::size_t firstStep = 0);
  // Operator events, forwarded to the sequencer (see the transition table in hardware/print_run.h).
  core::Status regionDone();  // for the current step
  core::Status pause();
  core::Status resume();
  // The current step printed again from its start, once the operator cleared the platform (the printer lost
  // its job: interruptedJobGone()).
  core::Status restartStep();
  core::Status abort();
  // The positioner's and the printer's emergency stops at once (PrintRun::emergencyStop); the run ends.
  core::Status emergencyStop();

  [[nodiscard]] bool hasRun() const { return m_run != nullptr; }
  // Under way: started and neither Completed nor Aborted.
  [[nodiscard]] bool isActive() const;
  [[nodiscard]] hardware::PrintRunState state() const;
  [[nodiscard]] std::size_t currentStep() const;
  [[nodiscard]] std::size_t stepCount() const;
  // A pause was asked for while printing: the run stops before the next move.
  [[nodiscard]] bool pausePending() const { return m_run && m_run->pausePending(); }
  [[nodiscard]] const hardware::PrintStep* currentPrintStep() const;
  // The run has a printer link, and the current step is printed by it (it has G-code).
  [[nodiscard]] bool hasPrinter() const { return m_run && m_run->hasPrinter(); }
  [[nodiscard]] bool currentStepUsesPrinter() const;
  // The run is paused because the printer's job for the current step was interrupted (lastProblem says why):
  // Resume follows the printer again, or the operator finishes the region by hand and presses Region done.
  [[nodiscard]] bool printInterrupted() const { return m_run && m_run->printInterrupted(); }
  // ... and the printer has no job of the step any more (it restarted): Resume has nothing to resume, only
  // restartStep(), Region done or Abort go on. Followed on every tick (printerJobGoneChanged).
  [[nodiscard]] bool interruptedJobGone() const { return m_run && m_run->interruptedJobGone(); }
  // A stop or emergency stop was asked for and a device has not confirmed it yet.
  [[nodiscard]] bool stopUnconfirmed() const { return m_run && m_run->stopUnconfirmed(); }
  // Since start(), frozen once the run ended.
  [[nodiscard]] std::chrono::milliseconds elapsed() const;
  [[nodiscard]] QString lastProblem() const;
  // The run was paused (or will pause when the region printing is done) because the link was lost; cleared
  // by Resume, Abort or a new run.
  [[nodiscard]] bool heldForLostLink() const { return m_heldForLostLink; }
  // How often tick() runs (50 ms by default).
  void setTickInterval(std::chrono::milliseconds interval);

 signals:
  void stateChanged(hardware::PrintRunState state);
  // The region (index from 0) the platform is oriented for or moving to; -1 when no run is under way.
  void currentRegionChanged(int region);
  // Region `region` may be printed now (from its file); the operator presses Region done afterwards.
  void printRequested(int region, const QString& regionFile);
  // One line per sequencer transition, "00:12 step 2/3 (region-02.stl): ... reached".
  void logged(const QString& line);
  // A run of `steps` is about to start (before its first event).
  void runStarting(const std::vector<hardware::PrintStep>& steps);
  // Every sequencer event as it happens; `reason` says why the run paused, failed or stopped (else empty).
  void runEvent(const hardware::PrintRunLogEntry& entry, const QString& reason);
  // The link to the device went down while the run was under way: the run is paused (see the header).
  void pausedForLostLink();
  // interruptedJobGone() changed.
  void printerJobGoneChanged(bool gone);

 private:
  void tick();
  void afterEvent();
  void holdIfLinkLost();

  std::shared_ptr<hardware::Positioner> m_positioner;
  std::shared_ptr<hardware::PrinterLink> m_printer;
  std::unique_ptr<hardware::PrintRun> m_run;
  QTimer m_timer;
  QElapsedTimer m_clock;
  std::chrono::milliseconds m_frozenElapsed{0};
  hardware::PrintRunState m_lastState = hardware::PrintRunState::Idle;
  int m_lastRegion = -1;
  bool m_heldForLostLink = false;
  bool m_lastJobGone = false;
};

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::hardware::PrintRunState)

#include "ui/device/print_run_driver.h"

#include <utility>

namespace multidir::ui {
namespace {

bool isFinal(hardware::PrintRunState state) {
  return state == hardware::PrintRunState::Completed || state == hardware::PrintRunState::Aborted;
}

// Why the run paused, failed or stopped at `entry`: the printer's interruption or the device's fault as the
// sequencer states it, else what the entry itself says after its step label.
QString eventReason(const hardware::PrintRun& run, const hardware::PrintRunLogEntry& entry) {
  using hardware::PrintRunState;
  if (entry.state != PrintRunState::Paused && entry.state != PrintRunState::Faulted &&
      entry.state != PrintRunState::Aborted)
    return {};
  if ((entry.state == PrintRunState::Paused && run.printInterrupted()) || entry.state == PrintRunState::Faulted)
    return QString::fromStdString(run.lastProblem());
  const std::string::size_type colon = entry.message.find("): ");
  return QString::fromStdString(colon == std::string::npos ? entry.message : entry.message.substr(colon + 3));
}

core::Error noRun() {
  return core::Error{core::ErrorCode::InvalidParameter, "no print run has been started", "print run"};
}

}  // namespace

PrintRunDriver::PrintRunDriver(QObject* parent) : QObject(parent) {
  m_timer.setInterval(50);
  connect(&m_timer, &QTimer::timeout, this, &PrintRunDriver::tick);
}

PrintRunDriver::~PrintRunDriver() {
  // Leave no platform turning towards a region nobody will print.
  if (isActive()) (void)m_run->abort();
}

core::Status PrintRunDriver::start(std::shared_ptr<hardware::Positioner> positioner,
                                   std::vector<hardware::PrintStep> steps, hardware::PrintRunOptions options,
                                   std::shared_ptr<hardware::PrinterLink> printer, std::size_t firstStep) {
  if (isActive())
    return core::Error{core::ErrorCode::InvalidParameter, "a print run is under way: abort it first", "print run"};
  if (!positioner) return core::Error{core::ErrorCode::InvalidParameter, "no device is connected", "print run"};
  if (steps.empty()) return core::Error{core::ErrorCode::InvalidParameter, "the plan has no regions", "print run"};
  auto run = std::make_unique<hardware::PrintRun>(*positioner, std::move(steps), std::move(options), printer.get());
  run->setLogCallback([this, sequencer = run.get()](const hardware::PrintRunLogEntry& entry) {
    const long long seconds = entry.elapsed.count() / 1000;
    emit logged(QStringLiteral("%1:%2 %3")
                    .arg(seconds / 60, 2, 10, QLatin1Char('0'))
                    .arg(seconds % 60, 2, 10, QLatin1Char('0'))
                    .arg(QString::fromStdString(entry.message)));
    emit runEvent(entry, eventReason(*sequencer, entry));
  });
  run->setPrintRequestCallback([this](std::size_t step, const hardware::PrintStep& printStep) {
    emit printRequested(static_cast<int>(step), QString::fromStdString(printStep.regionFile));
  });
  // The old run (if any) ended; it still refers to its positioner and printer, so it goes first.
  m_run.reset();
  m_positioner = std::move(positioner);
  m_printer = std::move(printer);
  m_run = std::move(run);
  m_lastState = hardware::PrintRunState::Idle;
  m_frozenElapsed = std::chrono::milliseconds(0);
  m_heldForLostLink = false;
  m_clock.start();
  emit runStarting(m_run->steps());
  const core::Status started = m_run->start(firstStep);
  afterEvent();
  return started;
}

core::Status PrintRunDriver::regionDone() {
  if (!m_run) return noRun();
  const core::Status status = m_run->regionDone(m_run->currentStep());
  afterEvent();
  return status;
}

core::Status PrintRunDriver::pause() {
  if (!m_run) return noRun();
  const core::Status status = m_run->pause();
  afterEvent();
  return status;
}

core::Status PrintRunDriver::resume() {
  if (!m_run) return noRun();
  const core::Status status = m_run->resume();
  if (status.ok()) m_heldForLostLink = false;
  afterEvent();
  return status;
}

core::Status PrintRunDriver::restartStep() {
  if (!m_run) return noRun();
  const core::Status status = m_run->restartStep();
  if (status.ok()) m_heldForLostLink = false;
  afterEvent();
  return status;
}

core::Status PrintRunDriver::abort() {
  if (!m_run) return noRun();
  const core::Status status = m_run->abort();
  if (status.ok()) m_heldForLostLink = false;
  afterEvent();
  return status;
}

core::Status PrintRunDriver::emergencyStop() {
  if (!m_run) return noRun();
  const core::Status status = m_run->emergencyStop();
  m_heldForLostLink = false;
  afterEvent();
  return status;
}

bool PrintRunDriver::currentStepUsesPrinter() const {
  const hardware::PrintStep* step = currentPrintStep();
  return hasPrinter() && step != nullptr && !step->gcodePath.empty();
}

bool PrintRunDriver::isActive() const { return m_run && !isFinal(m_run->state()); }

hardware::PrintRunState PrintRunDriver::state() const { return m_run ? m_run->state() : hardware::PrintRunState::Idle; }

std::size_t PrintRunDriver::currentStep() const { return m_run ? m_run->currentStep() : 0; }

std::size_t PrintRunDriver::stepCount() const { return m_run ? m_run->steps().size() : 0; }

const hardware::PrintStep* PrintRunDriver::currentPrintStep() const {
  if (!m_run || m_run->currentStep() >= m_run->steps().size()) return nullptr;
  return &m_run->steps()[m_run->currentStep()];
}

std::chrono::milliseconds PrintRunDriver::elapsed() const {
  if (!m_run) return std::chrono::milliseconds(0);
  if (!isActive()) return m_frozenElapsed;
  return std::chrono::milliseconds(m_clock.elapsed());
}

QString PrintRunDriver::lastProblem() const { return m_run ? QString::fromStdString(m_run->lastProblem()) : QString(); }

void PrintRunDriver::setTickInterval(std::chrono::milliseconds interval) {
  m_timer.setInterval(static_cast<int>(interval.count()));
}

void PrintRunDriver::tick() {
  if (!m_run) return;
  holdIfLinkLost();
  m_run->tick();
  afterEvent();
}

void PrintRunDriver::holdIfLinkLost() {
  const hardware::PrintRunState state = m_run->state();
  const bool underWay = state == hardware::PrintRunState::Moving || state == hardware::PrintRunState::Settling ||
                        state == hardware::PrintRunState::Printing;
  if (!underWay || m_positioner->snapshot().linkUp) return;
  if (state == hardware::PrintRunState::Printing && m_run->pausePending()) return;  // already holding
  // Moving or settling: stops (the stop may not reach the device; its heartbeat watchdog stops it). Printing:
  // the region may finish, the next one does not start.
  if (!m_run->pause().ok()) return;
  m_heldForLostLink = true;
  const long long seconds = m_clock.elapsed() / 1000;
  emit logged(QStringLiteral("%1:%2 %3")
                  .arg(seconds / 60, 2, 10, QLatin1Char('0'))
                  .arg(seconds % 60, 2, 10, QLatin1Char('0'))
                  .arg(tr("the link to %1 was lost: the run is paused; press Resume once the link is back")
                           .arg(QString::fromStdString(m_positioner->name()))));
  emit pausedForLostLink();
}

void PrintRunDriver::afterEvent() {
  const hardware::PrintRunState state = m_run->state();
  const bool active = !isFinal(state);
  // An aborted run keeps ticking until the device confirmed the stop, so that the log says when it did.
  if ((active || m_run->stopUnconfirmed()) && !m_timer.isActive()) m_timer.start();
  if (!active && !m_run->stopUnconfirmed()) m_timer.stop();
  if (!active && !isFinal(m_lastState)) m_frozenElapsed = std::chrono::milliseconds(m_clock.elapsed());
  const int region = active ? static_cast<int>(m_run->currentStep()) : -1;
  if (state != m_lastState) {
    m_lastState = state;
    emit stateChanged(state);
  }
  if (region != m_lastRegion) {
    m_lastRegion = region;
    emit currentRegionChanged(region);
  }
  if (const bool gone = m_run->interruptedJobGone(); gone != m_lastJobGone) {
    m_lastJobGone = gone;
    emit printerJobGoneChanged(gone);
  }
}

}  // namespace multidir::ui

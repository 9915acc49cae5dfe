#include "multidir/hardware/print_run.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "degrees_text.h"
#include "printable_text.h"

namespace multidir::hardware {

namespace {

bool commandReady(std::future<core::Status>& future) {
  return future.valid() && future.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

std::string celsius(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f C", value);
  return text;
}

// A heater overshooting its target, or a reading no sensor gives: "" when both read sane.
std::string temperatureFault(const PrinterStatus& p, double overshootC) {
  const auto check = [&](const HeaterReading& h, const char* name) -> std::string {
    if (!std::isfinite(h.actualC) || h.actualC < -20.0 || h.actualC > 500.0)
      return std::string("temperature fault: the ") + name + " reads " + celsius(h.actualC) +
             ", which no working sensor gives: check its thermistor and wiring";
    if (h.targetC > 0.0 && h.actualC > h.targetC + overshootC)
      return std::string("temperature fault: the ") + name + " reads " + celsius(h.actualC) + ", more than " +
             celsius(overshootC) + " above its target " + celsius(h.targetC) +
             " (a heater running away?): the printer's job was paused; check the heater before resuming";
    return {};
  };
  std::string fault = check(p.extruder, "extruder");
  return fault.empty() ? check(p.bed, "bed") : fault;
}

}  // namespace

PlatformOrientation PlatformOrientation::rotary(double angleDegrees) {
  PlatformOrientation o;
  o.kind = Kind::Rotary;
  o.rotaryDegrees = angleDegrees;
  return o;
}

PlatformOrientation PlatformOrientation::tiltAzimuth(double tiltDegrees, double azimuthDegrees) {
  PlatformOrientation o;
  o.kind = Kind::TiltAzimuth;
  o.tiltDegrees = tiltDegrees;
  o.azimuthDegrees = azimuthDegrees;
  return o;
}

std::string PlatformOrientation::describe() const {
  if (kind == Kind::Rotary) return "rotary " + degreesText(rotaryDegrees) + " deg";
  return "tilt " + degreesText(tiltDegrees) + " deg, azimuth " + degreesText(azimuthDegrees) + " deg";
}

const char* printRunStateName(PrintRunState state) {
  switch (state) {
    case PrintRunState::Idle: return "idle";
    case PrintRunState::Moving: return "moving";
    case PrintRunState::Settling: return "settling";
    case PrintRunState::Printing: return "printing";
    case PrintRunState::Paused: return "paused";
    case PrintRunState::Completed: return "completed";
    case PrintRunState::Aborted: return "aborted";
    case PrintRunState::Faulted: return "faulted";
  }
  return "?";
}

PrintRun::PrintRun(Positioner& positioner, std::vector<PrintStep> steps, PrintRunOptions options,
                   PrinterLink* printer)
    : m_positioner(positioner), m_printer(printer), m_steps(std::move(steps)), m_options(std::move(options)) {
  if (!m_options.steadyNow) m_options.steadyNow = [] { return std::chrono::steady_clock::now(); };
  if (!m_options.wallNow) m_options.wallNow = [] { return std::chrono::system_clock::now(); };
  // Warnings from before this run (a link the studio keeps across runs) were the earlier run's to log.
  if (m_printer != nullptr) m_protocolWarningsLogged = m_printer->status().protocolWarnings;
}

std::string PrintRun::stepLabel() const {
  if (m_steps.empty()) return "no step";
  const PrintStep& step = m_steps[m_step];
  return "step " + std::to_string(m_step + 1) + "/" + std::to_string(m_steps.size()) + " (" +
         (step.regionFile.empty() ? std::string("unnamed region") : step.regionFile) + ", " +
         step.orientation.describe() + ")";
}

void PrintRun::enter(PrintRunState state, const std::string& message) {
  m_state = state;
  PrintRunLogEntry entry;
  entry.wallTime = m_options.wallNow();
  entry.elapsed = std::chrono::duration_cast<std::chrono::milliseconds>(m_options.steadyNow() - m_started);
  entry.step = m_step;
  entry.state = state;
  entry.message = escapeControls(message);  // names and the printer's words come from outside
  m_log.push_back(entry);
  if (m_logCallback) m_logCallback(m_log.back());
}

core::Status PrintRun::refuse(const std::string& event) const {
  return core::Error{core::ErrorCode::InvalidParameter,
                     "cannot " + event + " the print run while it is " + printRunStateName(m_state), "print run"};
}

core::Status PrintRun::requestStop() {
  core::Status stopped = m_positioner.stopMotion();
  m_awaitingStopConfirmation = stopped.ok();
  m_stopProblemLogged = false;
  m_stopRequested = m_options.steadyNow();
  return stopped;
}

namespace {

constexpr std::chrono::milliseconds kStopConfirmationWarning{1000};

// What the log says after asking for a stop: never "stopped" before the device confirmed it.
// `emergency`: how the operator stops the device otherwise (PrintRunAdvice::EmergencyStop).
std::string stopRequestText(const core::Status& stopped, const std::string& device, const std::string& emergency) {
  if (stopped.ok()) return "stopping " + device + " (waiting for it to confirm)";
  return "the stop was refused (" + stopped.error().describe() + "): " + device + " may still move; " + emergency;
}

}  // namespace

void PrintRun::watchStop(const PositionerSnapshot& snapshot) {
  if (!m_awaitingStopConfirmation) return;
  if (snapshot.stopConfirmed) {
    m_awaitingStopConfirmation = false;
    enter(m_state, stepLabel() + ": motion stopped: " + m_positioner.name() + " confirmed the stop");
  } else if (!m_stopProblemLogged && m_options.steadyNow() - m_stopRequested >= kStopConfirmationWarning) {
    // Usually the device confirms within milliseconds; longer means the link is down or the stop failed.
    m_stopProblemLogged = true;
    const std::string why = !snapshot.problem.empty() ? snapshot.problem
                            : snapshot.linkUp         ? std::string("no answer yet")
                                                      : std::string("the link is down");
    enter(m_state, stepLabel() + ": " + m_positioner.name() + " has not confirmed the stop after " +
                       std::to_string(kStopConfirmationWarning.count()) + " ms (" + why +
                       "); it is sent as soon as the link allows; if the device still moves: " +
                       advice(PrintRunAdvice::EmergencyStop));
  }
}

std::string PrintRun::advice(PrintRunAdvice situation) const {
  if (m_options.advice) return m_options.advice(situation);
  switch (situation) {
    case PrintRunAdvice::RetryStep:
      return "fix it, then resume to retry the step or abort";
    case PrintRunAdvice::RetryWhenPrinterIdle:
      return "resume to retry the step once the printer is idle";
    case PrintRunAdvice::PrintInterrupted:
      return "fix it, then resume (the printer's job continues when it is paused or still printing) or finish the "
             "region by hand and press Region done, or abort";
    case PrintRunAdvice::EmergencyStop:
      return "use the E-STOP or cut its power";
  }
  return {};
}

void PrintRun::fault(const std::string& problem) {
  m_lastProblem = problem;
  const core::Status stopped = requestStop();
  enter(PrintRunState::Faulted,
        stepLabel() + ": " + problem + "; " +
            stopRequestText(stopped, m_positioner.name(), advice(PrintRunAdvice::EmergencyStop)) + "; " +
            advice(PrintRunAdvice::RetryStep));
}

namespace {

// A state the link read but could not map (a word outside the protocol's documented set): MultiDir cannot
// tell whether the printer's head moves, so the run stops and asks, as when the link is lost.
std::string unknownStateText(const PrinterStatus& p) {
  return "the printer reports a state MultiDir does not know" +
         (p.message.empty() ? std::string() : " (" + p.message + ")");
}

}  // namespace

std::string PrintRun::printerForbidsMotion() const {
  if (m_printer == nullptr) return {};
  const PrinterStatus p = m_printer->status();
  if (p.linkLost)
    return "the platform does not move while the printer's state is unknown: the link to " + m_printer->name() +
           " is lost" + (p.lastError.empty() ? std::string() : " (" + p.lastError + ")");
  if (p.state == PrinterJobState::Unknown)
    return "the platform does not move while " + unknownStateText(p) + "; check the printer";
  if (p.busy())
    return "the platform does not move while the printer reports a job " + std::string(printerJobStateName(p.state)) +
           (p.currentFile.empty() ? std::string() : " (" + p.currentFile + ")") +
           ": let it finish or cancel it on the printer";
  return {};
}

void PrintRun::beginMove() {
  m_pausePending = false;
  m_faultLoggedWhilePrinting = false;
  m_printInterrupted = false;
  m_phase = PrintPhase::None;
  m_stepBegun = false;
  m_stepProgress = 0.0;
  m_moveStarted = m_options.steadyNow();
  if (const std::string forbidden = printerForbidsMotion(); !forbidden.empty()) {
    m_lastProblem = forbidden;
    enter(PrintRunState::Faulted,
          stepLabel() + ": the move was not sent: " + forbidden + "; " + advice(PrintRunAdvice::RetryWhenPrinterIdle));
    return;
  }
  core::Status started = m_positioner.startMove(m_steps[m_step].orientation);
  if (!started.ok()) {
    m_lastProblem = started.error().describe();
    enter(PrintRunState::Faulted, stepLabel() + ": the move was refused: " + m_lastProblem);
    return;
  }
  enter(PrintRunState::Moving, stepLabel() + ": moving " + m_positioner.name());
}

core::Status PrintRun::start(std::size_t firstStep) {
  if (m_state != PrintRunState::Idle) return refuse("start");
  if (m_steps.empty())
    return core::Error{core::ErrorCode::InvalidParameter, "the print run has no steps: plan the regions first",
                       "print run"};
  if (firstStep >= m_steps.size())
    return core::Error{core::ErrorCode::InvalidParameter,
                       "there is no step " + std::to_string(firstStep + 1) + " to start from: the run has " +
                           std::to_string(m_steps.size()) + " steps",
                       "print run"};
  m_started = m_options.steadyNow();
  m_step = firstStep;
  beginMove();
  return core::Done{};
}

core::Status PrintRun::pause() {
  switch (m_state) {
    case PrintRunState::Moving:
    case PrintRunState::Settling: {
      const core::Status stopped = requestStop();
      if (!stopped.ok()) {
        m_lastProblem = "the stop was refused: " + stopped.error().describe();
        enter(PrintRunState::Faulted,
              stepLabel() +
                  ": pause: " + stopRequestText(stopped, m_positioner.name(), advice(PrintRunAdvice::EmergencyStop)));
        return stopped;
      }
      enter(PrintRunState::Paused,
            stepLabel() + ": paused; " +
                stopRequestText(stopped, m_positioner.name(), advice(PrintRunAdvice::EmergencyStop)));
      return core::Done{};
    }
    case PrintRunState::Printing:
      if (!m_pausePending) {
        m_pausePending = true;
        enter(PrintRunState::Printing, stepLabel() + ": pause requested; it takes effect when the region is done");
      }
      return core::Done{};
    default:
      return refuse("pause");
  }
}

core::Status PrintRun::resume() {
  if (m_state == PrintRunState::Printing && m_pausePending) {
    m_pausePending = false;
    enter(PrintRunState::Printing, stepLabel() + ": pause request withdrawn");
    return core::Done{};
  }
  if (m_state != PrintRunState::Paused && m_state != PrintRunState::Faulted) return refuse("resume");
  if (m_state == PrintRunState::Paused && m_printInterrupted) {
    const PrinterStatus p = m_printer->status();
    const auto cannot = [&](const std::string& why) {
      return core::Error{core::ErrorCode::InvalidParameter, "cannot resume step " + std::to_string(m_step + 1) + ": " + why,
                         "print run"};
    };
    if (p.linkLost) return cannot("the link to " + m_printer->name() + " is still lost; check the printer and network");
    if (p.stop.latched()) return cannot("the printer's emergency stop is latched");
    const bool ours = p.currentFile == remoteName();
    if (ours && p.state == PrinterJobState::Complete) {
      enter(PrintRunState::Printing, stepLabel() + ": the printer finished " + remoteName() + " meanwhile");
      finishRegion();
      return core::Done{};
    }
    if (ours && (p.state == PrinterJobState::Paused || p.state == PrinterJobState::Printing)) {
      if (p.state == PrinterJobState::Paused) m_printerSideCommand = m_printer->resumePrint();
      m_printInterrupted = false;
      m_phase = PrintPhase::Running;
      m_pollsAtStart = p.polls;
      m_printStarted = m_options.steadyNow();
      m_printerPausedLogged = false;
      enter(PrintRunState::Printing, stepLabel() + (p.state == PrinterJobState::Paused
                                                        ? ": resuming the printer's job " + remoteName()
                                                        : ": the printer is still printing " + remoteName() +
                                                              "; following it again"));
      return core::Done{};
    }
    return cannot("the printer has no job of this step any more (it reports " +
                  std::string(printerJobStateName(p.state)) +
                  (p.currentFile.empty() ? std::string(", no file") : " of " + p.currentFile) +
                  (p.message.empty() ? std::string() : ": " + p.message) +
                  "); print the step again from its start (restart the step), finish the region by hand and "
                  "press Region done, or abort the run");
  }
  // Resuming is the operator clearing the stop; refused while the device has not confirmed it.
  watchStop(m_positioner.snapshot());
  if (core::Status cleared = m_positioner.clearStop(); !cleared.ok())
    return core::Error{core::ErrorCode::InvalidParameter, "cannot resume yet: " + cleared.error().describe(),
                       "print run"};
  m_awaitingStopConfirmation = false;
  enter(m_state, stepLabel() + (m_state == PrintRunState::Faulted ? ": retrying" : ": resuming"));
  beginMove();
  return core::Done{};
}

bool PrintRun::interruptedJobGone() const {
  if (m_state != PrintRunState::Paused || !m_printInterrupted || m_printer == nullptr) return false;
  const PrinterStatus p = m_printer->status();
  if (p.linkLost || p.state == PrinterJobState::Unknown) return false;  // nothing known of its job
  const bool ours = p.currentFile == remoteName();
  return !(ours && (p.busy() || p.state == PrinterJobState::Complete));
}

core::Status PrintRun::restartStep() {
  if (m_state != PrintRunState::Paused || !m_printInterrupted || m_printer == nullptr) return refuse("restart a step of");
  const PrinterStatus p = m_printer->status();
  const auto cannot = [&](const std::string& why) {
    return core::Error{core::ErrorCode::InvalidParameter, "cannot restart step " + std::to_string(m_step + 1) + ": " + why,
                       "print run"};
  };
  if (p.linkLost) return cannot("the link to " + m_printer->name() + " is still lost; check the printer and network");
  if (!interruptedJobGone())
    return cannot("the printer still has the step's job (" + std::string(printerJobStateName(p.state)) +
                  "); resume it instead");
  if (p.stop.latched()) return cannot("the printer's emergency stop is latched");
  if (p.firmwareState != "ready")
    return cannot("the printer's firmware is not ready (" + p.firmwareState + "); restart its firmware first");
  enter(PrintRunState::Paused, stepLabel() + ": " + m_printer->name() + " has no job of " + remoteName() +
                                   " any more; printing the step again from its start");
  beginPrint(m_positioner.snapshot());
  return core::Done{};
}

core::Status PrintRun::abort() {
  if (m_state == PrintRunState::Completed || m_state == PrintRunState::Aborted) return refuse("abort");
  // Whatever the run was doing it ends aborted, then its heaters go off (switchHeatersOff).
  const auto enterAborted = [this] {
    if (m_state == PrintRunState::Printing || (m_state == PrintRunState::Paused && m_printInterrupted)) {
      if (m_printer != nullptr && (m_phase != PrintPhase::None || m_printInterrupted)) {
        m_phase = PrintPhase::None;
        m_printerSideCommand = m_printer->cancelPrint();
        enter(PrintRunState::Aborted, stepLabel() + ": aborted while the region was printing: cancelling the job on " +
                                          m_printer->name());
        return;
      }
      if (m_state == PrintRunState::Printing) {
        enter(PrintRunState::Aborted, stepLabel() + ": aborted while the region was printing: stop the printer");
        return;
      }
    }
    if (m_state == PrintRunState::Moving || m_state == PrintRunState::Settling) {
      const core::Status stopped = requestStop();
      if (!stopped.ok()) m_lastProblem = "the stop was refused: " + stopped.error().describe();
      enter(PrintRunState::Aborted,
            stepLabel() + ": aborted; " +
                stopRequestText(stopped, m_positioner.name(), advice(PrintRunAdvice::EmergencyStop)));
      return;
    }
    enter(PrintRunState::Aborted, stepLabel() + ": aborted");
  };
  enterAborted();
  switchHeatersOff();
  return core::Done{};
}

// An aborted run leaves no heater on, whatever it was doing: between two steps the previous step's G-code may
// have left them hot for the next one. Queued behind a cancel, so it reaches the printer after the cancel.
void PrintRun::switchHeatersOff() {
  if (m_printer == nullptr) return;
  m_heatersOffCommand = m_printer->switchHeatersOff();
  enter(m_state, stepLabel() + ": switching the heaters of " + m_printer->name() + " off");
}

core::Status PrintRun::regionDone(std::size_t step) {
  if (m_state != PrintRunState::Printing && !(m_state == PrintRunState::Paused && m_printInterrupted))
    return core::Error{core::ErrorCode::InvalidParameter,
                       "region " + std::to_string(step + 1) + " cannot be done: no region is printing (the run is " +
                           printRunStateName(m_state) + ")",
                       "print run"};
  if (step != m_step)
    return core::Error{core::ErrorCode::InvalidParameter,
                       "region " + std::to_string(step + 1) + " is not the one printing (region " +
                           std::to_string(m_step + 1) + " is)",
                       "print run"};
  if (m_printer != nullptr && m_phase != PrintPhase::None)
    return core::Error{core::ErrorCode::InvalidParameter,
                       "region " + std::to_string(step + 1) + " is being printed by " + m_printer->name() +
                           ": the run goes on by itself when the printer reports it complete",
                       "print run"};
  enter(m_state, stepLabel() + ": region done (operator)");
  finishRegion();
  return core::Done{};
}

void PrintRun::finishRegion() {
  m_phase = PrintPhase::None;
  m_printInterrupted = false;
  m_stepBegun = false;
  if (m_step + 1 == m_steps.size()) {
    enter(PrintRunState::Completed, "all " + std::to_string(m_steps.size()) + " regions printed");
    return;
  }
  ++m_step;
  if (m_pausePending) {
    m_pausePending = false;
    enter(PrintRunState::Paused, stepLabel() + ": paused before moving (requested while printing)");
    return;
  }
  const PositionerSnapshot snapshot = m_positioner.snapshot();
  if (snapshot.faulted || !snapshot.linkUp) {
    fault(snapshot.problem.empty() ? std::string("the positioner is not ready") : snapshot.problem);
    return;
  }
  beginMove();
}

void PrintRun::tick() {
  const PositionerSnapshot snapshot = m_positioner.snapshot();
  watchStop(snapshot);
  if (m_printer != nullptr) logProtocolWarnings();
  if (m_awaitingPrinterStop && m_printer->status().stop.confirmed) {
    m_awaitingPrinterStop = false;
    enter(m_state, stepLabel() + ": " + m_printer->name() + " confirmed the emergency stop");
  }
  if (commandReady(m_printerSideCommand)) {
    const core::Status side = m_printerSideCommand.get();
    if (!side.ok()) enter(m_state, stepLabel() + ": the printer refused: " + side.error().describe());
  }
  if (commandReady(m_heatersOffCommand)) {
    const core::Status off = m_heatersOffCommand.get();
    if (off.ok())
      enter(m_state, stepLabel() + ": " + m_printer->name() + " switched the heaters off");
    else if (m_printer->status().stop.latched())
      enter(m_state, stepLabel() + ": the heaters-off was not taken (" + off.error().describe() +
                         "); the printer's emergency stop switches its heaters off");
    else
      enter(m_state, stepLabel() + ": the heaters of " + m_printer->name() +
                         " may still be on: " + off.error().describe() + "; switch them off on the printer");
  }
  if (m_state != PrintRunState::Moving && m_state != PrintRunState::Settling && m_state != PrintRunState::Printing)
    return;
  const auto now = m_options.steadyNow();
  if (m_state == PrintRunState::Printing) {
    if (m_phase != PrintPhase::None) tickPrinter(snapshot);
    if (m_state != PrintRunState::Printing) return;
    if ((snapshot.faulted || !snapshot.linkUp) && !m_faultLoggedWhilePrinting) {
      m_faultLoggedWhilePrinting = true;
      enter(PrintRunState::Printing, stepLabel() + ": warning while printing: " +
                                         (snapshot.problem.empty() ? std::string("link down") : snapshot.problem));
    }
    return;
  }
  if (snapshot.faulted) return fault(snapshot.problem.empty() ? "the positioner reports a fault" : snapshot.problem);
  if (!snapshot.linkUp)
    return fault("the link to " + m_positioner.name() + " is down" +
                 (snapshot.problem.empty() ? std::string() : ": " + snapshot.problem));
  if (m_state == PrintRunState::Moving) {
    if (snapshot.reached) {
      m_settleStarted = now;
      enter(PrintRunState::Settling, stepLabel() + ": reached, settling");
    } else if (now - m_moveStarted > m_options.moveTimeout) {
      fault("the target was not reached within " + std::to_string(m_options.moveTimeout.count()) + " ms");
    }
    return;
  }
  // Settling
  if (!snapshot.reached) {
    enter(PrintRunState::Moving, stepLabel() + ": left the target while settling, waiting again");
    return;
  }
  if (now - m_settleStarted >= m_options.settleTime) {
    if (stepUsesPrinter()) return beginPrint(snapshot);
    m_stepBegun = true;
    enter(PrintRunState::Printing, stepLabel() + ": settled; print region " + std::to_string(m_step + 1));
    if (m_printRequest) m_printRequest(m_step, m_steps[m_step]);
  }
}

std::string PrintRun::remoteName() const {
  return std::filesystem::path(m_steps[m_step].gcodePath).filename().string();
}

void PrintRun::beginPrint(const PositionerSnapshot& snapshot) {
  // The printer never starts unless the platform is at rest at the step's orientation.
  if (!snapshot.reached || snapshot.moving || !snapshot.linkUp || snapshot.faulted)
    return fault("the print was not started: " + m_positioner.name() + " is not at rest at the step's orientation");
  const PrinterStatus p = m_printer->status();
  if (p.linkLost)
    return fault("the print was not started: the link to " + m_printer->name() + " is lost" +
                 (p.lastError.empty() ? std::string() : " (" + p.lastError + ")"));
  if (p.state == PrinterJobState::Unknown)
    return fault("the print was not started: " + unknownStateText(p) + "; check the printer");
  if (p.busy())
    return fault("the print was not started: " + m_printer->name() + " reports a job " +
                 printerJobStateName(p.state) + " (" + p.currentFile + "); let it finish or cancel it on the printer");
  if (p.stop.latched()) return fault("the print was not started: the printer's emergency stop is latched");
  m_phase = PrintPhase::Uploading;
  m_printInterrupted = false;
  m_printerPausedLogged = false;
  m_progressTenths = -1;
  m_printerCommand = m_printer->upload(m_steps[m_step].gcodePath, remoteName(), m_steps[m_step].gcodeSha256);
  enter(PrintRunState::Printing, stepLabel() + ": settled; uploading " + m_steps[m_step].gcodePath + " to " +
                                     m_printer->name() + " as " + remoteName());
  if (m_printRequest) m_printRequest(m_step, m_steps[m_step]);
}

void PrintRun::logProtocolWarnings() {
  const PrinterStatus p = m_printer->status();
  // The count starts again at a reconnect of the link: all of its warnings are then new.
  if (p.protocolWarnings < m_protocolWarningsLogged) m_protocolWarningsLogged = 0;
  if (p.protocolWarnings == m_protocolWarningsLogged) return;
  // Only the latest warning's words are kept by the link: those before it, since the last tick, are counted.
  const std::uint64_t earlier = p.protocolWarnings - m_protocolWarningsLogged - 1;
  m_protocolWarningsLogged = p.protocolWarnings;
  enter(m_state, stepLabel() + ": warning from " + m_printer->name() + ": " + p.lastWarning +
                     (earlier > 0 ? " (and " + std::to_string(earlier) + " earlier since the last one logged)"
                                  : std::string()) +
                     "; the link went on without it (" + std::to_string(p.protocolWarnings) +
                     (p.protocolWarnings == 1 ? " warning" : " warnings") + " since the link connected)");
}

void PrintRun::interruptPrint(const std::string& reason) {
  m_phase = PrintPhase::None;
  m_printInterrupted = true;
  m_lastProblem = reason;
  enter(PrintRunState::Paused, stepLabel() + ": paused: " + reason + "; the platform stays where it is; " +
                                   advice(PrintRunAdvice::PrintInterrupted));
}


void PrintRun::tickPrinter(const PositionerSnapshot& snapshot) {
  const PrinterStatus p = m_printer->status();
  if (snapshot.moving) {
    m_printerSideCommand = m_printer->pausePrint();
    return interruptPrint(m_positioner.name() + " moved while the region printed: the printer's job was paused");
  }
  if (p.linkLost)
    return interruptPrint("the link to " + m_printer->name() + " is lost" +
                          (p.lastError.empty() ? std::string() : " (" + p.lastError + ")") +
                          "; the printer may still be printing on its own");
  if (m_phase == PrintPhase::Uploading) {
    if (!commandReady(m_printerCommand)) return;
    const core::Status uploaded = m_printerCommand.get();
    if (!uploaded.ok()) return interruptPrint("the upload of " + remoteName() + " failed: " + uploaded.error().describe());
    m_phase = PrintPhase::Starting;
    m_stepBegun = true;  // from here the printer may print, even when its answer is lost
    m_printerCommand = m_printer->startPrint(remoteName());
    enter(PrintRunState::Printing, stepLabel() + ": uploaded; starting " + remoteName());
    return;
  }
  if (m_phase == PrintPhase::Starting) {
    if (!commandReady(m_printerCommand)) return;
    const core::Status started = m_printerCommand.get();
    if (!started.ok()) {
      // Refused in the printer's words: it did not start. No answer at all: it may have.
      if (started.error().code != core::ErrorCode::DeviceUnreachable) m_stepBegun = false;
      return interruptPrint("the printer did not start " + remoteName() + ": " + started.error().describe());
    }
    m_phase = PrintPhase::Running;
    m_jobSeen = false;
    m_pollsAtStart = p.polls;
    m_printStarted = m_options.steadyNow();
    enter(PrintRunState::Printing, stepLabel() + ": " + m_printer->name() + " prints " + remoteName());
    return;
  }
  // Running: only a status read after the start was answered tells about this job.
  if (p.polls <= m_pollsAtStart) return;
  const bool ours = p.currentFile == remoteName();
  if (p.state == PrinterJobState::Unknown)
    return interruptPrint(unknownStateText(p) + "; the printer may still be printing on its own");
  if (p.state == PrinterJobState::Error)
    return interruptPrint("the printer reports an error" + (p.message.empty() ? std::string() : ": " + p.message));
  if (p.state == PrinterJobState::Cancelled && ours)
    return interruptPrint("the job " + remoteName() + " was cancelled on the printer");
  if (ours && (p.state == PrinterJobState::Printing || p.state == PrinterJobState::Paused)) {
    m_jobSeen = true;
    m_stepProgress = p.progress;
    if (const std::string fault = temperatureFault(p, m_options.temperatureOvershootC); !fault.empty()) {
      m_printerSideCommand = m_printer->pausePrint();
      return interruptPrint(fault);
    }
    if (p.state == PrinterJobState::Paused && !m_printerPausedLogged) {
      m_printerPausedLogged = true;
      enter(PrintRunState::Printing, stepLabel() + ": the job was paused on the printer; waiting for it to resume");
    } else if (p.state == PrinterJobState::Printing) {
      m_printerPausedLogged = false;
    }
    const int tenths = static_cast<int>(std::floor(p.progress * 10.0));
    if (tenths > m_progressTenths) {
      m_progressTenths = tenths;
      enter(PrintRunState::Printing, stepLabel() + ": printing, " + std::to_string(tenths * 10) + " %, extruder " +
                                         celsius(p.extruder.actualC) + " / " + celsius(p.extruder.targetC) + ", bed " +
                                         celsius(p.bed.actualC) + " / " + celsius(p.bed.targetC));
    }
    return;
  }
  if (ours && p.state == PrinterJobState::Complete) {
    enter(PrintRunState::Printing, stepLabel() + ": " + m_printer->name() + " reports " + remoteName() + " complete");
    return finishRegion();
  }
  // Seen printing, and now neither printing, paused nor complete: the printer lost the job (it restarted, e.g.
  // Klipper's standby with no file).
  if (m_jobSeen)
    return interruptPrint(m_printer->name() + " no longer has the job " + remoteName() + ": it reports " +
                          printerJobStateName(p.state) +
                          (p.currentFile.empty() ? std::string(" with no file") : " of " + p.currentFile) +
                          " (it may have restarted)");
  if (m_options.steadyNow() - m_printStarted > m_options.printStartTimeout)
    interruptPrint("the printer accepted the start of " + remoteName() + " but reports " +
                   printerJobStateName(p.state) + (p.currentFile.empty() ? std::string() : " of " + p.currentFile) +
                   " after " + std::to_string(m_options.printStartTimeout.count()) + " ms");
}

core::Status PrintRun::emergencyStop() {
  // Both devices first, before anything that could take time.
  const core::Status platform = m_positioner.emergencyStop();
  if (m_printer != nullptr) m_printerSideCommand = m_printer->emergencyStop();
  m_awaitingStopConfirmation = platform.ok();
  m_awaitingPrinterStop = m_printer != nullptr;
  m_stopProblemLogged = false;
  m_stopRequested = m_options.steadyNow();
  m_phase = PrintPhase::None;
  m_lastProblem = "emergency stop";
  std::string message = stepLabel() + ": EMERGENCY STOP sent to " + m_positioner.name() +
                        (platform.ok() ? std::string() : " (refused: " + platform.error().describe() + ")") +
                        (m_printer != nullptr ? " and " + m_printer->name() : std::string(" (no printer link: stop the printer by hand)"));
  const bool finished = m_state == PrintRunState::Completed || m_state == PrintRunState::Aborted;
  enter(finished ? m_state : PrintRunState::Aborted, message);
  return core::Done{};
}

}  // namespace multidir::hardware

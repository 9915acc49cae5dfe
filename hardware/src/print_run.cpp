#include "multidir/hardware/print_run.h"

#include <utility>

#include "degrees_text.h"

namespace multidir::hardware {

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

PrintRun::PrintRun(Positioner& positioner, std::vector<PrintStep> steps, PrintRunOptions options)
    : m_positioner(positioner), m_steps(std::move(steps)), m_options(std::move(options)) {
  if (!m_options.steadyNow) m_options.steadyNow = [] { return std::chrono::steady_clock::now(); };
  if (!m_options.wallNow) m_options.wallNow = [] { return std::chrono::system_clock::now(); };
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
  entry.message = message;
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
std::string stopRequestText(const core::Status& stopped, const std::string& device) {
  if (stopped.ok()) return "stopping " + device + " (waiting for it to confirm)";
  return "the stop was refused (" + stopped.error().describe() + "): " + device +
         " may still move; use the E-STOP or cut its power";
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
                       "); it is sent as soon as the link allows; if the device still moves, use the E-STOP");
  }
}

void PrintRun::fault(const std::string& problem) {
  m_lastProblem = problem;
  const core::Status stopped = requestStop();
  enter(PrintRunState::Faulted, stepLabel() + ": " + problem + "; " + stopRequestText(stopped, m_positioner.name()) +
                                    "; fix it, then resume to retry the step or abort");
}

void PrintRun::beginMove() {
  m_pausePending = false;
  m_faultLoggedWhilePrinting = false;
  m_moveStarted = m_options.steadyNow();
  core::Status started = m_positioner.startMove(m_steps[m_step].orientation);
  if (!started.ok()) {
    m_lastProblem = started.error().describe();
    enter(PrintRunState::Faulted, stepLabel() + ": the move was refused: " + m_lastProblem);
    return;
  }
  enter(PrintRunState::Moving, stepLabel() + ": moving " + m_positioner.name());
}

core::Status PrintRun::start() {
  if (m_state != PrintRunState::Idle) return refuse("start");
  if (m_steps.empty())
    return core::Error{core::ErrorCode::InvalidParameter, "the print run has no steps: plan the regions first",
                       "print run"};
  m_started = m_options.steadyNow();
  m_step = 0;
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
        enter(PrintRunState::Faulted, stepLabel() + ": pause: " + stopRequestText(stopped, m_positioner.name()));
        return stopped;
      }
      enter(PrintRunState::Paused, stepLabel() + ": paused; " + stopRequestText(stopped, m_positioner.name()));
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

core::Status PrintRun::abort() {
  if (m_state == PrintRunState::Completed || m_state == PrintRunState::Aborted) return refuse("abort");
  if (m_state == PrintRunState::Printing) {
    enter(PrintRunState::Aborted, stepLabel() + ": aborted while the region was printing: stop the printer");
    return core::Done{};
  }
  if (m_state == PrintRunState::Moving || m_state == PrintRunState::Settling) {
    const core::Status stopped = requestStop();
    if (!stopped.ok()) m_lastProblem = "the stop was refused: " + stopped.error().describe();
    enter(PrintRunState::Aborted, stepLabel() + ": aborted; " + stopRequestText(stopped, m_positioner.name()));
    return core::Done{};
  }
  enter(PrintRunState::Aborted, stepLabel() + ": aborted");
  return core::Done{};
}

core::Status PrintRun::regionDone(std::size_t step) {
  if (m_state != PrintRunState::Printing)
    return core::Error{core::ErrorCode::InvalidParameter,
                       "region " + std::to_string(step + 1) + " cannot be done: no region is printing (the run is " +
                           printRunStateName(m_state) + ")",
                       "print run"};
  if (step != m_step)
    return core::Error{core::ErrorCode::InvalidParameter,
                       "region " + std::to_string(step + 1) + " is not the one printing (region " +
                           std::to_string(m_step + 1) + " is)",
                       "print run"};
  enter(PrintRunState::Printing, stepLabel() + ": region done");
  if (m_step + 1 == m_steps.size()) {
    enter(PrintRunState::Completed, "all " + std::to_string(m_steps.size()) + " regions printed");
    return core::Done{};
  }
  ++m_step;
  if (m_pausePending) {
    m_pausePending = false;
    enter(PrintRunState::Paused, stepLabel() + ": paused before moving (requested while printing)");
    return core::Done{};
  }
  const PositionerSnapshot snapshot = m_positioner.snapshot();
  if (snapshot.faulted || !snapshot.linkUp) {
    fault(snapshot.problem.empty() ? std::string("the positioner is not ready") : snapshot.problem);
    return core::Done{};
  }
  beginMove();
  return core::Done{};
}

void PrintRun::tick() {
  const PositionerSnapshot snapshot = m_positioner.snapshot();
  watchStop(snapshot);
  if (m_state != PrintRunState::Moving && m_state != PrintRunState::Settling && m_state != PrintRunState::Printing)
    return;
  const auto now = m_options.steadyNow();
  if (m_state == PrintRunState::Printing) {
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
    enter(PrintRunState::Printing, stepLabel() + ": settled; print region " + std::to_string(m_step + 1));
    if (m_printRequest) m_printRequest(m_step, m_steps[m_step]);
  }
}

}  // namespace multidir::hardware

#include "run_robot_command.h"

#include <cmath>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <string>

#include "multidir/hardware/robot_run.h"
#include "multidir/hardware/ur_link.h"
#include "multidir/slicing/estimates.h"
#include "run_command.h"

namespace multidir::cli {
namespace {

// Ctrl-C (and SIGTERM, SIGHUP): a stop; Ctrl-Z (SIGTSTP): while a step runs, a pause; while paused, the resume
// (docs/robot-cell.md, "Pause and resume"). The handlers only count.
hardware::RobotRunRequests g_robotRequests;
extern "C" void onRobotRunSignal(int) { g_robotRequests.stops.fetch_add(1); }
extern "C" void onRobotPauseSignal(int) { g_robotRequests.pauseToggles.fetch_add(1); }

std::string clockText() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[16];
  std::strftime(text, sizeof text, "%H:%M:%S", &local);
  return text;
}

void logLine(std::ostream& out, const std::string& text) {
  out << "[" << clockText() << "] " << text << "\n" << std::flush;
}

// The run's events as the console's log lines.
class ConsoleLog : public hardware::RobotRunListener {
 public:
  explicit ConsoleLog(std::ostream& out) : m_out(out) {}

  void poweringOn() override { logLine(m_out, "powering the arm on and releasing its brakes"); }
  void stepStarting(int step, int steps, const std::string& program) override {
    logLine(m_out, "step " + std::to_string(step) + "/" + std::to_string(steps) + ": sending " + program);
    m_lastProgress.clear();
  }
  void robotMessage(const hardware::UrLinkMessage& message) override {
    if (message.kind == hardware::UrLinkMessage::Kind::Text) logLine(m_out, "robot: " + message.describe());
  }
  void progress(const hardware::RobotRunProgress& p) override {
    char percent[16];
    std::snprintf(percent, sizeof percent, "%.0f %%", 100.0 * p.fraction);
    // Where in the step: the movel the robot says it runs (its register; by position for older jobs) and, for a
    // step split into programs the controller accepts, which of them runs.
    std::string where;
    if (p.movel >= 0) where += ", movel " + std::to_string(p.movel + 1) + " of " + std::to_string(p.movels);
    if (p.parts > 1) where += ", program " + std::to_string(p.part) + " of " + std::to_string(p.parts);
    const std::string text = "progress: step " + std::to_string(p.step) + "/" + std::to_string(p.steps) + " " +
                             p.programState + " " + percent + where + ", job remaining about " +
                             slicing::durationText(p.secondsLeft);
    if (text != m_lastProgress) logLine(m_out, m_lastProgress = text);
  }
  void cannotPause(const std::string& why) override {
    logLine(m_out, "cannot pause: " + why + "; Ctrl-C stops the run");
  }
  void paused(const hardware::RobotRunPause& p) override {
    logLine(m_out, "paused at a safe point: step " + std::to_string(p.step) + " after movel " +
                       std::to_string(p.movel + 1) + " of " + std::to_string(p.movels) +
                       (p.parts > 1 ? " in program " + std::to_string(p.part) + " of " + std::to_string(p.parts) : "") +
                       " (the extruder stopped, the platform " + std::to_string(static_cast<int>(p.liftMm)) +
                       " mm off the nozzle); Ctrl-Z again (kill -TSTP) resumes, Ctrl-C stops");
  }
  void resuming(int step, int movel, const std::string& program) override {
    logLine(m_out, "resuming step " + std::to_string(step) + " after movel " + std::to_string(movel + 1) +
                       ": back down to the nozzle, then the rest of " + program);
  }
  void poweringOff() override {
    logLine(m_out, "second stop signal: powering the arm off (the dashboard's power off)");
  }
  void stopSettled(const hardware::StopLatch& latch) override {
    logLine(m_out, latch.confirmed ? std::string("the robot confirmed the ") + hardware::stopKindName(latch.kind)
                                   : "warning: the robot has not confirmed the stop (" + latch.problem +
                                         "): check the arm by hand");
  }
  void stepDone(int step, int steps, double robotSeconds, double estimateSeconds) override {
    char took[32];
    std::snprintf(took, sizeof took, "%.1f s", robotSeconds);
    logLine(m_out, "step " + std::to_string(step) + "/" + std::to_string(steps) + " done in " + took +
                       " of the robot's time (the job's estimate: " + slicing::durationText(estimateSeconds) + ")");
  }

 private:
  std::ostream& m_out;
  std::string m_lastProgress;
};

}  // namespace

int runRobotJob(const ParsedArgs& parsed, std::ostream& out, std::ostream& err) {
  for (const char* other : {"--printer", "--platform", "--machine", "--unit", "--api-key", "--api-key-file", "--settle",
                            "--printer-profile", "--yes-axes-configured"})
    if (parsed.has(other))
      throw UsageError(std::string("multidir run: ") + other +
                       " is not for --robot (the arm carries the part under the cell's fixed extruder; the "
                       "programs drive both). Run 'multidir help run'.");
  const std::string folder = onlyPositional(parsed, "run", "robot job", "multidir run OUT --robot HOST[:PORT]");
  core::Result<hardware::UrLinkSettings> settings = hardware::parseUrAddress(parsed.value("--robot", ""));
  if (!settings) throw UsageError("multidir run: " + settings.error().describe() + ". Run 'multidir help run'.");
  const core::Result<hardware::RobotJob> read = hardware::readRobotJob(folder);
  if (!read) throw FileError("multidir run: " + read.error().describe());
  const hardware::RobotJob& job = read.value();
  const int steps = static_cast<int>(job.steps.size());
  int from = 1;
  if (parsed.has("--from")) {
    const double value = parseNumber(parsed.value("--from", ""), "--from");
    if (value != std::floor(value) || value < 1 || value > steps)
      throw UsageError("multidir run: --from must be a whole number from 1 to " + std::to_string(steps) +
                       ". Run 'multidir help run'.");
    from = static_cast<int>(value);
  }

  g_robotRequests.stops = 0;
  g_robotRequests.pauseToggles = 0;
  g_robotRequests.stopName = "Ctrl-C";
  auto previousTstp = std::signal(SIGTSTP, onRobotPauseSignal);
  auto previousInt = std::signal(SIGINT, onRobotRunSignal);
  auto previousTerm = std::signal(SIGTERM, onRobotRunSignal);
  auto previousHup = std::signal(SIGHUP, onRobotRunSignal);
  struct Restore {
    void (*i)(int), (*t)(int), (*h)(int), (*z)(int);
    ~Restore() {
      std::signal(SIGINT, i);
      std::signal(SIGTERM, t);
      std::signal(SIGHUP, h);
      std::signal(SIGTSTP, z);
    }
  } restore{previousInt, previousTerm, previousHup, previousTstp};

  const std::string where = settings->host + ":" + std::to_string(settings->dashboardPort);
  hardware::UrLink link(*settings);
  if (core::Status c = link.connect(); !c) {
    err << "multidir run: the robot at " << where << " cannot be reached: " << c.error().describe() << "\n";
    return kExitRunStopped;
  }
  const hardware::UrLinkStatus s = link.status();
  logLine(out, "connected to the robot at " + where + " (robot mode " + s.robotMode + ", safety mode " + s.safetyMode +
                   ", program " + s.programState + "); job: " + std::to_string(steps) + " steps for " + job.robot);

  ConsoleLog log(out);
  const hardware::RobotRunEnd end = hardware::runRobotJob(link, job, from, g_robotRequests, log);
  switch (end.kind) {
    case hardware::RobotRunEnd::Kind::Done:
      logLine(out, "done: " + std::to_string(end.stepsPrinted) + " steps printed");
      return kExitOk;
    case hardware::RobotRunEnd::Kind::Refused:
      err << "multidir run: " << end.why << "\n";
      return kExitRunStopped;
    case hardware::RobotRunEnd::Kind::Stopped:
      break;
  }
  err << "multidir run: the run stopped at step " << end.step << ": " << end.why << "; when the cause is fixed, "
      << "continue with --from " << end.step << " (the step's program runs again from its start) or --from "
      << end.step + 1 << " if the step is complete\n";
  return kExitRunStopped;
}

}  // namespace multidir::cli

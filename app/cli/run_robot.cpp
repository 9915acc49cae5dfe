#include "run_robot.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "multidir/hardware/ur_link.h"
#include "multidir/robot/cell.h"
#include "multidir/robot/movel_register.h"
#include "multidir/slicing/estimates.h"
#include "robot_pause.h"
#include "run_command.h"

namespace multidir::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

std::atomic<int> g_robotInterrupts{0};
extern "C" void onRobotRunSignal(int) { g_robotInterrupts.fetch_add(1); }
// Ctrl-Z (SIGTSTP): while a step runs, a pause; while paused, the resume (docs/robot-cell.md, "Pause and resume").
std::atomic<int> g_robotPauses{0};
extern "C" void onRobotPauseSignal(int) { g_robotPauses.fetch_add(1); }

struct RobotStep {
  int step = 0;
  std::string program;   // file name in the job folder
  std::string script;    // its text
  double seconds = 0.0;  // the job's estimate
};

struct RobotJob {
  std::string robot;
  std::vector<RobotStep> steps;
  // From the job's copy of its cell (cell.json): what a pause needs; absent, the run cannot pause.
  bool canPause = false;
  std::string whyNoPause;
  PauseGeometry pause;
};

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

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw FileError("multidir run: " + path.string() + " cannot be read: check that it exists and its permissions");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// robot-job.json (format multidir-robot-job, version 1) and every step's program, read before anything moves.
RobotJob readRobotJob(const std::string& folderText) {
  const fs::path folder(folderText);
  const fs::path jobFile = fs::is_directory(folder) ? folder / "robot-job.json" : folder;
  const fs::path base = jobFile.parent_path();
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(readText(jobFile));
  } catch (const nlohmann::json::parse_error& e) {
    throw FileError("multidir run: " + jobFile.string() + " is not JSON (" + e.what() +
                    "): write it again with 'multidir robot-program'");
  }
  const auto bad = [&](const std::string& what) {
    return FileError("multidir run: " + jobFile.string() + ": " + what +
                     ": write it again with 'multidir robot-program'");
  };
  if (!json.is_object() || json.value("format", "") != "multidir-robot-job")
    throw bad("not a robot job (its \"format\" is not \"multidir-robot-job\")");
  if (json.value("version", 0) != 1)
    throw bad("version " + json.value("version", nlohmann::json()).dump() + " is not one this MultiDir reads (1)");
  RobotJob job;
  job.robot = json.value("robot", "");
  if (!json.contains("steps") || !json["steps"].is_array() || json["steps"].empty()) throw bad("it has no steps");
  for (const nlohmann::json& entry : json["steps"]) {
    RobotStep step;
    if (!entry.is_object() || !entry.contains("step") || !entry["step"].is_number_integer() ||
        !entry.contains("program") || !entry["program"].is_string() || !entry.contains("seconds") ||
        !entry["seconds"].is_number())
      throw bad("step " + std::to_string(job.steps.size() + 1) + " lacks its step, program or seconds");
    step.step = entry["step"].get<int>();
    step.program = entry["program"].get<std::string>();
    step.seconds = entry["seconds"].get<double>();
    if (!(step.seconds >= 0.0)) throw bad("step " + std::to_string(step.step) + "'s seconds are negative");
    const fs::path program = base / step.program;
    if (step.program.find('/') != std::string::npos || step.program.find("..") != std::string::npos ||
        !fs::is_regular_file(fs::symlink_status(program)))
      throw bad("step " + std::to_string(step.step) + "'s program " + step.program +
                " is not a regular file in the job folder");
    step.script = readText(program);
    job.steps.push_back(std::move(step));
  }
  const std::string cellName = json.value("cell", "");
  const fs::path cellFile = base / cellName;
  if (cellName.empty() || cellName.find('/') != std::string::npos || !fs::is_regular_file(cellFile)) {
    job.whyNoPause = "the job has no copy of its cell (cell.json), which gives the nozzle axis to lift along";
  } else if (auto cell = robot::parseCell(cellFile); !cell) {
    job.whyNoPause = "its cell.json cannot be read: " + cell.error().describe();
  } else {
    job.canPause = true;
    job.pause.nozzleAxis = {cell->nozzleAxis.x(), cell->nozzleAxis.y(), cell->nozzleAxis.z()};
    job.pause.travelSpeedMmPerS = cell->motion.travelSpeedMmPerS;
    job.pause.toolAccelMmPerS2 = cell->motion.toolAccelMmPerS2;
  }
  return job;
}

std::string describeMessages(const std::vector<hardware::UrLinkMessage>& messages) {
  std::string text;
  for (const hardware::UrLinkMessage& m : messages)
    if (m.kind != hardware::UrLinkMessage::Kind::Text) text += (text.empty() ? "" : "; ") + m.describe();
  return text;
}

// A pause asked for during a step: the arm brought to a safe point (docs/robot-cell.md, "Pause and resume").
struct PauseOutcome {
  enum class Kind { Paused, NotInAMove, Failed } kind = Kind::Failed;
  std::string why;    // Failed
  StepScript script;  // Paused: the step's program read, and the movel after which it resumes
  int movel = -1;
};

// The dashboard's pause (the arm brakes on its way, the program holds), then, from where the arm stands, the
// movel under way: the pause program finishes it, stops the extruder and lifts the platform off the nozzle.
// When the arm is in a joint move (no movel under way), the program plays on and the pause is tried again later.
// `layerLineNow` takes the robot's messages and gives the line of the last layer message: it is asked once the arm
// stands still, so the layers the program entered until the pause landed bound the search (asked before the pause,
// the bound can be layers old: the messages of every layer the program entered between the run's last look and
// the pause landing, on a loaded machine or a slow link; then a travel of an older layer, lifted by the slicer's
// z hop to the next layer's height, passes within the tolerance of where the arm stands and was taken for the
// move under way: the pause finished that old travel and the resumed program printed again what followed it).
PauseOutcome pauseAtSafePoint(hardware::UrLink& link, const RobotJob& job, const RobotStep& step,
                              const std::function<int()>& layerLineNow, std::ostream& out) {
  PauseOutcome outcome;
  auto script = parseStepScript(step.script, step.program);
  if (!script) return {PauseOutcome::Kind::Failed, "cannot pause: " + script.error().describe(), {}, -1};
  outcome.script = std::move(script.value());
  if (auto reply = link.dashboard("pause"); !reply || reply.value() != "Pausing program")
    return {PauseOutcome::Kind::Failed,
            "the robot did not pause (" + (reply ? reply.value() : reply.error().describe()) + ")", {}, -1};
  // Wait for the arm to stand still.
  const auto deadline = Clock::now() + 5s;
  hardware::UrLinkStatus now = link.status();
  while (Clock::now() < deadline && !(now.programState == "PAUSED" && now.atRest)) {
    std::this_thread::sleep_for(5ms);
    now = link.status();
  }
  if (!(now.programState == "PAUSED" && now.atRest))
    return {PauseOutcome::Kind::Failed, "the arm did not come to rest after the pause (program " + now.programState + ")",
            {}, -1};
  // Where it stands, on the program's movels: within 0.2 mm (the arm brakes on its path), from the last layer the
  // program entered before it held (its messages were sent before the arm came to rest).
  const int layerLine = layerLineNow();
  const std::array<double, 3> tcpMm = {now.tcp[0] * 1000.0, now.tcp[1] * 1000.0, now.tcp[2] * 1000.0};
  if (robot::programNumbersMovels(step.script)) {
    // The robot says which movel it runs (its register, on RTDE): wait for the register of the rest state.
    const auto registerDeadline = Clock::now() + 2s;
    while (Clock::now() < registerDeadline && link.status().movelRegisterTime < now.controllerTime)
      std::this_thread::sleep_for(5ms);
    const hardware::UrLinkStatus held = link.status();
    if (held.movelRegisterTime < now.controllerTime)
      return {PauseOutcome::Kind::Failed, "the robot's RTDE state did not follow its real-time state within 2 s", {},
              -1};
    const PauseGeometry& g = job.pause;
    const std::array<double, 3> first = outcome.script.ends.front();
    const std::array<double, 3> approach = {first[0] - g.liftMm * g.nozzleAxis[0], first[1] - g.liftMm * g.nozzleAxis[1],
                                            first[2] - g.liftMm * g.nozzleAxis[2]};
    outcome.movel = robot::movelNamedByRegister(outcome.script.ends, approach, tcpMm, held.movelRegister, 0.2);
  } else {
    outcome.movel = movelUnderWay(outcome.script, job.pause, tcpMm, 0.2, layerLine);
  }
  if (outcome.movel < 0) {
    (void)link.dashboard("play");
    outcome.kind = PauseOutcome::Kind::NotInAMove;
    return outcome;
  }
  if (core::Status sent = link.sendProgram(pauseProgram(outcome.script, job.pause, outcome.movel)); !sent)
    return {PauseOutcome::Kind::Failed, "the pause program could not be sent: " + sent.error().describe(), {}, -1};
  // It runs to its end: the dashboard names the last program with its state.
  const auto until = Clock::now() + 120s;
  while (Clock::now() < until) {
    std::this_thread::sleep_for(20ms);
    const hardware::UrLinkStatus s = link.status();
    if (s.safetyMode != "NORMAL" || s.robotMode != "RUNNING" || s.linkLost)
      return {PauseOutcome::Kind::Failed, "the pause program did not finish (robot mode " + s.robotMode +
                                              ", safety mode " + s.safetyMode + ")", {}, -1};
    auto state = link.dashboard("programState");
    if (state && state.value() == "STOPPED multidir_pause" && s.atRest) {
      logLine(out, "paused at a safe point: step " + std::to_string(step.step) + " after movel " +
                       std::to_string(outcome.movel + 1) + " of " + std::to_string(outcome.script.movels.size()) +
                       " (the extruder stopped, the platform " + std::to_string(static_cast<int>(job.pause.liftMm)) +
                       " mm off the nozzle); Ctrl-Z again (kill -TSTP) resumes, Ctrl-C stops");
      outcome.kind = PauseOutcome::Kind::Paused;
      return outcome;
    }
  }
  return {PauseOutcome::Kind::Failed, "the pause program did not finish within 120 s", {}, -1};
}

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
  const RobotJob job = readRobotJob(folder);
  const int steps = static_cast<int>(job.steps.size());
  int from = 1;
  if (parsed.has("--from")) {
    const double value = parseNumber(parsed.value("--from", ""), "--from");
    if (value != std::floor(value) || value < 1 || value > steps)
      throw UsageError("multidir run: --from must be a whole number from 1 to " + std::to_string(steps) +
                       ". Run 'multidir help run'.");
    from = static_cast<int>(value);
  }

  g_robotInterrupts = 0;
  g_robotPauses = 0;
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
  hardware::UrLinkStatus s = link.status();
  logLine(out, "connected to the robot at " + where + " (robot mode " + s.robotMode + ", safety mode " + s.safetyMode +
                   ", program " + s.programState + "); job: " + std::to_string(steps) + " steps for " + job.robot);
  if (s.programState != "STOPPED") {
    err << "multidir run: the robot is running a program (" << s.programState
        << "): stop it on the teach pendant (or with the dashboard's stop) first\n";
    return kExitRunStopped;
  }
  if (s.robotMode != "RUNNING") logLine(out, "powering the arm on and releasing its brakes");
  if (core::Status on = link.powerOn(60s); !on) {
    err << "multidir run: " << on.error().describe() << "\n";
    return kExitRunStopped;
  }

  // How the run ends when it does not complete: the stop latched (resent until the robot confirms it), then
  // the reason in the robot's words and how to go on.
  const auto stopAndEnd = [&](int step, const std::string& why, bool operatorStop) {
    const hardware::UrLinkStatus now = link.status();
    if (now.programState != "STOPPED" || !now.atRest || operatorStop) {
      link.stop();
      const auto deadline = Clock::now() + 10s;
      while (Clock::now() < deadline && !link.status().stop.confirmed) {
        if (g_robotInterrupts.load() > 1 && link.status().stop.kind != hardware::StopKind::EmergencyStop) {
          logLine(out, "second stop signal: powering the arm off (the dashboard's power off)");
          link.emergencyStop();
        }
        std::this_thread::sleep_for(20ms);
      }
      const hardware::StopLatch latch = link.status().stop;
      logLine(out, latch.confirmed ? std::string("the robot confirmed the ") + hardware::stopKindName(latch.kind)
                                   : "warning: the robot has not confirmed the stop (" + latch.problem +
                                         "): check the arm by hand");
    }
    err << "multidir run: the run stopped at step " << step << ": " << why << "; when the cause is fixed, "
        << "continue with --from " << step << " (the step's program runs again from its start) or --from " << step + 1
        << " if the step is complete\n";
    return kExitRunStopped;
  };

  double remainingAfter = 0.0;
  for (int k = from; k <= steps; ++k) remainingAfter += job.steps[static_cast<std::size_t>(k - 1)].seconds;
  for (int k = from; k <= steps; ++k) {
    const RobotStep& step = job.steps[static_cast<std::size_t>(k - 1)];
    remainingAfter -= step.seconds;
    (void)link.takeMessages();
    hardware::UrLinkStatus before = link.status();
    logLine(out, "step " + std::to_string(k) + "/" + std::to_string(steps) + ": sending " + step.program);
    if (core::Status sent = link.sendProgram(step.script); !sent)
      return stopAndEnd(k, "the program could not be sent: " + sent.error().describe(), false);
    const double startedAt = before.controllerTime;
    bool started = false;
    auto nextProgress = Clock::now() + 1s;
    std::string lastProgress;
    // The robot's messages since the last call: its texts logged, its faults described ("" when none). The
    // program's layer messages say where it is: the line of the last one bounds where a pause can have landed.
    int layerLine = 0;
    auto takeFaults = [&] {
      const std::vector<hardware::UrLinkMessage> messages = link.takeMessages();
      for (const hardware::UrLinkMessage& m : messages)
        if (m.kind == hardware::UrLinkMessage::Kind::Text) {
          logLine(out, "robot: " + m.describe());
          const std::size_t at = step.script.find("textmsg(\"" + m.text + "\")");
          if (m.text.rfind("multidir step ", 0) == 0 && at != std::string::npos)
            layerLine = static_cast<int>(std::count(step.script.begin(), step.script.begin() + static_cast<long>(at), '\n'));
        }
      return describeMessages(messages);
    };
    // Faults among the messages taken while a pause looks for the layer: reported by the loop's next look.
    std::string faultsWhilePausing;
    int pausesSeen = g_robotPauses.load();
    bool pausePending = false;
    auto nextPauseTry = Clock::now();
    while (true) {
      std::this_thread::sleep_for(10ms);
      if (g_robotInterrupts.load() > 0) return stopAndEnd(k, "stopped by Ctrl-C", true);
      const hardware::UrLinkStatus now = link.status();
      const std::string faults = faultsWhilePausing + takeFaults();
      faultsWhilePausing.clear();
      if (!faults.empty()) {
        // Let the state that goes with the message arrive, so the run reports both.
        std::this_thread::sleep_for(100ms);
        const hardware::UrLinkStatus after = link.status();
        return stopAndEnd(k,
                          "the robot reports: " + faults + " (robot mode " + after.robotMode + ", safety mode " +
                              after.safetyMode + ")",
                          false);
      }
      if (now.linkLost)
        return stopAndEnd(k,
                          "the link to the robot is lost (" + now.linkProblem +
                              "); the program may still run on the controller, and the stop is sent as soon as the "
                              "link is back",
                          false);
      if (now.safetyMode != "NORMAL" || now.robotMode != "RUNNING") {
        // The controller's words about it come on another interface than its state, and may arrive a little
        // later: wait up to half a second for them, so the operator reads the robot's reason, not only its mode.
        std::string words;
        for (int wait = 0; wait < 50 && words.empty(); ++wait) {
          std::this_thread::sleep_for(10ms);
          words = takeFaults();
        }
        const std::string modes = "(robot mode " + now.robotMode + ", safety mode " + now.safetyMode + ")";
        if (!words.empty()) return stopAndEnd(k, "the robot reports: " + words + " " + modes, false);
        return stopAndEnd(k, "the robot left normal operation " + modes, false);
      }
      started = started || now.programStarts > before.programStarts;
      if (now.programEnds > before.programEnds && now.atRest) break;
      if (g_robotPauses.load() != pausesSeen) {  // Ctrl-Z while the step runs: pause
        pausesSeen = g_robotPauses.load();
        if (!job.canPause)
          logLine(out, "cannot pause: " + job.whyNoPause + "; Ctrl-C stops the run");
        else
          pausePending = true;
      }
      if (pausePending && started && Clock::now() >= nextPauseTry) {
        const PauseOutcome paused = pauseAtSafePoint(link, job, step, [&] {
          faultsWhilePausing += takeFaults();
          return layerLine;
        }, out);
        if (paused.kind == PauseOutcome::Kind::NotInAMove) {
          nextPauseTry = Clock::now() + 300ms;  // in a joint move (home, the approach): again at the next movel
          continue;
        }
        pausePending = false;
        if (paused.kind == PauseOutcome::Kind::Failed)
          return stopAndEnd(k, paused.why + (faultsWhilePausing.empty() ? "" : "; the robot reports: " + faultsWhilePausing),
                            false);
        // Paused: wait for the resume, a stop or a fault.
        while (true) {
          std::this_thread::sleep_for(10ms);
          if (g_robotInterrupts.load() > 0) return stopAndEnd(k, "stopped by Ctrl-C while paused", true);
          const std::string words = faultsWhilePausing + takeFaults();
          faultsWhilePausing.clear();
          const hardware::UrLinkStatus still = link.status();
          if (!words.empty() || still.linkLost || still.safetyMode != "NORMAL" || still.robotMode != "RUNNING")
            return stopAndEnd(k,
                              "while paused, " +
                                  (words.empty() ? std::string("the robot left normal operation") : "the robot reports: " + words) +
                                  (still.linkLost ? " (the link to the robot is lost: " + still.linkProblem + ")" : "") +
                                  " (robot mode " + still.robotMode + ", safety mode " + still.safetyMode + ")",
                              false);
          if (g_robotPauses.load() != pausesSeen) break;  // Ctrl-Z again: resume
        }
        pausesSeen = g_robotPauses.load();
        const std::string resumed = resumeProgram(paused.script, job.pause, paused.movel);
        before = link.status();
        logLine(out, "resuming step " + std::to_string(k) + " after movel " + std::to_string(paused.movel + 1) +
                         ": back down to the nozzle, then the rest of " + step.program);
        if (core::Status sent = link.sendProgram(resumed); !sent)
          return stopAndEnd(k, "the resumed program could not be sent: " + sent.error().describe(), false);
        started = false;
        continue;
      }
      if (Clock::now() >= nextProgress && started) {
        nextProgress = Clock::now() + 1s;
        const double elapsed = now.controllerTime - startedAt;
        const double left = std::max(0.0, step.seconds - elapsed) + remainingAfter;
        char percent[16];
        std::snprintf(percent, sizeof percent, "%.0f %%",
                      step.seconds > 0.0 ? std::min(100.0, 100.0 * elapsed / step.seconds) : 100.0);
        const std::string text = "progress: step " + std::to_string(k) + "/" + std::to_string(steps) + " " +
                                 now.programState + " " + percent + ", job remaining about " +
                                 slicing::durationText(left);
        if (text != lastProgress) logLine(out, lastProgress = text);
      }
    }
    const hardware::UrLinkStatus done = link.status();
    char took[32];
    std::snprintf(took, sizeof took, "%.1f s", done.controllerTime - startedAt);
    logLine(out, "step " + std::to_string(k) + "/" + std::to_string(steps) + " done in " + took +
                     " of the robot's time (the job's estimate: " + slicing::durationText(step.seconds) + ")");
  }
  logLine(out, "done: " + std::to_string(steps - from + 1) + " steps printed");
  return kExitOk;
}

}  // namespace multidir::cli

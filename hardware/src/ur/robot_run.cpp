#include "multidir/hardware/robot_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "multidir/robot/cell.h"
#include "multidir/robot/movel_register.h"

namespace multidir::hardware {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

core::Result<std::string> readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return core::Error{core::ErrorCode::FileNotFound,
                       path.string() + " cannot be read: check that it exists and its permissions", {}};
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

core::Result<RobotJob> readRobotJob(const std::string& folderText) {
  const fs::path folder(folderText);
  const fs::path jobFile = fs::is_directory(folder) ? folder / "robot-job.json" : folder;
  const fs::path base = jobFile.parent_path();
  nlohmann::json json;
  auto jobText = readText(jobFile);
  if (!jobText) return jobText.error();
  try {
    json = nlohmann::json::parse(jobText.value());
  } catch (const nlohmann::json::parse_error& e) {
    return core::Error{core::ErrorCode::MalformedFile, jobFile.string() + " is not JSON (" + e.what() +
                    "): write it again with 'multidir robot-program'", {}};
  }
  const auto bad = [&](const std::string& what) {
    return core::Error{core::ErrorCode::MalformedFile, jobFile.string() + ": " + what +
                     ": write it again with 'multidir robot-program'", {}};
  };
  if (!json.is_object() || json.value("format", "") != "multidir-robot-job")
    return bad("not a robot job (its \"format\" is not \"multidir-robot-job\")");
  if (json.value("version", 0) != 1)
    return bad("version " + json.value("version", nlohmann::json()).dump() + " is not one this MultiDir reads (1)");
  RobotJob job;
  job.robot = json.value("robot", "");
  if (!json.contains("steps") || !json["steps"].is_array() || json["steps"].empty()) return bad("it has no steps");
  for (const nlohmann::json& entry : json["steps"]) {
    RobotJobStep step;
    if (!entry.is_object() || !entry.contains("step") || !entry["step"].is_number_integer() ||
        !entry.contains("program") || !entry["program"].is_string() || !entry.contains("seconds") ||
        !entry["seconds"].is_number())
      return bad("step " + std::to_string(job.steps.size() + 1) + " lacks its step, program or seconds");
    step.step = entry["step"].get<int>();
    step.program = entry["program"].get<std::string>();
    step.seconds = entry["seconds"].get<double>();
    if (!(step.seconds >= 0.0)) return bad("step " + std::to_string(step.step) + "'s seconds are negative");
    const fs::path program = base / step.program;
    if (step.program.find('/') != std::string::npos || step.program.find("..") != std::string::npos ||
        !fs::is_regular_file(fs::symlink_status(program)))
      return bad("step " + std::to_string(step.step) + "'s program " + step.program +
                " is not a regular file in the job folder");
    auto script = readText(program);
    if (!script) return script.error();
    step.script = std::move(script.value());
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

namespace {

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
PauseOutcome pauseAtSafePoint(hardware::UrLink& link, const RobotJob& job, const RobotJobStep& step,
                              const std::function<int()>& layerLineNow, RobotRunListener& listener) {
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
      listener.paused({step.step, outcome.movel, static_cast<int>(outcome.script.movels.size()), job.pause.liftMm});
      outcome.kind = PauseOutcome::Kind::Paused;
      return outcome;
    }
  }
  return {PauseOutcome::Kind::Failed, "the pause program did not finish within 120 s", {}, -1};
}

}  // namespace

RobotRunEnd runRobotJob(UrLink& link, const RobotJob& job, int from, RobotRunRequests& requests,
                        RobotRunListener& listener) {
  const int steps = static_cast<int>(job.steps.size());
  hardware::UrLinkStatus s = link.status();
  if (s.programState != "STOPPED")
    return {RobotRunEnd::Kind::Refused, 0,
            "the robot is running a program (" + s.programState +
                "): stop it on the teach pendant (or with the dashboard's stop) first",
            0};
  if (s.robotMode != "RUNNING") listener.poweringOn();
  if (core::Status on = link.powerOn(60s); !on) return {RobotRunEnd::Kind::Refused, 0, on.error().describe(), 0};

  // How the run ends when it does not complete: the stop latched (resent until the robot confirms it), then
  // the reason in the robot's words and how to go on.
  const auto stopAndEnd = [&](int step, const std::string& why, bool operatorStop) {
    const hardware::UrLinkStatus now = link.status();
    if (now.programState != "STOPPED" || !now.atRest || operatorStop) {
      link.stop();
      const auto deadline = Clock::now() + 10s;
      while (Clock::now() < deadline && !link.status().stop.confirmed) {
        if (requests.stops.load() > 1 && link.status().stop.kind != hardware::StopKind::EmergencyStop) {
          listener.poweringOff();
          link.emergencyStop();
        }
        std::this_thread::sleep_for(20ms);
      }
      listener.stopSettled(link.status().stop);
    }
    return RobotRunEnd{RobotRunEnd::Kind::Stopped, step, why, step - from};
  };

  double remainingAfter = 0.0;
  for (int k = from; k <= steps; ++k) remainingAfter += job.steps[static_cast<std::size_t>(k - 1)].seconds;
  for (int k = from; k <= steps; ++k) {
    const RobotJobStep& step = job.steps[static_cast<std::size_t>(k - 1)];
    remainingAfter -= step.seconds;
    (void)link.takeMessages();
    hardware::UrLinkStatus before = link.status();
    listener.stepStarting(k, steps, step.program);
    if (core::Status sent = link.sendProgram(step.script); !sent)
      return stopAndEnd(k, "the program could not be sent: " + sent.error().describe(), false);
    const double startedAt = before.controllerTime;
    bool started = false;
    auto nextProgress = Clock::now() + 1s;
    // The step's movels, to say which one the arm is on (the progress's move index/count).
    const auto movels = parseStepScript(step.script, step.program);
    // The robot's messages since the last call: each told to the listener, its faults described ("" when none). The
    // program's layer messages say where it is: the line of the last one bounds where a pause can have landed.
    int layerLine = 0;
    auto takeFaults = [&] {
      const std::vector<hardware::UrLinkMessage> messages = link.takeMessages();
      for (const hardware::UrLinkMessage& m : messages) {
        listener.robotMessage(m);
        if (m.kind == hardware::UrLinkMessage::Kind::Text) {
          const std::size_t at = step.script.find("textmsg(\"" + m.text + "\")");
          if (m.text.rfind("multidir step ", 0) == 0 && at != std::string::npos)
            layerLine = static_cast<int>(std::count(step.script.begin(), step.script.begin() + static_cast<long>(at), '\n'));
        }
      }
      return describeMessages(messages);
    };
    // Faults among the messages taken while a pause looks for the layer: reported by the loop's next look.
    std::string faultsWhilePausing;
    int pausesSeen = requests.pauseToggles.load();
    bool pausePending = false;
    auto nextPauseTry = Clock::now();
    while (true) {
      std::this_thread::sleep_for(10ms);
      if (requests.stops.load() > 0) return stopAndEnd(k, "stopped by " + requests.stopName, true);
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
      if (requests.pauseToggles.load() != pausesSeen) {  // a pause asked for while the step runs
        pausesSeen = requests.pauseToggles.load();
        if (!job.canPause)
          listener.cannotPause(job.whyNoPause);
        else
          pausePending = true;
      }
      if (pausePending && started && Clock::now() >= nextPauseTry) {
        const PauseOutcome paused = pauseAtSafePoint(link, job, step, [&] {
          faultsWhilePausing += takeFaults();
          return layerLine;
        }, listener);
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
          if (requests.stops.load() > 0) return stopAndEnd(k, "stopped by " + requests.stopName + " while paused", true);
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
          if (requests.pauseToggles.load() != pausesSeen) break;  // asked again: resume
        }
        pausesSeen = requests.pauseToggles.load();
        const std::string resumed = resumeProgram(paused.script, job.pause, paused.movel);
        before = link.status();
        listener.resuming(k, paused.movel, step.program);
        if (core::Status sent = link.sendProgram(resumed); !sent)
          return stopAndEnd(k, "the resumed program could not be sent: " + sent.error().describe(), false);
        started = false;
        continue;
      }
      if (Clock::now() >= nextProgress && started) {
        nextProgress = Clock::now() + 1s;
        const double elapsed = now.controllerTime - startedAt;
        RobotRunProgress progress;
        progress.step = k;
        progress.steps = steps;
        progress.programState = now.programState;
        progress.fraction = step.seconds > 0.0 ? std::min(1.0, elapsed / step.seconds) : 1.0;
        progress.secondsLeft = std::max(0.0, step.seconds - elapsed) + remainingAfter;
        if (movels) {
          // On its path within the blend radius the program's movels use (0.5 mm), from the layer last reported.
          progress.movels = static_cast<int>(movels->movels.size());
          progress.movel = movelUnderWay(*movels, job.pause,
                                         {now.tcp[0] * 1000.0, now.tcp[1] * 1000.0, now.tcp[2] * 1000.0}, 0.5,
                                         layerLine);
        }
        listener.progress(progress);
      }
    }
    const hardware::UrLinkStatus done = link.status();
    listener.stepDone(k, steps, done.controllerTime - startedAt, step.seconds);
  }
  return {RobotRunEnd::Kind::Done, 0, {}, steps - from + 1};
}

}  // namespace multidir::hardware

#include "multidir/hardware/robot_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "multidir/robot/cell.h"
#include "multidir/robot/move_time.h"
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
  const int version = json.value("version", 0);
  if (version != 1 && version != 2)
    return bad("version " + json.value("version", nlohmann::json()).dump() + " is not one this MultiDir reads (1, 2)");
  RobotJob job;
  job.robot = json.value("robot", "");
  if (!json.contains("steps") || !json["steps"].is_array() || json["steps"].empty()) return bad("it has no steps");
  // A program file of the job: a plain file in the job folder, read.
  const auto readProgram = [&](int stepNumber, const std::string& name) -> core::Result<std::string> {
    const fs::path program = base / name;
    if (name.empty() || name.find('/') != std::string::npos || name.find("..") != std::string::npos ||
        !fs::is_regular_file(fs::symlink_status(program)))
      return bad("step " + std::to_string(stepNumber) + "'s program " + name + " is not a regular file in the job folder");
    return readText(program);
  };
  for (const nlohmann::json& entry : json["steps"]) {
    RobotJobStep step;
    const bool listsParts = version >= 2;
    if (!entry.is_object() || !entry.contains("step") || !entry["step"].is_number_integer() ||
        !entry.contains("seconds") || !entry["seconds"].is_number() ||
        (listsParts ? !entry.contains("parts") || !entry["parts"].is_array() || entry["parts"].empty()
                    : !entry.contains("program") || !entry["program"].is_string()))
      return bad("step " + std::to_string(job.steps.size() + 1) + " lacks its step, " +
                 (listsParts ? "parts" : "program") + " or seconds");
    step.step = entry["step"].get<int>();
    step.seconds = entry["seconds"].get<double>();
    if (!(step.seconds >= 0.0)) return bad("step " + std::to_string(step.step) + "'s seconds are negative");
    std::vector<std::string> names;
    if (listsParts) {
      for (const nlohmann::json& part : entry["parts"]) {
        if (!part.is_object() || !part.contains("program") || !part["program"].is_string())
          return bad("step " + std::to_string(step.step) + " has a part without its program");
        names.push_back(part["program"].get<std::string>());
      }
    } else {
      names.push_back(entry["program"].get<std::string>());
    }
    for (const std::string& name : names) {
      auto script = readProgram(step.step, name);
      if (!script) return script.error();
      step.parts.push_back({name, std::move(script.value())});
    }
    step.program = step.parts.front().program;
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

// The value after `key` ("a=", "v=") in a movel line, 0 when absent.
double movelArgument(const std::string& line, const std::string& key) {
  const std::size_t at = line.find(key, line.find(']'));
  return at == std::string::npos ? 0.0 : std::strtod(line.c_str() + at + key.size(), nullptr);
}

// A step's programs read as movels, once per step: the movel numbers run on across its parts (the register's).
struct StepMovels {
  std::vector<std::optional<StepScript>> parts;  // empty optional: the part cannot be read as movels
  std::vector<int> offsets;                      // the step's movels before each part
  int movels = 0;
  bool numbered = false;  // the programs write the movel register (robot/movel_register.h)
  // The planned time of the step's movels before movel i (i = 0..movels): each movel's trapezoid at its own a and v
  // from the end before it, as the job's estimate counts it.
  std::vector<double> secondsBefore{0.0};

  // Where part p's first movel comes from: the step's approach (the first end lifted off the nozzle) or the end of
  // the part before.
  [[nodiscard]] std::array<double, 3> firstFrom(std::size_t p, const PauseGeometry& g) const {
    if (p > 0 && parts[p - 1] && !parts[p - 1]->ends.empty()) return parts[p - 1]->ends.back();
    const std::array<double, 3> first = parts[p]->ends.front();
    return {first[0] - g.liftMm * g.nozzleAxis[0], first[1] - g.liftMm * g.nozzleAxis[1],
            first[2] - g.liftMm * g.nozzleAxis[2]};
  }
};

StepMovels readStepMovels(const RobotJobStep& step, const PauseGeometry& geometry) {
  StepMovels m;
  m.numbered = robot::programNumbersMovels(step.parts.front().script);
  bool readable = true;
  for (const RobotJobPart& part : step.parts) {
    m.offsets.push_back(m.movels);
    auto script = parseStepScript(part.script, part.program);
    readable = readable && script.ok();
    if (!script) {
      m.parts.emplace_back();
      continue;
    }
    m.parts.emplace_back(std::move(script.value()));
    const StepScript& s = *m.parts.back();
    std::array<double, 3> from = m.firstFrom(m.parts.size() - 1, geometry);
    for (std::size_t i = 0; i < s.ends.size(); ++i) {
      const std::string& line = s.lines[static_cast<std::size_t>(s.movels[i])];
      const double a = movelArgument(line, "a=") * 1000.0, v = movelArgument(line, "v=") * 1000.0;
      const double d = std::sqrt(std::pow(s.ends[i][0] - from[0], 2) + std::pow(s.ends[i][1] - from[1], 2) +
                                 std::pow(s.ends[i][2] - from[2], 2));
      const double t = a > 0.0 && v > 0.0 ? robot::trapezoidSeconds(d, v, a) : 0.0;
      m.secondsBefore.push_back(m.secondsBefore.back() + t);
      from = s.ends[i];
    }
    m.movels += static_cast<int>(s.ends.size());
  }
  if (!readable) m.movels = 0;
  return m;
}

// A pause asked for during a step: the arm brought to a safe point (docs/robot-cell.md, "Pause and resume").
struct PauseOutcome {
  enum class Kind { Paused, NotInAMove, Failed } kind = Kind::Failed;
  std::string why;    // Failed
  StepScript script;  // Paused: the part's program read, and its movel (0-based in it) after which it resumes
  int movel = -1;
};

// The dashboard's pause (the arm brakes on its way, the program holds), then, from where the arm stands, the
// movel under way in the step's program `part`: the pause program finishes it, stops the extruder and lifts the
// platform off the nozzle. When the arm is in a joint move (no movel under way), the program plays on and the
// pause is tried again later.
// `layerLineNow` takes the robot's messages and gives the line of the last layer message: it is asked once the arm
// stands still, so the layers the program entered until the pause landed bound the search (asked before the pause,
// the bound can be layers old: the messages of every layer the program entered between the run's last look and
// the pause landing, on a loaded machine or a slow link; then a travel of an older layer, lifted by the slicer's
// z hop to the next layer's height, passes within the tolerance of where the arm stands and was taken for the
// move under way: the pause finished that old travel and the resumed program printed again what followed it).
PauseOutcome pauseAtSafePoint(hardware::UrLink& link, const RobotJob& job, const RobotJobStep& step,
                              const StepMovels& stepMovels, std::size_t part, const std::function<int()>& layerLineNow,
                              RobotRunListener& listener) {
  PauseOutcome outcome;
  if (!stepMovels.parts[part]) {
    auto script = parseStepScript(step.parts[part].script, step.parts[part].program);
    return {PauseOutcome::Kind::Failed, "cannot pause: " + script.error().describe(), {}, -1};
  }
  outcome.script = *stepMovels.parts[part];
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
  const int offset = stepMovels.offsets[part];
  if (stepMovels.numbered) {
    // The robot says which movel it runs (its register, on RTDE): wait for the register of the rest state.
    const auto registerDeadline = Clock::now() + 2s;
    while (Clock::now() < registerDeadline && link.status().movelRegisterTime < now.controllerTime)
      std::this_thread::sleep_for(5ms);
    const hardware::UrLinkStatus held = link.status();
    if (held.movelRegisterTime < now.controllerTime)
      return {PauseOutcome::Kind::Failed, "the robot's RTDE state did not follow its real-time state within 2 s", {},
              -1};
    // The register numbers the step's movels across its parts: this part's start at `offset`.
    outcome.movel = robot::movelNamedByRegister(outcome.script.ends, stepMovels.firstFrom(part, job.pause), tcpMm,
                                                held.movelRegister > 0 ? held.movelRegister - offset : 0, 0.2);
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
      listener.paused({step.step, offset + outcome.movel, stepMovels.movels, job.pause.liftMm,
                       static_cast<int>(part) + 1, static_cast<int>(step.parts.size())});
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

  // Which of a split step's programs runs, for the reasons a run ends ("" for a step of one program).
  std::string partContext;
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
    return RobotRunEnd{RobotRunEnd::Kind::Stopped, step, why + partContext, step - from};
  };

  // The pause requests seen, and a pause asked for that has not landed yet: kept across a step's programs and its
  // steps, so a pause asked for as one program ends lands in the next.
  int pausesSeen = requests.pauseToggles.load();
  bool pausePending = false;
  double remainingAfter = 0.0;
  for (int k = from; k <= steps; ++k) remainingAfter += job.steps[static_cast<std::size_t>(k - 1)].seconds;
  for (int k = from; k <= steps; ++k) {
    const RobotJobStep& step = job.steps[static_cast<std::size_t>(k - 1)];
    remainingAfter -= step.seconds;
    // The step's movels (the progress's move index/count, the pause's), over all its programs.
    const StepMovels stepMovels = readStepMovels(step, job.pause);
    const std::size_t partCount = step.parts.size();
    listener.stepStarting(k, steps, step.program);
    double startedAt = -1.0;
    for (std::size_t p = 0; p < partCount; ++p) {
      const RobotJobPart& part = step.parts[p];
      partContext = partCount < 2 ? std::string()
                                  : " (in " + part.program + ", program " + std::to_string(p + 1) + " of " +
                                        std::to_string(partCount) + " of the step)";
      (void)link.takeMessages();
      hardware::UrLinkStatus before = link.status();
      if (core::Status sent = link.sendProgram(part.script); !sent)
        return stopAndEnd(k, "the program could not be sent: " + sent.error().describe(), false);
      if (startedAt < 0.0) startedAt = before.controllerTime;
      bool started = false;
      auto nextProgress = Clock::now() + 1s;
      // The robot's messages since the last call: each told to the listener, its faults described ("" when none).
      // The program's layer messages say where it is: the line of the last one bounds where a pause can have landed.
      int layerLine = 0;
      auto takeFaults = [&] {
        const std::vector<hardware::UrLinkMessage> messages = link.takeMessages();
        for (const hardware::UrLinkMessage& m : messages) {
          listener.robotMessage(m);
          if (m.kind == hardware::UrLinkMessage::Kind::Text) {
            const std::size_t at = part.script.find("textmsg(\"" + m.text + "\")");
            if (m.text.rfind("multidir step ", 0) == 0 && at != std::string::npos)
              layerLine =
                  static_cast<int>(std::count(part.script.begin(), part.script.begin() + static_cast<long>(at), '\n'));
          }
        }
        return describeMessages(messages);
      };
      // Faults among the messages taken while a pause looks for the layer: reported by the loop's next look.
      std::string faultsWhilePausing;
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
          const PauseOutcome paused = pauseAtSafePoint(link, job, step, stepMovels, p, [&] {
            faultsWhilePausing += takeFaults();
            return layerLine;
          }, listener);
          if (paused.kind == PauseOutcome::Kind::NotInAMove) {
            nextPauseTry = Clock::now() + 300ms;  // in a joint move (home, the approach): again at the next movel
            continue;
          }
          pausePending = false;
          if (paused.kind == PauseOutcome::Kind::Failed)
            return stopAndEnd(
                k, paused.why + (faultsWhilePausing.empty() ? "" : "; the robot reports: " + faultsWhilePausing), false);
          // Paused: wait for the resume, a stop or a fault.
          while (true) {
            std::this_thread::sleep_for(10ms);
            if (requests.stops.load() > 0)
              return stopAndEnd(k, "stopped by " + requests.stopName + " while paused", true);
            const std::string words = faultsWhilePausing + takeFaults();
            faultsWhilePausing.clear();
            const hardware::UrLinkStatus still = link.status();
            if (!words.empty() || still.linkLost || still.safetyMode != "NORMAL" || still.robotMode != "RUNNING")
              return stopAndEnd(k,
                                "while paused, " +
                                    (words.empty() ? std::string("the robot left normal operation")
                                                   : "the robot reports: " + words) +
                                    (still.linkLost ? " (the link to the robot is lost: " + still.linkProblem + ")" : "") +
                                    " (robot mode " + still.robotMode + ", safety mode " + still.safetyMode + ")",
                                false);
            if (requests.pauseToggles.load() != pausesSeen) break;  // asked again: resume
          }
          pausesSeen = requests.pauseToggles.load();
          // The rest of this part; the step's next parts follow it as they would have.
          const std::string resumed = resumeProgram(paused.script, job.pause, paused.movel);
          before = link.status();
          listener.resuming(k, stepMovels.offsets[p] + paused.movel, part.program);
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
          progress.part = static_cast<int>(p) + 1;
          progress.parts = static_cast<int>(partCount);
          progress.fraction = step.seconds > 0.0 ? std::min(1.0, elapsed / step.seconds) : 1.0;
          if (stepMovels.movels > 0) {
            progress.movels = stepMovels.movels;
            if (stepMovels.numbered) {
              // The robot says which movel it runs (its register): paths that cross are told apart.
              if (now.movelRegister >= 1 && now.movelRegister <= stepMovels.movels) progress.movel = now.movelRegister - 1;
            } else if (stepMovels.parts[p]) {
              // A job written before the register: on its path within the blend radius the program's movels use
              // (0.5 mm), from the layer last reported.
              const int local = movelUnderWay(*stepMovels.parts[p], job.pause,
                                              {now.tcp[0] * 1000.0, now.tcp[1] * 1000.0, now.tcp[2] * 1000.0}, 0.5,
                                              layerLine);
              if (local >= 0) progress.movel = stepMovels.offsets[p] + local;
            }
            // The share of the step's movel time done before the movel under way, against the time spent.
            const double total = stepMovels.secondsBefore.back();
            if (progress.movel >= 0 && total > 0.0)
              progress.fraction = stepMovels.secondsBefore[static_cast<std::size_t>(progress.movel)] / total;
          }
          progress.secondsLeft = (1.0 - progress.fraction) * step.seconds + remainingAfter;
          listener.progress(progress);
        }
      }
    }
    partContext.clear();
    const hardware::UrLinkStatus done = link.status();
    listener.stepDone(k, steps, done.controllerTime - startedAt, step.seconds);
  }
  return {RobotRunEnd::Kind::Done, 0, {}, steps - from + 1};
}

}  // namespace multidir::hardware

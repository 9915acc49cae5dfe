#include "run_robot.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "multidir/hardware/ur_link.h"
#include "multidir/slicing/estimates.h"
#include "run_command.h"

namespace multidir::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

std::atomic<int> g_robotInterrupts{0};
extern "C" void onRobotRunSignal(int) { g_robotInterrupts.fetch_add(1); }

struct RobotStep {
  int step = 0;
  std::string program;   // file name in the job folder
  std::string script;    // its text
  double seconds = 0.0;  // the job's estimate
};

struct RobotJob {
  std::string robot;
  std::vector<RobotStep> steps;
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
  return job;
}

std::string describeMessages(const std::vector<hardware::UrLinkMessage>& messages) {
  std::string text;
  for (const hardware::UrLinkMessage& m : messages)
    if (m.kind != hardware::UrLinkMessage::Kind::Text) text += (text.empty() ? "" : "; ") + m.describe();
  return text;
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
  auto previousInt = std::signal(SIGINT, onRobotRunSignal);
  auto previousTerm = std::signal(SIGTERM, onRobotRunSignal);
  auto previousHup = std::signal(SIGHUP, onRobotRunSignal);
  struct Restore {
    void (*i)(int), (*t)(int), (*h)(int);
    ~Restore() {
      std::signal(SIGINT, i);
      std::signal(SIGTERM, t);
      std::signal(SIGHUP, h);
    }
  } restore{previousInt, previousTerm, previousHup};

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
    const hardware::UrLinkStatus before = link.status();
    logLine(out, "step " + std::to_string(k) + "/" + std::to_string(steps) + ": sending " + step.program);
    if (core::Status sent = link.sendProgram(step.script); !sent)
      return stopAndEnd(k, "the program could not be sent: " + sent.error().describe(), false);
    const double startedAt = before.controllerTime;
    bool started = false;
    auto nextProgress = Clock::now() + 1s;
    std::string lastProgress;
    // The robot's messages since the last call: its texts logged, its faults described ("" when none).
    auto takeFaults = [&] {
      const std::vector<hardware::UrLinkMessage> messages = link.takeMessages();
      for (const hardware::UrLinkMessage& m : messages)
        if (m.kind == hardware::UrLinkMessage::Kind::Text) logLine(out, "robot: " + m.describe());
      return describeMessages(messages);
    };
    while (true) {
      std::this_thread::sleep_for(10ms);
      if (g_robotInterrupts.load() > 0) return stopAndEnd(k, "stopped by Ctrl-C", true);
      const hardware::UrLinkStatus now = link.status();
      const std::string faults = takeFaults();
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

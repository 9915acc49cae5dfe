#include "run_command.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <thread>

#include "api_key.h"
#include "cli_args.h"
#include "firmware_axes_positioner.h"
#include "multidir/hardware/platform_check.h"
#include "multidir/hardware/print_run.h"
#include "multidir/hardware/printer_url.h"
#include "multidir/hardware/robot_arm.h"
#include "multidir/hardware/rotary_platform.h"
#include "multidir/slicing/estimates.h"
#include "run_job_checks.h"
#include "run_job_file.h"
#include "run_robot_command.h"
#include "run_stitched.h"

namespace multidir::cli {

const char* const kRunHelp =
    "Usage: multidir run JOB --printer URL --platform HOST:PORT --machine PROFILE.json [options]\n"
    "       multidir run JOB --printer URL [--yes-axes-configured] [options]   (a job the printer's axes turn)\n"
    "       multidir run OUT --robot HOST[:PORT] [--from STEP]   (a robot cell's job: 'multidir robot-program')\n"
    "\n"
    "Runs a sliced print job headless (JOB: the folder written by 'multidir slice' for a profile whose platform\n"
    "is driven over Modbus, or its print-job.json). For each step: turns the platform (4-DOF rotary controller\n"
    "or 5-DOF robot arm, as the job's machine says) to the step's orientation, waits until it has settled,\n"
    "sends the step's G-code to the printer (Klipper through Moonraker, or OctoPrint: uploaded and started;\n"
    "Marlin over USB: streamed line by line), follows it until the printer reports it complete, and goes on.\n"
    "The platform never moves while the printer prints, and the printer never starts while the platform is not\n"
    "at rest at the step's orientation.\n"
    "\n"
    "A job sliced for a printer whose own firmware turns the platform (multidir.platform = firmware-axis or\n"
    "firmware-2axis: one or two rotary axes, such as Open5x's U and V or Klipper's [manual_stepper]s) is one\n"
    "stitched program, job.gcode, that turns the axes itself between the steps. The printer alone prints it:\n"
    "no --platform, --machine, --unit, --settle or --printer-profile (refused). Before it starts, job.gcode must\n"
    "be the file print-job.json names (slicing.stitched), a regular file in the job folder, and the printer\n"
    "must have every axis the program turns: Klipper is asked for its manual_stepper objects, Marlin for M114\n"
    "(its report lists the extra axes after Z); OctoPrint cannot be asked (it relays no firmware reply), so\n"
    "check the printer yourself and say so with --yes-axes-configured. The upload is checked by its SHA-256,\n"
    "as a step's is. --from STEP sends the program from the transition before that step on (no homing, no\n"
    "purge line, the axes declared where step STEP-1 printed): the printer must still be homed and the\n"
    "platform stand where that step left it.\n"
    "\n"
    "Before anything moves, the whole job is checked: every step's angles against the platform's own machine\n"
    "profile (--machine; the limits print-job.json carries describe the plan, not the platform), and every\n"
    "step's G-code file (a regular file in the job folder, not a link, one per step) by the checks\n"
    "'multidir slice' ran, against the printer profile it was sliced with.\n"
    "\n"
    "Every event is logged with its time; a progress line (step, printer progress, temperatures, the job's\n"
    "remaining time from the slicer's estimates) follows the printer. When the printer reports an error, a\n"
    "job cancelled on the printer, a temperature fault, or a link is lost, the run stops there (the platform\n"
    "stays where it is) and says why and how to go on: when nothing of the step was printed, fix it and\n"
    "continue with --from STEP; a step interrupted while printing cannot be printed again from its start over\n"
    "the part already printed: accept it (or finish it by hand) and continue with --from STEP+1, or clear the\n"
    "platform and print the whole job again.\n"
    "\n"
    "Ctrl-C (and SIGTERM, or SIGHUP when the terminal closes) stops both devices: the platform's motion and\n"
    "the printer's job (cancelled), and switches the printer's heaters off, whatever the run is doing (also\n"
    "while the platform turns). A second Ctrl-C sends\n"
    "both emergency stops (Klipper then needs a FIRMWARE_RESTART; OctoPrint sends M112 and disconnects from the\n"
    "printer, which needs a reset and a Connect in OctoPrint's Connection panel; Marlin a reset; the platform a\n"
    "clear fault and homing).\n"
    "\n"
    "With --robot, OUT is the folder 'multidir robot-program' wrote (robot-job.json and each step's URScript\n"
    "program, or its parts in order) for a cell whose Universal Robots arm carries the part under a fixed extruder: the run connects to\n"
    "the controller's dashboard server (PORT, default 29999), secondary interface (PORT+1, default 30002) and\n"
    "real-time interface (PORT+2, default 30003), powers the arm on and releases its brakes when needed, sends\n"
    "each step's program (each of its parts) in order and waits until it has ended with the arm at rest,\n"
    "logging the programs'\n"
    "textmsg lines, progress and the job's time left from robot-job.json's per-step seconds. A protective\n"
    "stop, an emergency stop, a program error or a lost link stops the run with the robot's own words. Ctrl-C\n"
    "stops the program (the dashboard's stop, latched and resent until the robot's state shows the program\n"
    "stopped and the arm at rest, and again after a reconnect); a second Ctrl-C powers the arm off. Ctrl-Z\n"
    "(SIGTSTP) pauses the step at a safe point: the move under way finished, the extruder stopped, the part\n"
    "30 mm off the nozzle (the job's cell.json gives the axis); Ctrl-Z again resumes it from the next move,\n"
    "down from 30 mm over it (docs/robot-cell.md, \"Pause and resume\").\n"
    "\n"
    "Options:\n"
    "  --robot HOST[:PORT]  the UR controller (docs/hardware.md, \"UR controller\")\n"
    "  --printer URL        the printer: Klipper through Moonraker at http://HOST:PORT (default port 80),\n"
    "                       moonraker://HOST:PORT or HOST:PORT (7125 when absent); OctoPrint at\n"
    "                       octoprint://HOST:PORT (default port 80; OctoPrint's own server uses 5000); Marlin\n"
    "                       over USB serial at serial:///dev/ttyACM0[?baud=115200]\n"
    "  --api-key-file FILE  the printer's API key, read from FILE (one line): OctoPrint's (required: Settings >\n"
    "                       Application Keys), or Moonraker's when its [authorization] asks for one. Without\n"
    "                       it, the environment variable MULTIDIR_PRINTER_API_KEY is read. Prefer either to\n"
    "  --api-key KEY        the key itself, which is visible to every user in the process list\n"
    "  --platform HOST:PORT the platform's Modbus TCP address (rotary controller or robot)\n"
    "  --machine FILE       the connected platform's machine profile (JSON, as 'multidir decompose --profile'\n"
    "                       reads): its angle range and step, or maximal tilt and forbidden cones\n"
    "  --printer-profile P  the printer profile (NAME or .ini) the G-code is checked against (default: the one\n"
    "                       the job was sliced with)\n"
    "  --unit ID            Modbus unit id, 0..255 (default: 1 for the rotary controller, 255 for the robot)\n"
    "  --from STEP          start at this step, 1..the number of steps (default: 1)\n"
    "  --yes-axes-configured  (a job the printer's axes turn, on OctoPrint) the printer has the axes the\n"
    "                       program turns: OctoPrint cannot be asked\n"
    "  --settle MS          the platform holds the orientation this long before printing (default: 500)\n"
    "  --log FILE           also write the log to FILE (a write error is reported at once; the run goes on)\n"
    "  -h, --help           show this help\n"
    "\n"
    "Exit codes: 0 every step printed, 1 the job cannot be read, 2 usage error, 4 the run did not complete\n"
    "(a device unreachable or faulted, a printer fault, Ctrl-C, SIGTERM, SIGHUP).\n";

namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

std::atomic<int> g_interrupts{0};
std::atomic<int> g_firstSignal{0};

extern "C" void onRunSignal(int signal) {
  int none = 0;
  g_firstSignal.compare_exchange_strong(none, signal);
  g_interrupts.fetch_add(1);
}

// The first stop signal as the log names it: each one stops the devices as Ctrl-C does.
std::string interruptName() {
  switch (g_firstSignal.load()) {
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP (the terminal closed)";
    default:
      return "Ctrl-C";
  }
}

int wholeNumber(const std::string& text, const std::string& option, long low, long high) {
  const double value = parseNumber(text, option);
  if (value != std::floor(value) || value < static_cast<double>(low) || value > static_cast<double>(high))
    throw UsageError("multidir run: " + option + " must be a whole number from " + std::to_string(low) + " to " +
                     std::to_string(high) + ", not '" + text + "'. Run 'multidir help run'.");
  return static_cast<int>(value);
}

std::string clockText() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[16];
  std::strftime(text, sizeof text, "%H:%M:%S", &local);
  return text;
}

// `text` without terminal control sequences: the devices' own words (a printer's message, a file name from
// the job) could hold escapes that colour, move or clear the terminal, and the log file is read as text.
// ESC sequences (CSI "ESC [ ... final", OSC "ESC ] ... BEL or ESC \\", and two-byte ones) are dropped; other
// control characters but the tab become '?'.
std::string withoutControls(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == 0x1b) {
      const char kind = i + 1 < text.size() ? text[i + 1] : '\0';
      i += 1;
      if (kind == '[') {
        while (i + 1 < text.size() && !(text[i + 1] >= 0x40 && text[i + 1] <= 0x7e)) ++i;
        ++i;
      } else if (kind == ']') {
        while (i + 1 < text.size() && text[i + 1] != '\a' && !(text[i + 1] == 0x1b)) ++i;
        ++i;
        if (i < text.size() && text[i] == 0x1b) ++i;  // ESC \\ ends it
      }
      continue;
    }
    out += (c < 0x20 && c != '\t') || c == 0x7f ? '?' : static_cast<char>(c);
  }
  return out;
}

// Writes each line to the terminal and the log file. A log file that cannot be written (a full disk) is
// reported at once, on the terminal and stderr, and then left alone: the run goes on, since stopping the
// devices over a log would be worse than a log that ends early.
class RunLog {
 public:
  RunLog(std::ostream& out, std::ostream& err, const std::string& path) : m_out(out), m_err(err), m_path(path) {
    if (path.empty()) return;
    m_file.open(path, std::ios::app);
    if (!m_file)
      throw FileError("multidir run: cannot write the log file " + path + ": check the folder exists and is writable");
  }
  void line(const std::string& text) {
    const std::string stamped = "[" + clockText() + "] " + withoutControls(text) + "\n";
    m_out << stamped << std::flush;
    toFile(stamped);
  }
  // The command's last word (why it stopped, how to go on): on stderr, and in the log file with its time.
  void ending(const std::string& text) {
    const std::string clean = "multidir run: " + withoutControls(text);
    m_err << clean << "\n" << std::flush;
    toFile("[" + clockText() + "] " + clean + "\n");
  }

 private:
  void toFile(const std::string& text) {
    if (!m_file.is_open()) return;
    errno = 0;
    m_file << text << std::flush;
    if (m_file) return;
    const std::string why = errno != 0 ? std::strerror(errno) : "write error";
    m_file.close();
    const std::string warning = "warning: the log file " + withoutControls(m_path) + " cannot be written (" + why +
                                "): the run goes on, logged on the terminal only from here";
    m_out << "[" + clockText() + "] " + warning + "\n" << std::flush;
    m_err << "multidir run: " << warning << "\n" << std::flush;
  }

  std::ostream& m_out;
  std::ostream& m_err;
  std::string m_path;
  std::ofstream m_file;
};

// Restores the previous handlers however the command ends.
class SignalScope {
 public:
  // SIGHUP (the terminal closed) and SIGTERM stop the devices as Ctrl-C does; SIGPIPE is ignored while the run
  // lasts, so output to a pipe whose reader is gone (`| tee` in the closed terminal) cannot end the command
  // before it stopped them.
  SignalScope() {
    g_interrupts = 0;
    g_firstSignal = 0;
    m_int = std::signal(SIGINT, onRunSignal);
    m_term = std::signal(SIGTERM, onRunSignal);
    m_hup = std::signal(SIGHUP, onRunSignal);
    m_pipe = std::signal(SIGPIPE, SIG_IGN);
  }
  ~SignalScope() {
    std::signal(SIGINT, m_int);
    std::signal(SIGTERM, m_term);
    std::signal(SIGHUP, m_hup);
    std::signal(SIGPIPE, m_pipe);
  }
  SignalScope(const SignalScope&) = delete;
  SignalScope& operator=(const SignalScope&) = delete;

 private:
  void (*m_int)(int) = SIG_DFL;
  void (*m_term)(int) = SIG_DFL;
  void (*m_hup)(int) = SIG_DFL;
  void (*m_pipe)(int) = SIG_DFL;
};

// Ctrl-C before the run started (connecting, enabling, homing): the caller stops the devices.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Polls `condition` every 20 ms until it holds, `limit` passes or Ctrl-C.
bool waitFor(const std::function<bool()>& condition, std::chrono::milliseconds limit) {
  const auto deadline = Clock::now() + limit;
  while (Clock::now() < deadline && g_interrupts == 0) {
    if (condition()) return true;
    std::this_thread::sleep_for(20ms);
  }
  return condition();
}

// waitFor, and Interrupted naming `what` when Ctrl-C ended the wait.
bool waitOrInterrupt(const std::function<bool()>& condition, std::chrono::milliseconds limit, const std::string& what) {
  const bool held = waitFor(condition, limit);
  if (!held && g_interrupts > 0) throw Interrupted(interruptName() + " while " + what);
  return held;
}

std::string celsius(const hardware::HeaterReading& h) {
  char text[48];
  std::snprintf(text, sizeof text, "%.1f/%.0f C", h.actualC, h.targetC);
  return text;
}

// The devices of one run and how to bring the platform to a known state.
struct Devices {
  std::unique_ptr<hardware::PrinterLink> printer;
  std::unique_ptr<hardware::RotaryPlatform> rotary;
  std::unique_ptr<hardware::RobotArm> robot;
  std::unique_ptr<hardware::Positioner> positioner;
};

// `platform`: the connected platform's own profile (--machine), whose limits the drivers enforce.
void connectPlatform(Devices& devices, const RunJob& job, const core::MachineSpec& platform, const std::string& host,
                     int port, int unit, RunLog& log) {
  hardware::ConnectionSettings connection;
  connection.tcp.host = host;
  connection.tcp.port = port;
  // The job's device, told apart from the other before anything is written to either: a robot arm answers a
  // rotary job's registers with a Modbus exception that does not say the wrong device is connected.
  const bool rotary = job.machine.kind == core::MachineKind::RotaryPlatform;
  const int rotaryUnit = rotary && unit >= 0 ? unit : 1;
  const int robotUnit = !rotary && unit >= 0 ? unit : 255;
  if (core::Status kind = hardware::checkPlatformFor(job.machine.kind, connection, rotaryUnit, robotUnit); !kind)
    throw std::runtime_error("--platform " + host + ":" + std::to_string(port) + ": " + kind.error().message);
  if (rotary) {
    hardware::RotaryPlatformOptions options;
    options.connection = connection;
    options.connection.slaveId = unit < 0 ? 1 : unit;
    options.machine = platform;
    devices.rotary = std::make_unique<hardware::RotaryPlatform>(options);
    // Refused while another run controls the platform (docs/hardware.md, "One controller at a time").
    if (core::Status c = devices.rotary->connect(); !c) throw std::runtime_error(c.error().describe());
    log.line(devices.rotary->name() + " is controlled by this run (" +
             hardware::controlSessionText(devices.rotary->status().control.session) + ") until it ends");
    const hardware::RotaryStatus s = devices.rotary->status();
    if (s.fault != hardware::RotaryFault::None)
      throw std::runtime_error(devices.rotary->name() + " reports a fault (" + hardware::rotaryFaultName(s.fault) +
                               "): clear it in the studio or on the controller first");
    if (!s.homed) {
      log.line("homing " + devices.rotary->name() + " (not homed yet)");
      if (!s.enabled) {
        auto enabled = devices.rotary->enable();
        if (enabled.wait_for(5s) != std::future_status::ready || !enabled.get().ok() ||
            !waitOrInterrupt([&] { return devices.rotary->status().enabled; }, 5s, "enabling the platform"))
          throw std::runtime_error(devices.rotary->name() + " did not enable");
      }
      auto homed = devices.rotary->home();
      if (homed.wait_for(5s) != std::future_status::ready)
        throw std::runtime_error(devices.rotary->name() + " did not take the homing command");
      if (core::Status h = homed.get(); !h) throw std::runtime_error(h.error().describe());
      // Ends on a fault too (a stall, the limit switch): the controller stopped homing and will not finish.
      const auto homedOrFaulted = [&] {
        const hardware::RotaryStatus now = devices.rotary->status();
        return (now.homed && !now.homing) || now.fault != hardware::RotaryFault::None;
      };
      if (!waitOrInterrupt(homedOrFaulted, 120s, "homing the platform"))
        throw std::runtime_error(devices.rotary->name() + " did not finish homing within 120 s: check that it turns " +
                                 "freely and its home switch");
      if (const hardware::RotaryFault fault = devices.rotary->status().fault; fault != hardware::RotaryFault::None)
        throw std::runtime_error(devices.rotary->name() + " stopped homing with a fault (" +
                                 hardware::rotaryFaultName(fault) +
                                 "): check that it turns freely and its home switch, clear the fault on the "
                                 "controller (or with Clear fault in the studio), then run the job again");
    }
    devices.positioner = hardware::makePositioner(*devices.rotary);
    return;
  }
  hardware::RobotArmOptions options;
  options.connection = connection;
  options.connection.slaveId = unit < 0 ? 255 : unit;
  options.machine = platform;
  devices.robot = std::make_unique<hardware::RobotArm>(options);
  if (core::Status c = devices.robot->connect(); !c) throw std::runtime_error(c.error().describe());
  log.line(devices.robot->name() + " is controlled by this run (" +
           hardware::controlSessionText(devices.robot->status().control.session) + ") until it ends");
  devices.positioner = hardware::makePositioner(*devices.robot);
}

// Ctrl-C before the first step: the platform's stop (it may be homing) and the printer's heaters off (they
// may be on from before), each waited for at most 10 s.
void stopBeforeTheRun(Devices& devices, RunLog& log) {
  log.line(interruptName() + ": stopping the platform and switching the printer's heaters off");
  std::future<core::Status> platform;
  if (devices.rotary) platform = devices.rotary->stop();
  if (devices.robot) platform = devices.robot->stop();
  std::future<core::Status> heaters = devices.printer->switchHeatersOff();
  const auto outcome = [](std::future<core::Status>& f) -> std::string {
    if (!f.valid()) return "not connected";
    if (f.wait_for(10s) != std::future_status::ready) return "no answer within 10 s: check it by hand";
    const core::Status s = f.get();
    return s.ok() ? "done" : s.error().describe();
  };
  if (platform.valid()) log.line("platform stop: " + outcome(platform));
  log.line("heaters off: " + outcome(heaters));
}

// Klipper and OctoPrint keep a paused job and resume it themselves; Marlin's job is the stream multidir run
// sent, which ends with the command.
bool printerKeepsAResumableJob(const hardware::PrinterStatus& printer, const std::string& name,
                               const std::string& gcodeName) {
  return printer.state == hardware::PrinterJobState::Paused && printer.currentFile == gcodeName &&
         (name.rfind("Moonraker", 0) == 0 || name.rfind("OctoPrint", 0) == 0);
}

// The run ended on its own (a fault or a pause, no Ctrl-C) and the command is about to exit, leaving the
// printer unwatched: its heaters go off, unless it keeps a paused job it can resume itself (which needs them).
void leaveThePrinterSafe(Devices& devices, RunLog& log, const std::string& gcodeName) {
  const hardware::PrinterStatus printer = devices.printer->status();
  if (printer.linkLost) {
    log.line("warning: the printer cannot be reached to switch its heaters off: check it by hand");
    return;
  }
  if (printerKeepsAResumableJob(printer, devices.printer->name(), gcodeName)) {
    log.line("the printer keeps its paused job, and its heaters on for it: resume or cancel it there");
    return;
  }
  std::future<core::Status> heaters = devices.printer->switchHeatersOff();
  if (heaters.wait_for(10s) != std::future_status::ready) {
    log.line("warning: the printer did not confirm its heaters off within 10 s: check it by hand");
    return;
  }
  const core::Status off = heaters.get();
  log.line(off.ok() ? std::string("nobody watches the printer now: switched its heaters off")
                    : "warning: switching the printer's heaters off failed: " + off.error().describe());
}

// How to go on after the run stopped at job step `step` (1-based), true to what is on the platform: a step
// the printer had begun holds part of its region, which printing the step again from its start (--from) would
// print over.
std::string howToGoOn(const hardware::PrintRun& run, const hardware::PrinterStatus& printer, std::size_t step,
                      const std::string& name, std::size_t steps, const std::string& gcodeName,
                      bool stoppedByOperator) {
  const std::string from = "--from " + std::to_string(step);
  if (!run.stepBegun())
    return "; nothing of step " + std::to_string(step) + " was printed: continue with " + from +
           (stoppedByOperator ? " when ready" : " once it is fixed");
  char percent[16];
  std::snprintf(percent, sizeof percent, "%.0f %%", run.stepProgress() * 100.0);
  std::string text = "; step " + std::to_string(step) + " was interrupted while printing (" +
                     (run.stepProgress() > 0.0 ? "the printer had read " + std::string(percent) + " of " + gcodeName
                                               : "the printer had been started on " + gcodeName) +
                     "): part of its region may be on the platform, and " + from +
                     " would print the step again from its start, over that part, so it cannot go on from there. ";
  const std::string next = step < steps ? "continue with the next step: --from " + std::to_string(step + 1)
                                        : "the job is done (it was the last step)";
  if (printer.linkLost)
    return text + "The link to the printer is lost: it may still be printing " + gcodeName +
           " on its own; check it. If it completes the step, " + next +
           "; otherwise clear the platform and print the whole job again (without --from)";
  if (printerKeepsAResumableJob(printer, name, gcodeName))
    text +=
        "The printer's job is still paused on the printer: cancel it there (or resume it there once the cause "
        "is fixed and, when it is complete, " +
        next + "). ";
  return text + "Either accept step " + std::to_string(step) + " as it is (or finish it by hand) and " + next +
         ", or clear the platform and print the whole job again (without --from)";
}

}  // namespace

int runRun(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const ParsedArgs parsed = parseArgs(args,
                                      {"--printer", "--platform", "--unit", "--api-key", "--api-key-file", "--log",
                                       "--settle", "--from", "--machine", "--printer-profile", "--robot"},
                                      {"--help", "--yes-axes-configured"}, "run");
  if (parsed.has("--help")) {
    out << kRunHelp;
    return kExitOk;
  }
  if (parsed.has("--robot")) return runRobotJob(parsed, out, err);
  const std::string jobPath =
      onlyPositional(parsed, "run", "job", "multidir run JOB --printer URL --platform HOST:PORT");
  if (!parsed.has("--printer"))
    throw UsageError(
        "multidir run: --printer URL is required (Moonraker's address, such as http://192.168.0.20:7125, "
        "OctoPrint's, such as octoprint://192.168.0.21:80, or a Marlin printer's serial port, such as "
        "serial:///dev/ttyACM0). Run 'multidir help run'.");
  core::Result<std::unique_ptr<hardware::PrinterLink>> link =
      hardware::makePrinterLinkFromUrl(parsed.value("--printer", ""), printerApiKey(parsed, "run"));
  if (!link) throw UsageError("multidir run: " + link.error().describe() + ". Run 'multidir help run'.");
  std::string platformHost;
  int platformPort = 0;
  if (parsed.has("--platform")) {
    const std::string platformText = parsed.value("--platform", "");
    const std::size_t colon = platformText.rfind(':');
    if (colon == std::string::npos || colon == 0)
      throw UsageError("multidir run: --platform must be HOST:PORT, such as 192.168.0.30:502, not '" + platformText +
                       "'. Run 'multidir help run'.");
    platformHost = platformText.substr(0, colon);
    platformPort = wholeNumber(platformText.substr(colon + 1), "--platform's port", 1, 65535);
  }
  const int unit = parsed.has("--unit") ? wholeNumber(parsed.value("--unit", ""), "--unit", 0, 255) : -1;
  const int settleMs = wholeNumber(parsed.value("--settle", "500"), "--settle", 0, 600000);

  const RunJob job = readRunJob(jobPath);
  if (job.stitched) {
    // The printer alone prints the stitched program; the platform's options belong to a Modbus device.
    for (const char* modbusOnly : {"--platform", "--machine", "--unit", "--settle", "--printer-profile"})
      if (parsed.has(modbusOnly))
        throw UsageError("multidir run: " + job.jobFile + " was sliced for a platform the printer's firmware turns (" +
                         job.stitched->platform + "): the printer prints " + job.stitched->gcodeName +
                         " alone and turns the platform itself, so " + modbusOnly +
                         " (an option for a platform driven over Modbus) does not apply: drop it, or slice the job "
                         "for a printer profile with multidir.platform = modbus. Run 'multidir help run'.");
  } else {
    if (!parsed.has("--platform"))
      throw UsageError(
          "multidir run: --platform HOST:PORT is required (the platform's Modbus TCP address, such as "
          "192.168.0.30:502). Run 'multidir help run'.");
    if (!parsed.has("--machine"))
      throw UsageError(
          "multidir run: --machine PROFILE.json is required: the connected platform's machine profile (its angle "
          "range and step, or maximal tilt and forbidden cones; JSON, as 'multidir decompose --profile' reads). The "
          "limits in print-job.json describe the plan, not the platform. Run 'multidir help run'.");
    if (parsed.has("--yes-axes-configured"))
      throw UsageError("multidir run: --yes-axes-configured is for a job whose platform the printer's firmware turns; "
                       "this one's platform is driven over Modbus: drop it. Run 'multidir help run'.");
  }
  const int totalSteps =
      job.stitched ? static_cast<int>(job.stitched->stepEstimateSeconds.size()) : static_cast<int>(job.steps.size());
  const int from = wholeNumber(parsed.value("--from", "1"), "--from", 1, totalSteps);
  // The whole job, before anything connects or moves: the platform's limits and the slicer's G-code checks (a
  // stitched job: its program read once, its axes found and its SHA-256 taken).
  std::vector<std::string> checkedGcode;
  core::MachineSpec platform;
  std::optional<StitchedRun> stitchedRun;
  if (job.stitched) {
    stitchedRun = prepareStitchedRun(job, from);
  } else {
    const std::string platformProfile = parsed.value("--machine", "");
    platform = loadPlatformProfile(platformProfile);
    // The SHA-256 of each step's G-code as checked: the link sends a step only if its file still has it.
    checkedGcode = checkRunJob(job, platform, "--machine " + platformProfile,
                               loadRunPrinterProfile(job, parsed.value("--printer-profile", "")));
  }
  RunLog log(out, err, parsed.value("--log", ""));
  SignalScope signals;

  Devices devices;
  devices.printer = std::move(*link);
  log.line("job " + job.jobFile + ": " + std::to_string(totalSteps) + " steps, " +
           core::machineKindName(job.machine.kind) +
           (job.stitched ? ", one program (" + stitchedRun->remoteName + ") turning the platform with the printer's " +
                               "own axes"
                         : std::string()) +
           (from > 1 ? ", starting at step " + std::to_string(from) : ""));
  if (core::Status c = devices.printer->connect(); !c) {
    log.ending(c.error().describe());
    return kExitRunStopped;
  }
  const hardware::PrinterStatus first = devices.printer->status();
  if (first.busy() || first.firmwareState != "ready") {
    log.ending(devices.printer->name() + " is not ready for a job (job " + hardware::printerJobStateName(first.state) +
               ", firmware " + first.firmwareState + (first.message.empty() ? "" : ": " + first.message) +
               "): let it finish, or cancel or restart it first");
    return kExitRunStopped;
  }
  log.line("connected to " + devices.printer->name() + " (firmware " + first.firmwareState + ")");
  const std::string notStarted = ", before the first step: nothing was printed; run the job again" +
                                 (from > 1 ? " with --from " + std::to_string(from) : std::string()) + " when ready";
  std::vector<hardware::PrintStep> steps;
  std::vector<double> estimates;
  if (job.stitched) {
    // The printer must have the axes the program turns before it starts: a line for an axis it lacks is skipped
    // (Marlin) or ends the job (Klipper) with the platform left where it was.
    try {
      if (!stitchedRun->axes.letters.empty() || !stitchedRun->axes.manualSteppers.empty())
        log.line(checkPrinterHasTheAxes(*devices.printer, stitchedRun->axes, parsed.has("--yes-axes-configured")));
    } catch (const std::runtime_error& e) {
      log.ending(std::string(e.what()) + notStarted);
      return kExitRunStopped;
    }
    devices.positioner = makeFirmwareAxesPositioner(*devices.printer);
    const std::string label = stitchedRun->remoteName + " (steps " + std::to_string(from) + " to " +
                              std::to_string(totalSteps) + ")";
    steps.push_back({hardware::PlatformOrientation::rotary(0.0), label, stitchedRun->uploadPath, stitchedRun->sha256});
    double total = 0.0;
    for (double e : stitchedRun->estimates) total += e;
    estimates.push_back(total);
  } else {
    try {
      connectPlatform(devices, job, platform, platformHost, platformPort, unit, log);
      if (g_interrupts > 0) throw Interrupted(interruptName() + " while connecting the platform");
    } catch (const Interrupted& e) {
      stopBeforeTheRun(devices, log);
      log.ending(std::string("stopped by ") + e.what() + notStarted);
      return kExitRunStopped;
    } catch (const std::runtime_error& e) {
      log.ending(e.what());
      return kExitRunStopped;
    }
    log.line("connected to " + devices.positioner->name());
    for (std::size_t i = static_cast<std::size_t>(from - 1); i < job.steps.size(); ++i) {
      const RunJobStep& s = job.steps[i];
      steps.push_back({s.orientation, "step " + std::to_string(s.index), s.gcodePath, checkedGcode[i]});
      estimates.push_back(s.estimateSeconds);
    }
  }
  hardware::PrintRunOptions options;
  // Nothing settles on a platform the printer's program turns: it stands at rest until the program starts.
  options.settleTime = std::chrono::milliseconds(job.stitched ? 0 : settleMs);
  // The run ends at a pause or fault: the log says so, and the last line says how to go on (no studio buttons).
  options.advice = [](hardware::PrintRunAdvice situation) {
    if (situation == hardware::PrintRunAdvice::EmergencyStop)
      return std::string("use the device's own emergency stop button or cut its power");
    return std::string("multidir run stops here (how to go on follows)");
  };
  hardware::PrintRun run(*devices.positioner, steps, options, devices.printer.get());
  run.setLogCallback([&](const hardware::PrintRunLogEntry& e) {
    log.line(std::string(hardware::printRunStateName(e.state)) + ": " + e.message);
  });
  if (core::Status started = run.start(); !started) {
    log.ending(started.error().describe());
    return kExitRunStopped;
  }

  int handledInterrupts = 0;
  std::string lastProgress;
  auto nextProgress = Clock::now();
  bool stoppedByOperator = false;
  Clock::time_point stopDeadline = Clock::time_point::max();
  Clock::time_point firstInterrupt{};
  bool emergencySent = false;
  constexpr auto kSameInterrupt = 300ms;
  while (true) {
    run.tick();
    // One Ctrl-C may arrive twice (to the process and to its process group, as timeout(1) sends it): signals
    // within kSameInterrupt of the first count as that one.
    const int interrupts = g_interrupts.load();
    if (interrupts > handledInterrupts) {
      const bool first = handledInterrupts == 0;
      const bool second = !first && Clock::now() - firstInterrupt > kSameInterrupt && !emergencySent;
      handledInterrupts = interrupts;
      if (first) {
        stoppedByOperator = true;
        firstInterrupt = Clock::now();
        stopDeadline = firstInterrupt + 10s;
        log.line(interruptName() + ": stopping both devices (press Ctrl-C again for their emergency stops)");
        // abort() cancels the printer's job itself when the run was printing; otherwise the printer is asked
        // here, in case it prints something the run did not start. Then abort() switches the heaters off
        // (queued behind the cancel), whatever the run was doing: a turn between two steps leaves them hot.
        const bool runCancels = run.state() == hardware::PrintRunState::Printing ||
                                (run.state() == hardware::PrintRunState::Paused && run.printInterrupted());
        if (!runCancels && devices.printer->status().busy()) (void)devices.printer->cancelPrint();
        (void)run.abort();
        if (devices.positioner->snapshot().moving) (void)devices.positioner->stopMotion();
      } else if (second) {
        emergencySent = true;
        stopDeadline = Clock::now() + 10s;
        log.line("second stop signal (" + interruptName() + " first): emergency stop of both devices");
        (void)run.emergencyStop();
      }
    }
    const hardware::PrintRunState state = run.state();
    if (state == hardware::PrintRunState::Completed) break;
    if (state == hardware::PrintRunState::Aborted || state == hardware::PrintRunState::Paused ||
        state == hardware::PrintRunState::Faulted) {
      if (!stoppedByOperator) break;
      // After Ctrl-C: wait for the platform's stop and the printer's cancel to take (below), then end.
      if (!run.stopUnconfirmed() && !devices.printer->status().busy()) break;
      if (Clock::now() > stopDeadline) break;
    }
    if (Clock::now() >= nextProgress && state == hardware::PrintRunState::Printing) {
      nextProgress = Clock::now() + 1s;
      const hardware::PrinterStatus p = devices.printer->status();
      const double progress = p.state == hardware::PrinterJobState::Printing ? p.progress : 0.0;
      double remaining = estimates[run.currentStep()] * (1.0 - progress);
      for (std::size_t k = run.currentStep() + 1; k < estimates.size(); ++k) remaining += estimates[k];
      char percent[16];
      std::snprintf(percent, sizeof percent, "%.0f %%", progress * 100.0);
      const int jobStep =
          job.stitched ? stitchedRun->stepAt(progress) : from + static_cast<int>(run.currentStep());
      const std::string text = "progress: step " + std::to_string(jobStep) + "/" + std::to_string(totalSteps) + " " +
                               hardware::printerJobStateName(p.state) + " " +
                               percent + ", extruder " + celsius(p.extruder) + ", bed " + celsius(p.bed) +
                               ", job remaining about " + slicing::durationText(remaining);
      if (text != lastProgress) log.line(lastProgress = text);
    }
    std::this_thread::sleep_for(50ms);
  }
  // Stops asked for are latched by the drivers: give them a bounded time to confirm before disconnecting.
  for (int i = 0; i < 100 && run.stopUnconfirmed(); ++i) {
    std::this_thread::sleep_for(50ms);
    run.tick();
  }
  if (run.stopUnconfirmed()) log.line("warning: a device has not confirmed its stop: check it by hand");
  if (run.state() == hardware::PrintRunState::Completed) {
    log.line("done: " + std::to_string(totalSteps - from + 1) + " steps printed");
    return kExitOk;
  }
  // A stitched program is one printer job: the step it was in follows from how far the printer had read it.
  const std::size_t step = job.stitched ? static_cast<std::size_t>(stitchedRun->stepAt(run.stepProgress()))
                                        : static_cast<std::size_t>(from) + run.currentStep();
  const std::string gcodeName = std::filesystem::path(steps[run.currentStep()].gcodePath).filename().string();
  // After Ctrl-C the run's abort has switched the heaters off already.
  if (!stoppedByOperator) leaveThePrinterSafe(devices, log, gcodeName);
  log.ending("the run stopped at step " + std::to_string(step) + " (" + hardware::printRunStateName(run.state()) +
             (run.lastProblem().empty() ? std::string() : ": " + run.lastProblem()) + ")" +
             (stoppedByOperator ? " by " + interruptName() : std::string()) +
             howToGoOn(run, devices.printer->status(), step, devices.printer->name(),
                       static_cast<std::size_t>(totalSteps), gcodeName, stoppedByOperator) +
             (job.stitched && run.stepBegun()
                  ? ". With --from, the printer gets the program from the transition before that step on: it must "
                    "still be homed, and the platform's axes must stand where the step before it printed (as the "
                    "printer left them)"
                  : std::string()));
  return kExitRunStopped;
}

}  // namespace multidir::cli

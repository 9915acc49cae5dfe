#include "simulate_command.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <memory>
#include <thread>

#include "cli_args.h"
#include "multidir/hardware/device_simulator.h"
#include "multidir/hardware/marlin_simulator.h"
#include "multidir/hardware/moonraker_simulator.h"
#include "multidir/hardware/octoprint_simulator.h"
#include "simulate_ur.h"

namespace multidir::cli {

const char* const kSimulateHelp =
    "Usage: multidir simulate [--rotary] [--robot] [--listen ADDRESS] [--port PORT] [--unit ID]\n"
    "       multidir simulate --printer moonraker|octoprint [--listen ADDRESS] [--port PORT] [--speed X]\n"
    "                         [--fault NAME [--fault-at FRACTION]] [--api-key KEY]\n"
    "                         [--manual-stepper NAME,... (moonraker) | --rotary-axes LETTERS (octoprint)]\n"
    "       multidir simulate --printer marlin [--speed X] [--fault NAME [--fault-at-line N]] [--rotary-axes U,V]\n"
    "       multidir simulate --ur MODEL [--port P] [--speed X] [--fault NAME [--fault-at S | --fault-at-line N]]\n"
    "                         [--cell CELL] [--trace FILE]\n"
    "\n"
    "Runs a Modbus TCP simulator of MultiDir's devices until Ctrl-C: the rotary platform controller and the\n"
    "Universal Robots arm's registers 128-255 with the behaviour of multidir_platform.script (register maps:\n"
    "docs/hardware.md). Point MultiDir's device settings at it to try a print run without hardware. It serves\n"
    "at most 64 clients at once (later ones are closed at once) and disconnects a client whose request does\n"
    "not arrive whole within 1 s.\n"
    "\n"
    "Options:\n"
    "  --rotary          simulate the rotary platform controller (default: both devices)\n"
    "  --robot           simulate the robot arm (default: both devices)\n"
    "  --listen ADDRESS  IPv4 address to listen on (default: 127.0.0.1, this machine only)\n"
    "  --port PORT       TCP port, 0 for a free one (default: 1502; 502 needs root)\n"
    "  --unit ID         unit id of the rotary controller, 0..255 (default: 1); the robot answers all others\n"
    "\n"
    "With --printer moonraker it runs a Klipper printer behind Moonraker's HTTP API instead (the endpoints\n"
    "'multidir run' uses, with Moonraker's reply shapes; docs/hardware.md): uploaded G-code is printed line by\n"
    "line, moves timed by their feed rates and heater waits by the heating rate. With --printer octoprint it\n"
    "runs OctoPrint's REST API in front of a Marlin printer instead; every request needs the API key it prints.\n"
    "  --printer moonraker  simulate a Moonraker printer (default port 7125)\n"
    "  --printer octoprint  simulate an OctoPrint server (default port 5000, OctoPrint's own)\n"
    "  --api-key KEY     the key the OctoPrint simulator expects (default: MULTIDIR-SIMULATED-OCTOPRINT-KEY)\n"
    "  --speed X         simulated seconds per real second, above 0 and at most 100000 (default: 1)\n"
    "  --fault NAME      inject once, when a job first reaches --fault-at: thermal-runaway, link-drop (3 s),\n"
    "                    cancelled-on-printer, slow-replies (3 s each)\n"
    "  --fault-at FRACTION  the job's progress for --fault, 0..1 (default: 0.5)\n"
    "  --manual-stepper NAMES  (moonraker) the printer's [manual_stepper]s, such as tilt,rotation: it runs\n"
    "                    MANUAL_STEPPER STEPPER=NAME [ENABLE=] [SET_POSITION=] [MOVE= SPEED=] for them (a turn\n"
    "                    takes |change| / SPEED), reports each as the object 'manual_stepper NAME', and ends a\n"
    "                    job in error at a MANUAL_STEPPER for a name it lacks, as Klipper does (default: none)\n"
    "  --rotary-axes LETTERS  (octoprint, marlin) rotary axes as G-code letters (of A B C U V W), such as U,V:\n"
    "                    G0/G1/G92 move and set them; a move of them alone takes its length in degrees over F\n"
    "                    (degrees per minute), one with X, Y or Z the XYZ length over F (default: none; a\n"
    "                    letter the printer lacks is skipped, as Marlin does)\n"
    "\n"
    "With --printer marlin it runs a Marlin printer on a pseudo-terminal instead and prints its device path:\n"
    "give it to 'multidir run' as --printer serial:///dev/pts/N. It checks line numbers and checksums (asking\n"
    "for a resend), answers M105 with temperatures, M114 with its position (rotary axes after Z) and M115 with\n"
    "its capabilities (AXIS_COUNT with rotary axes), says busy while M109, M400 or a\n"
    "move waiting for room in its planner hold it up, and halts on M112.\n"
    "  --printer marlin  simulate a Marlin printer over USB serial\n"
    "  --fault NAME      as above, or serial-resend (one line arrives damaged: the printer asks for it again);\n"
    "                    injected once, when the printer has received --fault-at-line lines (default: 100)\n"
    "\n"
    "With --ur MODEL (ur3 ur5 ur10 ur3e ur5e ur10e ur16e) it runs a Universal Robots controller instead, the\n"
    "interfaces MultiDir's robot cell uses in UR's formats (docs/hardware.md, \"UR controller\"): the dashboard\n"
    "server on P, the secondary interface (URScript programs; MultiDir's subset) on P+1, the real-time state\n"
    "on P+2, RTDE (the output integer registers) on P+3 (without --port UR's own 29999, 30002, 30003 and\n"
    "30004; --port 0 picks four free ones). The arm moves by\n"
    "the model's kinematics at the programs' a and v; a joint limit is a protective stop. Give it to\n"
    "'multidir run OUT --robot 127.0.0.1:P'.\n"
    "  --ur MODEL        simulate this arm\n"
    "  --cell CELL       the robot cell's file: the arm gets its joint limits and starts at its home\n"
    "  --fault NAME      inject once: protective-stop, emergency-stop, link-drop (3 s), program-error, at\n"
    "  --fault-at S      S simulated seconds after the first program started (default: 5), or\n"
    "  --fault-at-line N when a program reaches line N\n"
    "  --trace FILE      write every tick a program runs or the arm moves as CSV: time, joints, TCP pose (mm,\n"
    "                    rotation vector), analog out 0 (extruder) and 1 (nozzle set point), nozzle C, program\n"
    "  -h, --help        show this help\n"
    "\n"
    "Exit codes: 0 stopped by Ctrl-C, 1 cannot listen on the address and port, 2 usage error.\n";

namespace {

std::atomic<bool> g_stopRequested{false};

extern "C" void onStopSignal(int) { g_stopRequested = true; }

int wholeNumber(const std::string& text, const std::string& option, int low, int high) {
  const double value = parseNumber(text, option);
  if (value != std::floor(value) || value < low || value > high)
    throw UsageError("multidir simulate: " + option + " must be a whole number from " + std::to_string(low) + " to " +
                     std::to_string(high) + ", not '" + text + "'. Run 'multidir help simulate'.");
  return static_cast<int>(value);
}

bool isLoopback(const std::string& address) { return address.rfind("127.", 0) == 0; }

std::string rotaryLine(const hardware::SimulatedRotaryState& s) {
  char text[160];
  std::snprintf(text, sizeof text, "rotary: %s%s%s, angle %.2f deg, target %.2f deg, fault %d",
                s.enabled ? "enabled" : "disabled", s.homed ? ", homed" : (s.homing ? ", homing" : ", not homed"),
                s.moving ? ", moving" : "", s.angleDegrees, s.targetAngleDegrees, s.faultCode);
  return text;
}

std::string robotLine(const hardware::SimulatedRobotState& s) {
  static const char* const kStates[] = {"not running", "idle", "moving", "reached", "stopped", "halted", "fault"};
  const char* state = s.programState >= 0 && s.programState <= 6 ? kStates[s.programState] : "?";
  char text[160];
  std::snprintf(text, sizeof text, "robot: %s, tilt %.2f deg, azimuth %.2f deg, fault %d, command %u", state,
                s.tiltDegrees, s.azimuthDegrees, s.faultCode, static_cast<unsigned>(s.acknowledgedSequence));
  return text;
}

}  // namespace

namespace {

int simulateMarlin(const ParsedArgs& parsed, std::ostream& out, std::ostream& err) {
  for (const char* networkOnly : {"--listen", "--port", "--fault-at", "--api-key"})
    if (parsed.has(networkOnly))
      throw UsageError(std::string("multidir simulate: ") + networkOnly +
                       " is not for --printer marlin (a serial printer on a pseudo-terminal). Run 'multidir help "
                       "simulate'.");
  hardware::MarlinSimulatorOptions options;
  if (parsed.has("--manual-stepper"))
    throw UsageError(
        "multidir simulate: --manual-stepper is Klipper's (--printer moonraker); Marlin's rotary axes are letters: "
        "--rotary-axes U,V. Run 'multidir help simulate'.");
  options.rotaryAxes.letters = hardware::splitAxisList(parsed.value("--rotary-axes", ""));
  options.speed = parseNumber(parsed.value("--speed", "1"), "--speed");
  if (!(options.speed > 0.0) || options.speed > 100000.0)
    throw UsageError("multidir simulate: --speed must be above 0 and at most 100000. Run 'multidir help simulate'.");
  const std::string faultName = parsed.value("--fault", "none");
  const bool serialResend = faultName == "serial-resend";
  hardware::PrinterFault fault = hardware::PrinterFault::None;
  if (!serialResend) {
    core::Result<hardware::PrinterFault> parsedFault = hardware::parsePrinterFault(faultName);
    if (!parsedFault)
      throw UsageError("multidir simulate: " + parsedFault.error().describe() +
                       " (or serial-resend). Run 'multidir help simulate'.");
    fault = *parsedFault;
  }
  const int faultAtLine = wholeNumber(parsed.value("--fault-at-line", "100"), "--fault-at-line", 0, 100000000);
  const bool faulting = serialResend || fault != hardware::PrinterFault::None;

  g_stopRequested = false;
  auto previousInt = std::signal(SIGINT, onStopSignal);
  auto previousTerm = std::signal(SIGTERM, onStopSignal);
  hardware::MarlinSimulator simulator(options);
  const core::Status started = simulator.start();
  if (!started.ok()) {
    std::signal(SIGINT, previousInt);
    std::signal(SIGTERM, previousTerm);
    err << "multidir simulate: " << started.error().describe() << "\n";
    return kExitBadInput;
  }
  out << "Printer simulator (Marlin) on " << simulator.devicePath() << " at speed " << options.speed
      << (faulting ? ", fault " + faultName + " at line " + std::to_string(faultAtLine) : std::string())
      << ". Use --printer serial://" << simulator.devicePath() << ". Ctrl-C stops it.\n"
      << std::flush;
  std::string last;
  bool injected = false;
  auto restoreAt = std::chrono::steady_clock::time_point::max();
  while (!g_stopRequested) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    const std::size_t lines = simulator.received().size();
    if (faulting && !injected && lines >= static_cast<std::size_t>(faultAtLine)) {
      injected = true;
      out << "injecting " << faultName << "\n";
      if (serialResend) simulator.corruptNextLines(1);
      if (fault == hardware::PrinterFault::ThermalRunaway) simulator.injectThermalRunaway();
      if (fault == hardware::PrinterFault::CancelledOnPrinter) simulator.cancelJobOnPrinter();
      if (fault == hardware::PrinterFault::SlowReplies) simulator.setReplyDelay(std::chrono::milliseconds(3000));
      if (fault == hardware::PrinterFault::LinkDrop) {
        simulator.dropLink();
        restoreAt = std::chrono::steady_clock::now() + std::chrono::seconds(3);
      }
    }
    if (std::chrono::steady_clock::now() >= restoreAt) {
      simulator.restoreLink();
      restoreAt = std::chrono::steady_clock::time_point::max();
    }
    const hardware::MarlinSimulatorState s = simulator.state();
    char text[256];
    std::snprintf(text, sizeof text, "printer: %s, line %ld, %zu moves queued, extruder %.0f/%.0f C, bed %.0f/%.0f C",
                  s.halted ? ("halted: " + s.haltReason).c_str() : "running", s.lastLineNumber, s.queuedMoves,
                  s.extruder.actualC, s.extruder.targetC, s.bed.actualC, s.bed.targetC);
    if (text != last) out << (last = text) << "\n" << std::flush;
  }
  std::signal(SIGINT, previousInt);
  std::signal(SIGTERM, previousTerm);
  simulator.stop();
  out << "Simulator stopped.\n";
  return kExitOk;
}

int simulatePrinter(const ParsedArgs& parsed, std::ostream& out, std::ostream& err) {
  const std::string kind = parsed.value("--printer", "");
  if (kind == "marlin") return simulateMarlin(parsed, out, err);
  if (parsed.has("--fault-at-line"))
    throw UsageError("multidir simulate: --fault-at-line is for --printer marlin. Run 'multidir help simulate'.");
  const bool octoPrint = kind == "octoprint";
  if (kind != "moonraker" && !octoPrint)
    throw UsageError("multidir simulate: --printer '" + kind +
                     "' is not simulated: this version simulates 'moonraker' (Klipper), 'octoprint' and 'marlin'. "
                     "Run 'multidir help simulate'.");
  for (const char* modbusOnly : {"--rotary", "--robot", "--unit"})
    if (parsed.has(modbusOnly))
      throw UsageError(std::string("multidir simulate: ") + modbusOnly +
                       " is for the Modbus simulator, not with --printer. Run 'multidir help simulate'.");
  if (parsed.has("--api-key") && !octoPrint)
    throw UsageError("multidir simulate: --api-key is for --printer octoprint. Run 'multidir help simulate'.");
  hardware::OctoPrintSimulatorOptions options;  // Moonraker's are the shared part
  options.listenAddress = parsed.value("--listen", "127.0.0.1");
  options.port = wholeNumber(parsed.value("--port", octoPrint ? "5000" : "7125"), "--port", 0, 65535);
  options.speed = parseNumber(parsed.value("--speed", "1"), "--speed");
  if (!(options.speed > 0.0) || options.speed > 100000.0)
    throw UsageError("multidir simulate: --speed must be above 0 and at most 100000. Run 'multidir help simulate'.");
  if (parsed.has("--fault")) {
    core::Result<hardware::PrinterFault> fault = hardware::parsePrinterFault(parsed.value("--fault", ""));
    if (!fault) throw UsageError("multidir simulate: " + fault.error().describe() + ". Run 'multidir help simulate'.");
    options.fault = *fault;
  }
  options.faultAtProgress = parseNumber(parsed.value("--fault-at", "0.5"), "--fault-at");
  if (!(options.faultAtProgress >= 0.0) || options.faultAtProgress > 1.0)
    throw UsageError("multidir simulate: --fault-at must be between 0 and 1. Run 'multidir help simulate'.");
  options.apiKey = parsed.value("--api-key", hardware::kOctoPrintSimulatorApiKey);
  if (octoPrint && parsed.has("--manual-stepper"))
    throw UsageError(
        "multidir simulate: --manual-stepper is Klipper's (--printer moonraker); the printer behind OctoPrint is a "
        "Marlin, whose rotary axes are letters: --rotary-axes U,V. Run 'multidir help simulate'.");
  if (!octoPrint && parsed.has("--rotary-axes"))
    throw UsageError(
        "multidir simulate: Klipper's G1 moves X, Y, Z and E only; its rotary axes are manual steppers: "
        "--manual-stepper tilt,rotation. Run 'multidir help simulate'.");
  options.rotaryAxes.letters = hardware::splitAxisList(parsed.value("--rotary-axes", ""));
  options.rotaryAxes.manualSteppers = hardware::splitAxisList(parsed.value("--manual-stepper", ""));
  if (options.apiKey.empty())
    throw UsageError("multidir simulate: --api-key must not be empty. Run 'multidir help simulate'.");

  g_stopRequested = false;
  auto previousInt = std::signal(SIGINT, onStopSignal);
  auto previousTerm = std::signal(SIGTERM, onStopSignal);
  std::unique_ptr<hardware::PrinterSimulator> simulator;
  if (octoPrint)
    simulator = std::make_unique<hardware::OctoPrintSimulator>(options);
  else
    simulator = std::make_unique<hardware::MoonrakerSimulator>(options);
  const core::Status started = simulator->start();
  if (!started.ok()) {
    std::signal(SIGINT, previousInt);
    std::signal(SIGTERM, previousTerm);
    err << "multidir simulate: " << started.error().describe() << "\n";
    return kExitBadInput;
  }
  if (!isLoopback(options.listenAddress))
    err << "multidir simulate: warning: listening on " << options.listenAddress
        << ", reachable from other machines on that network\n";
  out << "Printer simulator (" << (octoPrint ? "OctoPrint, Marlin" : "Moonraker, Klipper") << ") listening on http://"
      << simulator->address() << " at speed " << options.speed
      << (options.fault != hardware::PrinterFault::None
              ? std::string(", fault ") + hardware::printerFaultName(options.fault) + " at " +
                    std::to_string(static_cast<int>(options.faultAtProgress * 100)) + " %"
              : std::string())
      << ". Ctrl-C stops it.\n";
  if (octoPrint)
    out << "API key: " << options.apiKey << " (multidir run JOB --printer octoprint://" << simulator->address()
        << " --api-key " << options.apiKey << " ...)\n";
  out << std::flush;
  std::string last;
  while (!g_stopRequested) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    const hardware::SimulatedPrinterState s = simulator->state();
    char text[256];
    std::snprintf(text, sizeof text, "printer: %s, job %s%s%s, %d %%, extruder %.0f/%.0f C, bed %.0f/%.0f C",
                  s.firmwareState.c_str(), s.jobState.c_str(), s.file.empty() ? "" : " ", s.file.c_str(),
                  static_cast<int>(std::floor(s.progress * 10.0)) * 10, s.extruder.actualC, s.extruder.targetC,
                  s.bed.actualC, s.bed.targetC);
    if (text != last) out << (last = text) << "\n" << std::flush;
  }
  std::signal(SIGINT, previousInt);
  std::signal(SIGTERM, previousTerm);
  simulator->stop();
  out << "Simulator stopped.\n";
  return kExitOk;
}

}  // namespace

int runSimulate(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const ParsedArgs parsed = parseArgs(
      args,
      {"--listen", "--port", "--unit", "--printer", "--speed", "--fault", "--fault-at", "--fault-at-line", "--api-key",
       "--rotary-axes", "--manual-stepper", "--ur", "--trace", "--cell"},
      {"--rotary", "--robot", "--help"}, "simulate");
  if (parsed.has("--help")) {
    out << kSimulateHelp;
    return kExitOk;
  }
  if (!parsed.positionals.empty())
    throw UsageError("multidir simulate: unexpected argument '" + parsed.positionals[0] +
                     "'. Run 'multidir help simulate'.");
  if (parsed.has("--ur")) return simulateUr(parsed, out, err);
  for (const char* urOnly : {"--trace", "--cell"})
    if (parsed.has(urOnly))
      throw UsageError(std::string("multidir simulate: ") + urOnly + " is for --ur MODEL. Run 'multidir help simulate'.");
  if (parsed.has("--printer")) return simulatePrinter(parsed, out, err);
  for (const char* printerOnly :
       {"--speed", "--fault", "--fault-at", "--fault-at-line", "--api-key", "--rotary-axes", "--manual-stepper"})
    if (parsed.has(printerOnly))
      throw UsageError(std::string("multidir simulate: ") + printerOnly +
                       " is for the printer simulator: add --printer moonraker, octoprint or marlin. Run "
                       "'multidir help simulate'.");
  hardware::SimulatorOptions options;
  const bool rotary = parsed.has("--rotary");
  const bool robot = parsed.has("--robot");
  options.rotary = rotary || !robot;
  options.robot = robot || !rotary;
  options.listenAddress = parsed.value("--listen", "127.0.0.1");
  options.port = wholeNumber(parsed.value("--port", "1502"), "--port", 0, 65535);
  options.rotaryUnitId = wholeNumber(parsed.value("--unit", "1"), "--unit", 0, 255);

  // Handlers first, so that a Ctrl-C right after start-up still stops the simulator cleanly.
  g_stopRequested = false;
  auto previousInt = std::signal(SIGINT, onStopSignal);
  auto previousTerm = std::signal(SIGTERM, onStopSignal);
  hardware::DeviceSimulator simulator(options);
  const core::Status started = simulator.start();
  if (!started.ok()) {
    std::signal(SIGINT, previousInt);
    std::signal(SIGTERM, previousTerm);
    if (started.error().code == core::ErrorCode::InvalidParameter)
      throw UsageError("multidir simulate: " + started.error().describe() + ". Run 'multidir help simulate'.");
    err << "multidir simulate: " << started.error().describe() << "\n";
    return kExitBadInput;
  }
  if (!isLoopback(options.listenAddress))
    err << "multidir simulate: warning: listening on " << options.listenAddress
        << ", reachable from other machines on that network\n";
  out << "Simulator listening on " << simulator.address() << ":";
  if (options.rotary) out << " rotary platform controller (unit " << options.rotaryUnitId << ")";
  if (options.rotary && options.robot) out << ",";
  if (options.robot) out << " robot arm registers 128-255 (" << (options.rotary ? "other units" : "any unit") << ")";
  out << ". Ctrl-C stops it.\n" << std::flush;

  int connections = 0;
  std::string lastRotary;
  std::string lastRobot;
  while (!g_stopRequested) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    const int nowConnected = simulator.connectionCount();
    if (nowConnected != connections) {
      connections = nowConnected;
      out << "clients connected: " << connections << "\n";
    }
    if (options.rotary) {
      const std::string line = rotaryLine(simulator.rotaryState());
      if (line != lastRotary) out << (lastRotary = line) << "\n";
    }
    if (options.robot) {
      const std::string line = robotLine(simulator.robotState());
      if (line != lastRobot) out << (lastRobot = line) << "\n";
    }
    out << std::flush;
  }
  std::signal(SIGINT, previousInt);
  std::signal(SIGTERM, previousTerm);
  simulator.stop();
  out << "Simulator stopped.\n";
  return kExitOk;
}

}  // namespace multidir::cli

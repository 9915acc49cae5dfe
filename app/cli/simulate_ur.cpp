#include "simulate_ur.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <thread>

#include "multidir/hardware/ur_simulator.h"

namespace multidir::cli {
namespace {

std::atomic<bool> g_stop{false};
extern "C" void onUrStopSignal(int) { g_stop = true; }

int wholeNumber(const std::string& text, const std::string& option, long low, long high) {
  const double value = parseNumber(text, option);
  if (value != std::floor(value) || value < static_cast<double>(low) || value > static_cast<double>(high))
    throw UsageError("multidir simulate: " + option + " must be a whole number from " + std::to_string(low) + " to " +
                     std::to_string(high) + ", not '" + text + "'. Run 'multidir help simulate'.");
  return static_cast<int>(value);
}

// A port the system hands out as free now (the base of four consecutive ones is tried from it).
int freePort() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  inet_pton(AF_INET, "127.0.0.1", &address.sin_addr);
  int port = 0;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
    socklen_t length = sizeof address;
    getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
    port = ntohs(address.sin_port);
  }
  ::close(fd);
  return port;
}

}  // namespace

int simulateUr(const ParsedArgs& parsed, std::ostream& out, std::ostream& err) {
  for (const char* other :
       {"--printer", "--rotary", "--robot", "--unit", "--api-key", "--rotary-axes", "--manual-stepper"})
    if (parsed.has(other))
      throw UsageError(std::string("multidir simulate: ") + other +
                       " is not for --ur (a Universal Robots controller). Run 'multidir help simulate'.");
  hardware::UrSimulatorOptions options;
  options.model = parsed.value("--ur", "");
  options.listenAddress = parsed.value("--listen", "127.0.0.1");
  options.speed = parseNumber(parsed.value("--speed", "1"), "--speed");
  if (!(options.speed > 0.0) || options.speed > 100000.0)
    throw UsageError("multidir simulate: --speed must be above 0 and at most 100000. Run 'multidir help simulate'.");
  options.tracePath = parsed.value("--trace", "");
  options.cellPath = parsed.value("--cell", "");
  if (parsed.has("--fault")) {
    core::Result<hardware::UrSimulatorFault> fault = hardware::parseUrSimulatorFault(parsed.value("--fault", ""));
    if (!fault) throw UsageError("multidir simulate: " + fault.error().describe() + ". Run 'multidir help simulate'.");
    options.fault = *fault;
    if (parsed.has("--fault-at-line"))
      options.faultAtLine = wholeNumber(parsed.value("--fault-at-line", ""), "--fault-at-line", 1, 100000000);
    else
      options.faultAtSeconds = parseNumber(parsed.value("--fault-at", "5"), "--fault-at");
    if (!parsed.has("--fault-at-line") && !(options.faultAtSeconds >= 0.0))
      throw UsageError(
          "multidir simulate: --fault-at (seconds after the first program started) must not be "
          "negative. Run 'multidir help simulate'.");
  } else if (parsed.has("--fault-at") || parsed.has("--fault-at-line")) {
    throw UsageError(
        "multidir simulate: --fault-at and --fault-at-line need --fault NAME. Run 'multidir help "
        "simulate'.");
  }
  const bool portGiven = parsed.has("--port");
  const int port = portGiven ? wholeNumber(parsed.value("--port", ""), "--port", 0, 65532) : -1;

  g_stop = false;
  auto previousInt = std::signal(SIGINT, onUrStopSignal);
  auto previousTerm = std::signal(SIGTERM, onUrStopSignal);
  const auto restore = [&] {
    std::signal(SIGINT, previousInt);
    std::signal(SIGTERM, previousTerm);
  };
  std::unique_ptr<hardware::UrSimulator> simulator;
  core::Status started = core::Done{};
  // --port 0: four consecutive free ports, so that 'multidir run --robot HOST:P' finds P+1, P+2 and P+3.
  for (int attempt = 0; attempt < (port == 0 ? 50 : 1); ++attempt) {
    const int base = port == 0 ? freePort() : port;
    if (port == 0 && (base <= 0 || base > 65532)) continue;
    options.dashboardPort = portGiven ? base : 29999;
    options.secondaryPort = portGiven ? base + 1 : 30002;
    options.realtimePort = portGiven ? base + 2 : 30003;
    options.rtdePort = portGiven ? base + 3 : 30004;
    simulator = std::make_unique<hardware::UrSimulator>(options);
    started = simulator->start();
    if (started.ok()) break;
  }
  if (!started.ok()) {
    restore();
    if (started.error().code == core::ErrorCode::InvalidParameter)
      throw UsageError("multidir simulate: " + started.error().describe() + ". Run 'multidir help simulate'.");
    err << "multidir simulate: " << started.error().describe() << "\n";
    return kExitBadInput;
  }
  out << "UR controller simulator (" << options.model << ") on " << options.listenAddress << ": dashboard "
      << simulator->dashboardPort() << ", secondary interface " << simulator->secondaryPort()
      << ", real-time interface " << simulator->realtimePort() << ", RTDE " << simulator->rtdePort() << ", at speed "
      << options.speed;
  if (options.fault != hardware::UrSimulatorFault::None)
    out << ", fault " << hardware::urSimulatorFaultName(options.fault)
        << (options.faultAtLine > 0 ? " at line " + std::to_string(options.faultAtLine)
                                    : " " + std::to_string(options.faultAtSeconds) + " s after the first program");
  if (!options.cellPath.empty()) out << ", the joint limits and home of " << options.cellPath;
  if (!options.tracePath.empty()) out << ", trace " << options.tracePath;
  out << ". Use 'multidir run OUT --robot " << options.listenAddress << ":" << simulator->dashboardPort()
      << "'. Ctrl-C stops it.\n"
      << std::flush;
  std::string last;
  while (!g_stop) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    const hardware::UrSimulatorState s = simulator->state();
    std::string line = "robot: " + s.robotMode + ", safety " + s.safetyMode + ", program " + s.programState +
                       (s.programName.empty() ? std::string() : " " + s.programName) + ", programs finished " +
                       std::to_string(s.programsFinished) + (s.linkDropped ? ", link dropped" : "") +
                       (s.lastFault.empty() ? std::string() : ", last fault: " + s.lastFault);
    if (line != last) out << (last = line) << "\n" << std::flush;
  }
  restore();
  simulator->stop();
  out << "Simulator stopped.\n";
  return kExitOk;
}

}  // namespace multidir::cli

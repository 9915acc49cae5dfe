#pragma once
// Shared by the printer tests: a short G-code program, fast links to each protocol's simulator (Moonraker and
// OctoPrint on 127.0.0.1, Marlin on a pseudo-terminal), and one interface over all three simulators
// (SimulatedPrinterUnderTest), so that one test runs against every protocol (TEST_P over PrinterProtocol).
#include <algorithm>
#include <chrono>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "hardware_test_support.h"
#include "multidir/hardware/marlin_link.h"
#include "multidir/hardware/marlin_simulator.h"
#include "multidir/hardware/moonraker_link.h"
#include "multidir/hardware/moonraker_simulator.h"
#include "multidir/hardware/octoprint_link.h"
#include "multidir/hardware/octoprint_simulator.h"

namespace multidir::hardware::test {

// Heats the extruder to 200 C (about 18 s at the simulator's 10 C/s), then prints 20 moves of 10 mm at
// 1200 mm/min (10 s): about 28 simulated seconds.
inline std::string shortGcode() {
  std::string text = "; test program\nM104 S200\nM109 S200\nG90\nM83\nG1 X0 Y0 Z0.3 F1200\n";
  for (int i = 0; i < 20; ++i) text += "G1 X" + std::to_string((i + 1) % 2 * 10) + " Y" + std::to_string(i) + " E0.5\n";
  text += "M104 S0\n";
  return text;
}

// shortGcode() as a step of a multi-step job leaves it: the bed at 60 C and the extruder at 200 C at its end,
// for the next step (as robot-0.8.ini's end G-code leaves the bed on).
inline std::string heatersLeftOnGcode() {
  std::string text = "M140 S60\nM104 S200\nM109 S200\nG90\nM83\nG1 X0 Y0 Z0.3 F1200\n";
  for (int i = 0; i < 20; ++i) text += "G1 X" + std::to_string((i + 1) % 2 * 10) + " Y" + std::to_string(i) + " E0.5\n";
  return text;
}

inline std::string writeFile(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

// The running test's own folder name ("Suite_Name_Param"): ctest runs tests as processes side by side, and a
// file they shared was truncated by one while another uploaded it (the printer then ran an empty job).
inline std::string runningTestFolder() {
  const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info == nullptr ? "no-test" : std::string(info->test_suite_name()) + "_" + info->name();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// shortGcode() written as `folder`/step-01.gcode in the running test's own temporary folder; its path.
inline std::string shortGcodeFile(const std::string& folder) {
  return writeFile(std::filesystem::path(testing::TempDir()) / runningTestFolder() / folder / "step-01.gcode",
                   shortGcode());
}

// The commands of a G-code text as a printer receives them (comments and blank lines dropped).
inline std::vector<std::string> gcodeCommands(const std::string& text) {
  std::vector<std::string> commands;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(begin, end - begin);
    begin = end + 1;
    if (const std::size_t semicolon = line.find(';'); semicolon != std::string::npos) line.resize(semicolon);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    if (!line.empty()) commands.push_back(line);
  }
  return commands;
}

inline PrinterLinkOptions fastPrinterOptions() {
  PrinterLinkOptions options;
  options.pollInterval = 10ms;
  options.requestTimeout = 1000ms;
  options.uploadTimeout = 2000ms;
  options.linkLostAfter = 400ms;
  options.stopRetryInterval = 20ms;
  return options;
}

// The Marlin simulator's options for tests: its busy keepalive often enough to keep a fast link (400 ms)
// alive through long heater waits.
inline MarlinSimulatorOptions fastMarlinSimulatorOptions(double speed) {
  MarlinSimulatorOptions options;
  options.speed = speed;
  options.busyInterval = 50ms;
  return options;
}

// The links, with the test's checks that they could be made.
inline std::unique_ptr<PrinterLink> checkedLink(core::Result<std::unique_ptr<PrinterLink>> link) {
  EXPECT_TRUE(link.ok()) << (link.ok() ? "" : link.error().describe());
  return link.ok() ? std::move(link.value()) : nullptr;
}

inline std::unique_ptr<PrinterLink> moonrakerLinkTo(int port, PrinterLinkOptions options = fastPrinterOptions()) {
  MoonrakerSettings settings;
  settings.host = "127.0.0.1";
  settings.port = port;
  return checkedLink(makeMoonrakerLink(settings, options));
}

inline std::unique_ptr<PrinterLink> octoPrintLinkTo(int port, const std::string& apiKey = kOctoPrintSimulatorApiKey,
                                                    PrinterLinkOptions options = fastPrinterOptions()) {
  OctoPrintSettings settings;
  settings.host = "127.0.0.1";
  settings.port = port;
  settings.apiKey = apiKey;
  return checkedLink(makeOctoPrintLink(settings, options));
}

inline std::unique_ptr<PrinterLink> marlinLinkTo(const std::string& devicePath,
                                                 PrinterLinkOptions options = fastPrinterOptions(), int window = 1) {
  MarlinSettings settings;
  settings.devicePath = devicePath;
  settings.maxUnacknowledgedLines = window;
  return checkedLink(makeMarlinLink(settings, options));
}

// `link`, connected (the test fails, and goes on, when it could not be).
inline std::unique_ptr<PrinterLink> connectedLink(std::unique_ptr<PrinterLink> link) {
  const core::Status status = link->connect();
  EXPECT_TRUE(status.ok()) << messageOf(status);
  return link;
}

// Uploads `gcodePath` as step-01.gcode and starts it; true once the printer accepted both.
inline bool uploadedAndStarted(PrinterLink& link, const std::string& gcodePath) {
  return outcome(link.upload(gcodePath, "step-01.gcode")).ok() && outcome(link.startPrint("step-01.gcode")).ok();
}

// What connect() reads from an idle simulator, whatever the protocol.
inline void expectConnectedAndIdle(const PrinterStatus& s) {
  EXPECT_EQ(s.link, LinkState::Connected);
  EXPECT_FALSE(s.linkLost);
  EXPECT_EQ(s.state, PrinterJobState::Standby);
  EXPECT_EQ(s.firmwareState, "ready");
  EXPECT_NEAR(s.extruder.actualC, 22.0, 1e-9);
}

enum class PrinterProtocol { Moonraker, OctoPrint, Marlin };

inline const char* protocolText(PrinterProtocol protocol) {
  switch (protocol) {
    case PrinterProtocol::Moonraker:
      return "Moonraker";
    case PrinterProtocol::OctoPrint:
      return "OctoPrint";
    case PrinterProtocol::Marlin:
      return "Marlin";
  }
  return "?";
}
inline std::string protocolName(const testing::TestParamInfo<PrinterProtocol>& info) {
  return protocolText(info.param);
}
// How GoogleTest prints the parameter (test lists, ctest names).
inline void PrintTo(PrinterProtocol protocol, std::ostream* out) { *out << protocolText(protocol); }

// The protocols behind an HTTP server (PrinterSimulator: uploads, requests), and all of them.
inline auto httpProtocols() { return ::testing::Values(PrinterProtocol::Moonraker, PrinterProtocol::OctoPrint); }
inline auto allProtocols() {
  return ::testing::Values(PrinterProtocol::Moonraker, PrinterProtocol::OctoPrint, PrinterProtocol::Marlin);
}

// An HTTP protocol's simulator (Marlin has no HTTP server: see SimulatedMarlin).
inline std::unique_ptr<PrinterSimulator> printerSimulator(PrinterProtocol protocol, PrinterSimulatorOptions options) {
  EXPECT_NE(protocol, PrinterProtocol::Marlin) << "Marlin's simulator is not an HTTP PrinterSimulator";
  if (protocol == PrinterProtocol::Moonraker) return std::make_unique<MoonrakerSimulator>(options);
  OctoPrintSimulatorOptions octoPrint;
  static_cast<PrinterSimulatorOptions&>(octoPrint) = options;
  return std::make_unique<OctoPrintSimulator>(octoPrint);
}

inline std::unique_ptr<PrinterLink> printerLinkTo(PrinterProtocol protocol, int port,
                                                  PrinterLinkOptions options = fastPrinterOptions()) {
  EXPECT_NE(protocol, PrinterProtocol::Marlin) << "Marlin's link takes a device path: marlinLinkTo";
  return protocol == PrinterProtocol::Moonraker ? moonrakerLinkTo(port, options)
                                                : octoPrintLinkTo(port, kOctoPrintSimulatorApiKey, options);
}

// An HTTP protocol's requests as the simulators record them.
inline bool isUpload(PrinterProtocol protocol, const PrinterRequestRecord& r) {
  return r.method == "POST" &&
         r.path == (protocol == PrinterProtocol::Moonraker ? "/server/files/upload" : "/api/files/local");
}
inline bool isStart(PrinterProtocol protocol, const PrinterRequestRecord& r) {
  if (protocol == PrinterProtocol::Moonraker) return r.path == "/printer/print/start";
  return r.method == "POST" && r.path.rfind("/api/files/local/", 0) == 0;
}
inline bool isEmergencyStop(PrinterProtocol protocol, const PrinterRequestRecord& r) {
  if (protocol == PrinterProtocol::Moonraker) return r.path == "/printer/emergency_stop";
  return r.path == "/api/printer/command" && r.detail.find("M112") != std::string::npos;
}
inline int countRequests(const std::vector<PrinterRequestRecord>& records,
                         const std::function<bool(const PrinterRequestRecord&)>& which) {
  return static_cast<int>(std::count_if(records.begin(), records.end(), which));
}

// A printer simulator and its link, whatever the protocol, for tests that hold for every printer: the faults
// each simulator injects, and its records read as job intervals, starts and emergency stops on the test's clock.
class SimulatedPrinterUnderTest {
 public:
  using Clock = std::chrono::steady_clock;
  struct JobInterval {
    Clock::time_point from;  // the job began printing
    Clock::time_point to;    // it ended (Clock::time_point::max() while it still prints)
  };
  virtual ~SimulatedPrinterUnderTest() = default;
  [[nodiscard]] virtual std::unique_ptr<PrinterLink> link(PrinterLinkOptions options) const = 0;
  virtual void injectThermalRunaway() = 0;
  virtual void cancelJobOnPrinter() = 0;
  virtual void dropLink() = 0;
  virtual void restoreLink() = 0;
  virtual void setReplyDelay(std::chrono::milliseconds delay) = 0;
  [[nodiscard]] virtual std::vector<JobInterval> jobs() const = 0;
  [[nodiscard]] virtual std::vector<Clock::time_point> starts() const = 0;  // each job's start reached the printer
  [[nodiscard]] virtual std::vector<Clock::time_point> emergencyStops() const = 0;
  [[nodiscard]] virtual int completedJobs() const = 0;
  [[nodiscard]] virtual bool printingPastHeating() const = 0;  // the current job's moves have begun
  [[nodiscard]] virtual bool halted() const = 0;               // by its emergency stop (or a fault)
  [[nodiscard]] virtual HeaterReading extruder() const = 0;    // the simulated printer's, now
  [[nodiscard]] virtual HeaterReading bed() const = 0;
};

// Moonraker and OctoPrint: one HTTP PrinterSimulator each, the same records; only their paths differ.
class SimulatedHttpPrinter : public SimulatedPrinterUnderTest {
 public:
  SimulatedHttpPrinter(PrinterProtocol protocol, PrinterSimulatorOptions options)
      : m_protocol(protocol), m_sim(printerSimulator(protocol, std::move(options))) {
    EXPECT_TRUE(m_sim->start().ok());
  }
  std::unique_ptr<PrinterLink> link(PrinterLinkOptions options) const override {
    return printerLinkTo(m_protocol, m_sim->port(), std::move(options));
  }
  void injectThermalRunaway() override { m_sim->injectThermalRunaway(); }
  void cancelJobOnPrinter() override { m_sim->cancelJobOnPrinter(); }
  void dropLink() override { m_sim->dropLink(); }
  void restoreLink() override { m_sim->restoreLink(); }
  void setReplyDelay(std::chrono::milliseconds delay) override { m_sim->setReplyDelay(delay); }
  std::vector<JobInterval> jobs() const override {
    const auto events = m_sim->jobEvents();
    std::vector<JobInterval> out;
    for (std::size_t i = 0; i < events.size(); ++i)
      if (events[i].state == "printing")
        out.push_back({events[i].at, i + 1 < events.size() ? events[i + 1].at : Clock::time_point::max()});
    return out;
  }
  std::vector<Clock::time_point> starts() const override {
    return requestTimes([&](const PrinterRequestRecord& r) { return isStart(m_protocol, r); });
  }
  std::vector<Clock::time_point> emergencyStops() const override {
    return requestTimes([&](const PrinterRequestRecord& r) { return isEmergencyStop(m_protocol, r); });
  }
  int completedJobs() const override {
    const auto events = m_sim->jobEvents();
    return static_cast<int>(
        std::count_if(events.begin(), events.end(), [](const PrinterJobEvent& e) { return e.state == "complete"; }));
  }
  bool printingPastHeating() const override {
    const SimulatedPrinterState s = m_sim->state();
    return s.jobState == "printing" && s.progress > 0.1;
  }
  bool halted() const override { return m_sim->state().firmwareState == "shutdown"; }
  HeaterReading extruder() const override { return m_sim->state().extruder; }
  HeaterReading bed() const override { return m_sim->state().bed; }

 private:
  std::vector<Clock::time_point> requestTimes(const std::function<bool(const PrinterRequestRecord&)>& which) const {
    std::vector<Clock::time_point> out;
    for (const auto& r : m_sim->requests())
      if (which(r)) out.push_back(r.at);
    return out;
  }
  PrinterProtocol m_protocol;
  std::unique_ptr<PrinterSimulator> m_sim;
};

// Marlin has no jobs of its own: a job is the stream from the link's "N0 M110 N0" that begins it to the
// execution of the M400 that ends it (every move done).
class SimulatedMarlin : public SimulatedPrinterUnderTest {
 public:
  explicit SimulatedMarlin(MarlinSimulatorOptions options) : m_sim(std::move(options)) {
    EXPECT_TRUE(m_sim.start().ok());
  }
  MarlinSimulator& simulator() { return m_sim; }
  std::unique_ptr<PrinterLink> link(PrinterLinkOptions options) const override {
    return marlinLinkTo(m_sim.devicePath(), std::move(options));
  }
  void injectThermalRunaway() override { m_sim.injectThermalRunaway(); }
  void cancelJobOnPrinter() override { m_sim.cancelJobOnPrinter(); }
  void dropLink() override { m_sim.dropLink(); }
  void restoreLink() override { m_sim.restoreLink(); }
  void setReplyDelay(std::chrono::milliseconds delay) override { m_sim.setReplyDelay(delay); }
  std::vector<JobInterval> jobs() const override {
    std::vector<JobInterval> out;
    const auto ends = executedTimes("M400");
    const auto begins = starts();
    for (std::size_t k = 0; k < begins.size(); ++k)
      out.push_back({begins[k], k < ends.size() ? ends[k] : Clock::time_point::max()});
    return out;
  }
  // The M110 that a file line follows (connect's own M110 is followed by temperature polls only).
  std::vector<Clock::time_point> starts() const override {
    std::vector<Clock::time_point> out;
    const auto received = m_sim.received();
    for (std::size_t i = 0; i < received.size(); ++i) {
      if (received[i].command != "M110 N0" || received[i].outcome != MarlinLineRecord::Outcome::Accepted) continue;
      for (std::size_t j = i + 1; j < received.size() && received[j].command != "M110 N0"; ++j) {
        if (received[j].command == "M105") continue;
        out.push_back(received[i].at);
        break;
      }
    }
    return out;
  }
  std::vector<Clock::time_point> emergencyStops() const override {
    std::vector<Clock::time_point> out;
    for (const auto& r : m_sim.received())
      if (r.outcome == MarlinLineRecord::Outcome::EmergencyStop) out.push_back(r.at);
    return out;
  }
  int completedJobs() const override { return static_cast<int>(executedTimes("M400").size()); }
  // M109's record is written when the wait ends: past the heating once it has more than the finished jobs.
  bool printingPastHeating() const override { return executedTimes("M109 S200").size() > executedTimes("M400").size(); }
  bool halted() const override { return m_sim.state().halted; }
  HeaterReading extruder() const override { return m_sim.state().extruder; }
  HeaterReading bed() const override { return m_sim.state().bed; }

 private:
  std::vector<Clock::time_point> executedTimes(const std::string& command) const {
    std::vector<Clock::time_point> out;
    for (const auto& e : m_sim.executed())
      if (e.command == command) out.push_back(e.at);
    return out;
  }
  MarlinSimulator m_sim;
};

// `protocol`'s simulator, started, at `speed` simulated seconds per real second, records on `clock`. `midJobFault`
// (thermal-runaway or cancelled-on-printer) is injected by the simulator itself once, half-way through the
// moves of the first job that gets there (HTTP: at progress 0.5; Marlin: on its 10th move of shortGcode()'s
// 21): on that event, however late the test's thread runs.
inline std::unique_ptr<SimulatedPrinterUnderTest> simulatedPrinter(
    PrinterProtocol protocol, double speed, std::function<std::chrono::steady_clock::time_point()> clock,
    PrinterFault midJobFault = PrinterFault::None) {
  if (protocol == PrinterProtocol::Marlin) {
    MarlinSimulatorOptions options = fastMarlinSimulatorOptions(speed);
    options.steadyNow = std::move(clock);
    options.fault = midJobFault;
    options.faultAtMove = 10;
    return std::make_unique<SimulatedMarlin>(options);
  }
  PrinterSimulatorOptions options;
  options.speed = speed;
  options.steadyNow = std::move(clock);
  options.fault = midJobFault;
  options.faultAtProgress = 0.5;
  return std::make_unique<SimulatedHttpPrinter>(protocol, options);
}

}  // namespace multidir::hardware::test

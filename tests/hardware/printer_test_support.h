#pragma once
// Shared by the printer tests: a short G-code program, and a fast simulator and link on 127.0.0.1 for each
// protocol, so that one test runs against every protocol (TEST_P over PrinterProtocol).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "hardware_test_support.h"
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

inline std::string writeFile(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
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

inline std::unique_ptr<PrinterLink> moonrakerLinkTo(int port, PrinterLinkOptions options = fastPrinterOptions()) {
  MoonrakerSettings settings;
  settings.host = "127.0.0.1";
  settings.port = port;
  auto link = makeMoonrakerLink(settings, options);
  EXPECT_TRUE(link.ok()) << (link.ok() ? "" : link.error().describe());
  return link.ok() ? std::move(link.value()) : nullptr;
}

inline std::unique_ptr<PrinterLink> octoPrintLinkTo(int port, const std::string& apiKey = kOctoPrintSimulatorApiKey,
                                                    PrinterLinkOptions options = fastPrinterOptions()) {
  OctoPrintSettings settings;
  settings.host = "127.0.0.1";
  settings.port = port;
  settings.apiKey = apiKey;
  auto link = makeOctoPrintLink(settings, options);
  EXPECT_TRUE(link.ok()) << (link.ok() ? "" : link.error().describe());
  return link.ok() ? std::move(link.value()) : nullptr;
}

enum class PrinterProtocol { Moonraker, OctoPrint };

inline const char* protocolText(PrinterProtocol protocol) {
  return protocol == PrinterProtocol::Moonraker ? "Moonraker" : "OctoPrint";
}
inline std::string protocolName(const testing::TestParamInfo<PrinterProtocol>& info) {
  return protocolText(info.param);
}
// How GoogleTest prints the parameter (test lists, ctest names).
inline void PrintTo(PrinterProtocol protocol, std::ostream* out) { *out << protocolText(protocol); }

inline std::unique_ptr<PrinterSimulator> printerSimulator(PrinterProtocol protocol, PrinterSimulatorOptions options) {
  if (protocol == PrinterProtocol::Moonraker) return std::make_unique<MoonrakerSimulator>(options);
  OctoPrintSimulatorOptions octoPrint;
  static_cast<PrinterSimulatorOptions&>(octoPrint) = options;
  return std::make_unique<OctoPrintSimulator>(octoPrint);
}

inline std::unique_ptr<PrinterLink> printerLinkTo(PrinterProtocol protocol, int port,
                                                  PrinterLinkOptions options = fastPrinterOptions()) {
  return protocol == PrinterProtocol::Moonraker ? moonrakerLinkTo(port, options)
                                                : octoPrintLinkTo(port, kOctoPrintSimulatorApiKey, options);
}

// The protocol's requests as the simulators record them.
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

}  // namespace multidir::hardware::test

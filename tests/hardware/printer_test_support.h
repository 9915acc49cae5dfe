#pragma once
// Shared by the printer tests: a short G-code program, fast Moonraker and Marlin links (the simulators on
// 127.0.0.1 and on a pseudo-terminal).
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "hardware_test_support.h"
#include "multidir/hardware/marlin_link.h"
#include "multidir/hardware/moonraker_link.h"
#include "multidir/hardware/moonraker_simulator.h"

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

inline std::unique_ptr<PrinterLink> marlinLinkTo(const std::string& devicePath,
                                                 PrinterLinkOptions options = fastPrinterOptions(), int window = 1) {
  MarlinSettings settings;
  settings.devicePath = devicePath;
  settings.maxUnacknowledgedLines = window;
  auto link = makeMarlinLink(settings, options);
  EXPECT_TRUE(link.ok()) << (link.ok() ? "" : link.error().describe());
  return link.ok() ? std::move(link.value()) : nullptr;
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

}  // namespace multidir::hardware::test

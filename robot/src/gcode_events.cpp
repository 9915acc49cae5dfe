#include "gcode_events.h"

#include <cctype>
#include <cstdlib>
#include <sstream>

namespace multidir::robot::detail {
namespace {

std::string upperHead(const std::string& code) {
  std::string head = code.substr(0, code.find_first_of(" \t"));
  for (char& c : head) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return head;
}

// The value of word `letter` in `code` (after the command), if present.
bool wordValue(const std::string& code, char letter, double& value, bool& malformed) {
  std::istringstream words(code);
  std::string word;
  words >> word;  // the command
  while (words >> word) {
    if (std::toupper(static_cast<unsigned char>(word[0])) != letter) continue;
    char* end = nullptr;
    value = std::strtod(word.c_str() + 1, &end);
    malformed = end == word.c_str() + 1 || *end != '\0';
    return true;
  }
  return false;
}

}  // namespace

core::Result<GcodeSideInfo> scanGcodeSideInfo(const std::string& text, const std::string& name) {
  GcodeSideInfo info;
  info.feedMmPerMinByLine.push_back(0.0);
  std::istringstream lines(text);
  std::string raw;
  int lineNumber = 0;
  double feed = 0.0;
  auto bad = [&](const std::string& why) {
    return core::Error{core::ErrorCode::CheckFailed, "line " + std::to_string(lineNumber) + ": " + why, name};
  };
  while (std::getline(lines, raw)) {
    ++lineNumber;
    const std::size_t semicolon = raw.find(';');
    if (semicolon != std::string::npos && raw.compare(semicolon, 13, ";LAYER_CHANGE") == 0)
      info.layerChangeLines.push_back(lineNumber);
    std::string code = raw.substr(0, semicolon);
    const std::size_t first = code.find_first_not_of(" \t\r");
    if (first == std::string::npos) {
      info.feedMmPerMinByLine.push_back(feed);
      continue;
    }
    code = code.substr(first);
    while (!code.empty() && (code.back() == ' ' || code.back() == '\t' || code.back() == '\r')) code.pop_back();
    const std::string head = upperHead(code);
    double value = 0.0;
    bool malformed = false;
    if (head == "G0" || head == "G1" || head == "G00" || head == "G01") {
      if (wordValue(code, 'F', value, malformed)) {
        if (malformed || !(value > 0.0)) return bad("'" + code + "': the feed F must be a number above 0");
        feed = value;
      }
    } else if (head == "G28") {
      return bad("G28 homes a printer's axes; the robot cell's nozzle is fixed and has none: remove it from the "
                 "profile's start_gcode (resources/printers/ur5-cell-0.8.ini shows a start for the cell)");
    } else if (head == "M104" || head == "M109") {
      if (wordValue(code, 'S', value, malformed)) {
        if (malformed) return bad("'" + code + "': S must be a number");
        info.events.push_back({head == "M104" ? GcodeEvent::Kind::NozzleTemperature
                                              : GcodeEvent::Kind::NozzleTemperatureWait,
                               lineNumber, value});
      }
    } else if (head == "M106") {
      double duty = 255.0;
      if (wordValue(code, 'S', value, malformed)) {
        if (malformed) return bad("'" + code + "': S must be a number");
        duty = value;
      }
      info.events.push_back({duty > 0.0 ? GcodeEvent::Kind::FanOn : GcodeEvent::Kind::FanOff, lineNumber, duty});
    } else if (head == "M107") {
      info.events.push_back({GcodeEvent::Kind::FanOff, lineNumber, 0.0});
    }
    info.feedMmPerMinByLine.push_back(feed);
  }
  return info;
}

}  // namespace multidir::robot::detail

#include "sim/gcode_timeline.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace multidir::hardware::sim {
namespace {

constexpr double kHomingSeconds = 2.0;
constexpr double kDefaultFeedMmPerMin = 1500.0;

// The value of word `letter` in `code` (comment already removed); false when absent or not a number.
bool word(const std::string& code, char letter, double& value) {
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (std::toupper(static_cast<unsigned char>(code[i])) != letter) continue;
    if (i > 0 && !std::isspace(static_cast<unsigned char>(code[i - 1]))) continue;
    const char* start = code.c_str() + i + 1;
    char* end = nullptr;
    const double parsed = std::strtod(start, &end);
    if (end == start || !std::isfinite(parsed)) return false;
    value = parsed;
    return true;
  }
  return false;
}

}  // namespace

GcodeTimeline readGcodeTimeline(const std::string& text) {
  GcodeTimeline timeline;
  timeline.bytes = text.size();
  double position[4] = {0, 0, 0, 0};  // X Y Z E
  bool relative = false;
  bool relativeE = false;
  double feed = kDefaultFeedMmPerMin;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string code = text.substr(begin, end - begin);
    if (const std::size_t semicolon = code.find(';'); semicolon != std::string::npos) code.resize(semicolon);
    TimelineLine line;
    line.endByte = end < text.size() ? end + 1 : end;
    std::size_t first = code.find_first_not_of(" \t\r");
    if (first != std::string::npos) {
      code = code.substr(first);
      const char kind = static_cast<char>(std::toupper(static_cast<unsigned char>(code[0])));
      double number = -1;
      if (code.size() > 1) number = std::strtod(code.c_str() + 1, nullptr);
      const int command = static_cast<int>(number);
      if (kind == 'G' && (command == 0 || command == 1)) {
        double f = 0;
        if (word(code, 'F', f) && f > 0) feed = f;
        double target[4] = {position[0], position[1], position[2], position[3]};
        const char axes[4] = {'X', 'Y', 'Z', 'E'};
        for (int a = 0; a < 4; ++a) {
          double v = 0;
          if (!word(code, axes[a], v)) continue;
          const bool rel = a == 3 ? relativeE : relative;
          target[a] = rel ? position[a] + v : v;
        }
        const double dx = target[0] - position[0], dy = target[1] - position[1], dz = target[2] - position[2];
        double distance = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (distance < 1e-12) distance = std::abs(target[3] - position[3]);  // a retract or prime
        line.moveSeconds = distance / (feed / 60.0);
        for (int a = 0; a < 4; ++a) position[a] = target[a];
      } else if (kind == 'G' && command == 4) {
        double v = 0;
        if (word(code, 'P', v))
          line.moveSeconds = v / 1000.0;
        else if (word(code, 'S', v))
          line.moveSeconds = v;
      } else if (kind == 'G' && command == 28) {
        line.moveSeconds = kHomingSeconds;
      } else if (kind == 'G' && command == 90) {
        relative = false;
        relativeE = false;
      } else if (kind == 'G' && command == 91) {
        relative = true;
        relativeE = true;
      } else if (kind == 'G' && command == 92) {
        const char axes[4] = {'X', 'Y', 'Z', 'E'};
        for (int a = 0; a < 4; ++a) {
          double v = 0;
          if (word(code, axes[a], v)) position[a] = v;
        }
      } else if (kind == 'M' && command == 82) {
        relativeE = false;
      } else if (kind == 'M' && command == 83) {
        relativeE = true;
      } else if (kind == 'M' && (command == 104 || command == 109 || command == 140 || command == 190)) {
        double v = 0;
        if (word(code, 'S', v) || word(code, 'R', v)) {
          line.heater = command == 104 || command == 109 ? TimelineLine::Heater::Extruder : TimelineLine::Heater::Bed;
          line.targetC = v;
          line.waitForHeater = command == 109 || command == 190;
        }
      }
    }
    timeline.moveSeconds += line.moveSeconds;
    timeline.lines.push_back(line);
    begin = line.endByte;
    if (end == text.size()) break;
  }
  return timeline;
}

}  // namespace multidir::hardware::sim

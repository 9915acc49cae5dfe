#include "sim/gcode_timeline.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace multidir::hardware::sim {
namespace {

constexpr double kHomingSeconds = 2.0;

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

TimelineLine GcodeTimelineReader::read(const std::string& text, std::size_t endByte) {
  TimelineLine line;
  line.endByte = endByte;
  std::string code = text;
  if (const std::size_t semicolon = code.find(';'); semicolon != std::string::npos) code.resize(semicolon);
  const std::size_t first = code.find_first_not_of(" \t\r");
  if (first == std::string::npos) return line;
  code = code.substr(first);
  const char kind = static_cast<char>(std::toupper(static_cast<unsigned char>(code[0])));
  double number = -1;
  if (code.size() > 1) number = std::strtod(code.c_str() + 1, nullptr);
  const int command = static_cast<int>(number);
  const char axes[4] = {'X', 'Y', 'Z', 'E'};
  if (kind == 'G' && (command == 0 || command == 1)) {
    double f = 0;
    if (word(code, 'F', f) && f > 0) m_feedMmPerMin = f;
    double target[4] = {m_position[0], m_position[1], m_position[2], m_position[3]};
    for (int a = 0; a < 4; ++a) {
      double v = 0;
      if (!word(code, axes[a], v)) continue;
      const bool rel = a == 3 ? m_relativeE : m_relative;
      target[a] = rel ? m_position[a] + v : v;
    }
    const double dx = target[0] - m_position[0], dy = target[1] - m_position[1], dz = target[2] - m_position[2];
    double distance = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (distance < 1e-12) distance = std::abs(target[3] - m_position[3]);  // a retract or prime
    line.moveSeconds = distance / (m_feedMmPerMin / 60.0);
    for (int a = 0; a < 4; ++a) m_position[a] = target[a];
  } else if (kind == 'G' && command == 4) {
    double v = 0;
    if (word(code, 'P', v))
      line.moveSeconds = v / 1000.0;
    else if (word(code, 'S', v))
      line.moveSeconds = v;
  } else if (kind == 'G' && command == 28) {
    line.moveSeconds = kHomingSeconds;
  } else if (kind == 'G' && command == 90) {
    m_relative = false;
    m_relativeE = false;
  } else if (kind == 'G' && command == 91) {
    m_relative = true;
    m_relativeE = true;
  } else if (kind == 'G' && command == 92) {
    for (int a = 0; a < 4; ++a) {
      double v = 0;
      if (word(code, axes[a], v)) m_position[a] = v;
    }
  } else if (kind == 'M' && command == 82) {
    m_relativeE = false;
  } else if (kind == 'M' && command == 83) {
    m_relativeE = true;
  } else if (kind == 'M' && (command == 104 || command == 109 || command == 140 || command == 190)) {
    double v = 0;
    if (word(code, 'S', v) || word(code, 'R', v)) {
      line.heater = command == 104 || command == 109 ? TimelineLine::Heater::Extruder : TimelineLine::Heater::Bed;
      line.targetC = v;
      line.waitForHeater = command == 109 || command == 190;
    }
  }
  return line;
}

GcodeTimeline readGcodeTimeline(const std::string& text) {
  GcodeTimeline timeline;
  timeline.bytes = text.size();
  GcodeTimelineReader reader;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    const TimelineLine line = reader.read(text.substr(begin, end - begin), end < text.size() ? end + 1 : end);
    timeline.moveSeconds += line.moveSeconds;
    timeline.lines.push_back(line);
    begin = line.endByte;
    if (end == text.size()) break;
  }
  return timeline;
}

}  // namespace multidir::hardware::sim

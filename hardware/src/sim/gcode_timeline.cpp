#include "sim/gcode_timeline.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

namespace multidir::hardware::sim {
namespace {

constexpr double kHomingSeconds = 2.0;
constexpr double kKlipperManualStepperVelocity = 5.0;  // [manual_stepper] velocity's default (per second)

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

// Klipper's KEY=value parameter `key` of an extended command (keys are case-insensitive); false when absent.
bool klipperParameter(const std::string& code, const std::string& key, std::string& value) {
  std::size_t at = code.find(' ');
  while (at != std::string::npos) {
    const std::size_t begin = code.find_first_not_of(" \t", at);
    if (begin == std::string::npos) return false;
    const std::size_t end = code.find_first_of(" \t", begin);
    const std::string token = code.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    const std::size_t equals = token.find('=');
    if (equals != std::string::npos && equals == key.size()) {
      bool same = true;
      for (std::size_t i = 0; i < equals; ++i)
        same = same && std::toupper(static_cast<unsigned char>(token[i])) == key[i];
      if (same) {
        value = token.substr(equals + 1);
        return true;
      }
    }
    at = end;
  }
  return false;
}

bool klipperNumber(const std::string& code, const std::string& key, double& value) {
  std::string text;
  if (!klipperParameter(code, key, text)) return false;
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(parsed)) return false;
  value = parsed;
  return true;
}

bool startsWithWord(const std::string& code, const char* word) {
  const std::size_t n = std::char_traits<char>::length(word);
  if (code.size() < n || (code.size() > n && code[n] != ' ' && code[n] != '\t')) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (std::toupper(static_cast<unsigned char>(code[i])) != word[i]) return false;
  return true;
}

}  // namespace

// Klipper's MANUAL_STEPPER (klippy/extras/manual_stepper.py): ENABLE, then SET_POSITION, then MOVE at SPEED.
void GcodeTimelineReader::readManualStepper(const std::string& code, TimelineLine& line) {
  std::string name;
  const bool named = klipperParameter(code, "STEPPER", name);
  std::size_t index = m_axes.names.size();
  for (std::size_t i = 0; i < m_axes.names.size(); ++i)
    if (named && m_axes.names[i] == name) index = i;
  if (index == m_axes.names.size()) {
    // Klipper's mux command lookup (klippy/gcode.py): without any [manual_stepper] the command is unknown, which
    // Klipper only reports ("Unknown command"); with some, a name it lacks is an error.
    if (!m_axes.names.empty())
      line.error = "The value '" + (named ? name : std::string("None")) + "' is not valid for STEPPER";
    return;
  }
  double value = 0;
  if (klipperNumber(code, "ENABLE", value))
    m_enabled = value != 0.0 ? m_enabled | (1u << index) : m_enabled & ~(1u << index);
  if (klipperNumber(code, "SET_POSITION", value)) m_axis[index] = value;
  if (klipperNumber(code, "MOVE", value)) {
    double speed = kKlipperManualStepperVelocity;
    double given = 0;
    if (klipperNumber(code, "SPEED", given) && given > 0) speed = given;
    const double change = value - m_axis[index];
    line.moveSeconds = std::abs(change) / speed;
    line.turns = change != 0.0;
    m_axis[index] = value;
  }
}

TimelineLine GcodeTimelineReader::read(const std::string& text, std::size_t endByte) {
  TimelineLine line;
  line.endByte = endByte;
  std::string code = text;
  if (const std::size_t semicolon = code.find(';'); semicolon != std::string::npos) code.resize(semicolon);
  for (int a = 0; a < 3; ++a) line.endMm[static_cast<std::size_t>(a)] = m_position[a];
  line.axisDegrees = m_axis;
  line.enabledAxes = m_enabled;
  const std::size_t first = code.find_first_not_of(" \t\r");
  if (first == std::string::npos) return line;
  code = code.substr(first, code.find_last_not_of(" \t\r") + 1 - first);
  const char kind = static_cast<char>(std::toupper(static_cast<unsigned char>(code[0])));
  double number = -1;
  if (code.size() > 1) number = std::strtod(code.c_str() + 1, nullptr);
  const int command = static_cast<int>(number);
  const char axes[4] = {'X', 'Y', 'Z', 'E'};
  const bool marlinAxes = m_axes.firmware == RotaryAxisSetup::Firmware::Marlin;
  if (kind == 'G' && (command == 0 || command == 1)) {
    double f = 0;
    if (word(code, 'F', f) && f > 0) m_feedMmPerMin = f;
    double target[4] = {m_position[0], m_position[1], m_position[2], m_position[3]};
    for (int a = 0; a < 4; ++a) {
      double v = 0;
      if (!word(code, axes[a], v)) continue;
      // Klipper's G1 (gcode_move.py): E is relative after G91 or M83; Marlin's G90/G91 set E's mode too.
      const bool rel = a == 3 ? m_relativeE || (!marlinAxes && m_relative) : m_relative;
      target[a] = rel ? m_position[a] + v : v;
    }
    std::array<double, 3> axisTarget = m_axis;
    double turned = 0.0;  // the squared length of the rotary axes' change (degrees^2)
    for (std::size_t i = 0; marlinAxes && i < m_axes.names.size(); ++i) {
      double v = 0;
      if (!word(code, m_axes.names[i][0], v)) continue;
      axisTarget[i] = m_relative ? m_axis[i] + v : v;
      turned += (axisTarget[i] - m_axis[i]) * (axisTarget[i] - m_axis[i]);
    }
    const double dx = target[0] - m_position[0], dy = target[1] - m_position[1], dz = target[2] - m_position[2];
    double distance = std::sqrt(dx * dx + dy * dy + dz * dz);
    const bool linear = distance >= 1e-12;
    if (!linear) distance = turned > 0.0 ? std::sqrt(turned) : std::abs(target[3] - m_position[3]);
    line.moveSeconds = distance / (m_feedMmPerMin / 60.0);
    line.extrudes = linear && target[3] > m_position[3];
    line.turns = turned > 0.0;
    for (int a = 0; a < 4; ++a) m_position[a] = target[a];
    m_axis = axisTarget;
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
    if (marlinAxes) m_relativeE = false;  // Klipper's G90 leaves M83's relative extrusion as it was
  } else if (kind == 'G' && command == 91) {
    m_relative = true;
    if (marlinAxes) m_relativeE = true;
  } else if (kind == 'G' && command == 92) {
    for (int a = 0; a < 4; ++a) {
      double v = 0;
      if (word(code, axes[a], v)) m_position[a] = v;
    }
    for (std::size_t i = 0; marlinAxes && i < m_axes.names.size(); ++i) {
      double v = 0;
      if (word(code, m_axes.names[i][0], v)) m_axis[i] = v;
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
  } else if (!marlinAxes && startsWithWord(code, "MANUAL_STEPPER")) {
    readManualStepper(code, line);
  }
  for (int a = 0; a < 3; ++a) line.endMm[static_cast<std::size_t>(a)] = m_position[a];
  line.axisDegrees = m_axis;
  line.enabledAxes = m_enabled;
  return line;
}

GcodeTimeline readGcodeTimeline(const std::string& text, const RotaryAxisSetup& axes) {
  GcodeTimeline timeline;
  timeline.bytes = text.size();
  GcodeTimelineReader reader(axes);
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

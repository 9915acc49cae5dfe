#include "multidir/hardware/robot_pause.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace multidir::hardware {
namespace {

std::string trimmed(const std::string& s) {
  const std::size_t first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// movel(p[x, y, z, rx, ry, rz], a=A, v=V, r=R): the six pose numbers (metres, radians) and the rest after the
// pose's bracket (", a=..., v=..., r=...)").
bool readMovel(const std::string& line, std::array<double, 6>& pose, std::string& rest) {
  const std::string t = trimmed(line);
  if (!startsWith(t, "movel(p[")) return false;
  const std::size_t close = t.find(']');
  if (close == std::string::npos) return false;
  std::string numbers = t.substr(8, close - 8);
  std::replace(numbers.begin(), numbers.end(), ',', ' ');
  std::istringstream in(numbers);
  for (double& v : pose)
    if (!(in >> v)) return false;
  rest = t.substr(close + 1);
  return true;
}

std::string number(double v, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

// The movel line to `positionMm` with the orientation of movel `index` and its own parameters, or a travel's.
std::string movelTo(const StepScript& script, int index, const std::array<double, 3>& positionMm,
                    const std::string* parameters) {
  std::array<double, 6> pose{};
  std::string rest;
  readMovel(script.lines[static_cast<std::size_t>(script.movels[static_cast<std::size_t>(index)])], pose, rest);
  std::string text = "  movel(p[";
  for (int i = 0; i < 3; ++i) text += number(positionMm[static_cast<std::size_t>(i)] / 1000.0, 7) + ", ";
  text += number(pose[3], 7) + ", " + number(pose[4], 7) + ", " + number(pose[5], 7) + "]";
  return text + (parameters != nullptr ? *parameters : rest) + "\n";
}

std::array<double, 3> lifted(const std::array<double, 3>& p, const PauseGeometry& g) {
  // The platform backs away from the nozzle: against the nozzle axis (which points up into the extruder).
  return {p[0] - g.liftMm * g.nozzleAxis[0], p[1] - g.liftMm * g.nozzleAxis[1], p[2] - g.liftMm * g.nozzleAxis[2]};
}

std::string travelParameters(const PauseGeometry& g) {
  return ", a=" + number(g.toolAccelMmPerS2 / 1000.0, 4) + ", v=" + number(g.travelSpeedMmPerS / 1000.0, 6) +
         ", r=0.000000)";
}

// The last line before `end` (exclusive) that starts with `prefix`, trimmed; "" when none.
std::string lastBefore(const StepScript& script, int end, const char* prefix) {
  for (int i = end - 1; i >= 0; --i) {
    const std::string t = trimmed(script.lines[static_cast<std::size_t>(i)]);
    if (startsWith(t, prefix)) return t;
  }
  return {};
}

double distanceToSegment(const std::array<double, 3>& p, const std::array<double, 3>& a, const std::array<double, 3>& b) {
  double ab2 = 0.0, apab = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    ab2 += (b[i] - a[i]) * (b[i] - a[i]);
    apab += (p[i] - a[i]) * (b[i] - a[i]);
  }
  const double t = ab2 > 0.0 ? std::clamp(apab / ab2, 0.0, 1.0) : 0.0;
  double d2 = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double c = a[i] + t * (b[i] - a[i]) - p[i];
    d2 += c * c;
  }
  return std::sqrt(d2);
}

}  // namespace

core::Result<StepScript> parseStepScript(const std::string& text, const std::string& name) {
  StepScript script;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) script.lines.push_back(line);
  if (script.lines.empty() || !startsWith(trimmed(script.lines.front()), "def "))
    return core::Error{core::ErrorCode::MalformedFile, "the program does not start with its def line", name};
  for (std::size_t i = 0; i < script.lines.size(); ++i) {
    if (!startsWith(trimmed(script.lines[i]), "movel(")) continue;
    std::array<double, 6> pose{};
    std::string rest;
    if (!readMovel(script.lines[i], pose, rest))
      return core::Error{core::ErrorCode::MalformedFile,
                         "line " + std::to_string(i + 1) + ": a movel whose pose p[x, y, z, rx, ry, rz] cannot be read",
                         name};
    script.movels.push_back(static_cast<int>(i));
    script.ends.push_back({pose[0] * 1000.0, pose[1] * 1000.0, pose[2] * 1000.0});
  }
  if (script.movels.empty()) return core::Error{core::ErrorCode::MalformedFile, "the program has no movel", name};
  return script;
}

int movelUnderWay(const StepScript& script, const PauseGeometry& geometry, const std::array<double, 3>& tcpMm,
                  double toleranceMm, int fromLine) {
  const auto distanceTo = [&](std::size_t i) {
    const std::array<double, 3> from = i == 0 ? lifted(script.ends[0], geometry) : script.ends[i - 1];
    return distanceToSegment(tcpMm, from, script.ends[i]);
  };
  for (std::size_t i = 0; i < script.ends.size(); ++i) {
    if (script.movels[i] < fromLine || distanceTo(i) > toleranceMm) continue;
    // Near the end of movel i, the tolerance also takes in the first part of the movels after it: the arm 0.15 mm
    // into movel i + 1 is 0.15 mm from movel i's end. Of that run of movels within the tolerance, the one the
    // arm is on is the nearest (the first of equals: at their common point either is right); finishing movel i
    // instead would take the arm back along i + 1 and the resumed program would print that part again.
    std::size_t nearest = i;
    double least = distanceTo(i);
    for (std::size_t next = i + 1; next < script.ends.size(); ++next) {
      const double d = distanceTo(next);
      if (d > toleranceMm) break;
      if (d < least) {
        least = d;
        nearest = next;
      }
    }
    return static_cast<int>(nearest);
  }
  return -1;
}

std::string pauseProgram(const StepScript& script, const PauseGeometry& geometry, int index) {
  const int line = script.movels[static_cast<std::size_t>(index)];
  std::string text = "def multidir_pause():\n";
  text += "  # MultiDir: pause; the move under way finished, the extruder stopped, the platform lifted off the nozzle\n";
  if (const std::string tcp = lastBefore(script, line, "set_tcp("); !tcp.empty()) text += "  " + tcp + "\n";
  const std::string rate = lastBefore(script, line, "set_standard_analog_out(0,");
  if (!rate.empty()) text += "  " + rate + "\n";
  text += "  " + trimmed(script.lines[static_cast<std::size_t>(line)]) + "\n";
  text += "  set_standard_analog_out(0, 0.000000)\n";
  const std::string travel = travelParameters(geometry);
  text += movelTo(script, index, lifted(script.ends[static_cast<std::size_t>(index)], geometry), &travel);
  text += "end\n";
  return text;
}

std::string resumeProgram(const StepScript& script, const PauseGeometry& geometry, int index) {
  const int line = script.movels[static_cast<std::size_t>(index)];
  std::string def = trimmed(script.lines.front());
  const std::size_t paren = def.find('(');
  std::string text = (paren != std::string::npos ? def.substr(0, paren) : def) + "():\n";
  text += "  # MultiDir: resumed after movel " + std::to_string(index + 1) + " of " +
          std::to_string(script.movels.size()) + " (line " + std::to_string(line + 1) + " of the step's program)\n";
  if (const std::string tcp = lastBefore(script, line, "set_tcp("); !tcp.empty()) text += "  " + tcp + "\n";
  text += "  set_standard_analog_out(0, 0.000000)\n";
  // The way back down is no movel of the step: the movel register (when the program numbers its movels) says so.
  if (const std::string numbered = lastBefore(script, line, "write_output_integer_register("); !numbered.empty())
    text += "  " + numbered.substr(0, numbered.find(',')) + ", 0)\n";
  if (const std::string fan = lastBefore(script, line + 1, "set_standard_digital_out(0,"); !fan.empty())
    text += "  " + fan + "\n";
  const std::string setPoint = lastBefore(script, line + 1, "set_standard_analog_out(1,");
  if (!setPoint.empty()) {
    text += "  " + setPoint + "\n";
    // The nozzle may have cooled while paused: wait for its set point as the program's M109 does (2 C below).
    const double fraction = std::stod(setPoint.substr(std::string("set_standard_analog_out(1,").size()));
    if (fraction > 2.0 / 300.0)
      text += "  while get_standard_analog_in(0) < " + number(fraction - 2.0 / 300.0, 4) + ":\n    sync()\n  end\n";
  }
  const std::array<double, 3> end = script.ends[static_cast<std::size_t>(index)];
  const std::string travel = travelParameters(geometry);
  text += movelTo(script, index, lifted(end, geometry), &travel);
  text += movelTo(script, index, end, &travel);
  // The extruder's rate in effect after that movel (the program sets it only where it changes).
  if (const std::string rate = lastBefore(script, line + 1, "set_standard_analog_out(0,"); !rate.empty())
    text += "  " + rate + "\n";
  for (std::size_t i = static_cast<std::size_t>(line) + 1; i < script.lines.size(); ++i) text += script.lines[i] + "\n";
  return text;
}

}  // namespace multidir::hardware

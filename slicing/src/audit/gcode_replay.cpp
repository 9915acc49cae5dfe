#include "gcode_replay.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace multidir::slicing::audit {

namespace {

using core::Error;
using core::ErrorCode;

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// "KEY=value" in a Klipper command line (upper-cased); false when absent or not a number.
bool klipperParameter(const std::string& code, const std::string& key, double& value) {
  const std::string u = upper(code);
  const std::size_t at = u.find(" " + key + "=");
  if (at == std::string::npos) return false;
  const char* start = code.c_str() + at + key.size() + 2;
  char* end = nullptr;
  value = std::strtod(start, &end);
  return end != start && std::isfinite(value);
}

// The word after "KEY=" in a Klipper command line (case kept); empty when absent.
std::string klipperWord(const std::string& code, const std::string& key) {
  const std::size_t at = upper(code).find(" " + key + "=");
  if (at == std::string::npos) return {};
  const std::size_t start = at + key.size() + 2;
  return code.substr(start, code.find_first_of(" \t", start) - start);
}

}  // namespace

core::Result<Replay> replayGcode(const std::string& text, const std::string& name, const std::vector<ReplayAxis>& axes,
                                 double retractToleranceMm, MachineState& state) {
  const std::size_t axisCount = std::min(axes.size(), kMaxRotaryAxes);
  // The slot of a G-code letter among the rotary axes; axisCount when it is none of them.
  const auto slotOfLetter = [&](char letter) {
    for (std::size_t k = 0; k < axisCount; ++k)
      if (std::toupper(static_cast<unsigned char>(axes[k].letter)) == letter) return k;
    return axisCount;
  };
  Replay replay;
  int step = 0;
  bool inTransition = false;
  bool skirt = false;
  std::string feature;
  std::istringstream in(text);
  std::string line;
  int lineNumber = 0;
  const auto bad = [&](const std::string& what) {
    const std::string section = step > 0 ? " (step " + std::to_string(step) + ")" : "";
    return Error{ErrorCode::MalformedFile, "line " + std::to_string(lineNumber) + section + ": " + what, name};
  };
  while (std::getline(in, line)) {
    ++lineNumber;
    const std::size_t semicolon = line.find(';');
    if (semicolon != std::string::npos) {
      const std::string comment = line.substr(semicolon + 1);
      int k = 0;
      if (std::sscanf(comment.c_str(), " MULTIDIR STEP %d", &k) == 1) {
        step = k;
        inTransition = false;
      } else if (std::sscanf(comment.c_str(), " MULTIDIR TRANSITION %d", &k) == 1) {
        step = k;
        inTransition = true;
      } else if (comment.find("MULTIDIR START SEQUENCE") != std::string::npos ||
                 comment.find("MULTIDIR END SEQUENCE") != std::string::npos) {
        step = 0;
        inTransition = false;
      } else if (comment.rfind("TYPE:", 0) == 0) {
        skirt = comment.find("Skirt") != std::string::npos || comment.find("Brim") != std::string::npos;
        feature = comment.substr(5);
        while (!feature.empty() && std::isspace(static_cast<unsigned char>(feature.back()))) feature.pop_back();
      }
    }
    std::string code = line.substr(0, semicolon);
    const std::size_t first = code.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    code = code.substr(first);
    while (!code.empty() && std::isspace(static_cast<unsigned char>(code.back()))) code.pop_back();
    const std::string head = upper(code.substr(0, code.find_first_of(" \t")));

    ReplayMove move;
    move.line = lineNumber;
    move.from = state.position;
    move.axesFrom = state.axesDegrees;
    move.step = step;
    move.inTransition = inTransition;
    move.skirt = skirt;
    move.feature = feature;

    if (head == "MANUAL_STEPPER") {
      // Klipper's stepper names are case-sensitive in its config but not in commands: compare upper-cased.
      const std::string stepper = upper(klipperWord(code, "STEPPER"));
      std::size_t slot = axisCount;
      for (std::size_t k = 0; k < axisCount && slot == axisCount; ++k)
        if (axes[k].stepper.empty() || upper(axes[k].stepper) == stepper) slot = k;
      if (slot == axisCount) continue;  // a stepper that turns no platform axis
      double value = 0.0;
      if (klipperParameter(code, "SET_POSITION", value)) state.axesDegrees[slot] = value;
      if (klipperParameter(code, "MOVE", value)) {
        move.to = state.position;
        state.axesDegrees[slot] = value;
        move.axesTo = state.axesDegrees;
        replay.moves.push_back(move);
      }
      continue;
    }
    if (head == "G2" || head == "G3" || head == "G02" || head == "G03")
      return bad("an arc move (" + head + "); the audit replays straight moves only: slice with arc fitting off");
    if (head == "G10") {
      state.firmwareRetracted = true;
      continue;
    }
    if (head == "G11") {
      state.firmwareRetracted = false;
      continue;
    }
    const bool motion = head == "G0" || head == "G1" || head == "G00" || head == "G01";
    if (!motion && head != "G90" && head != "G91" && head != "M82" && head != "M83" && head != "G92" && head != "G28")
      continue;
    // The words after the command: a letter and a number each.
    std::vector<std::pair<char, double>> words;
    for (std::size_t i = head.size(); i < code.size();) {
      const unsigned char c = static_cast<unsigned char>(code[i]);
      if (std::isspace(c)) {
        ++i;
        continue;
      }
      if (!std::isalpha(c)) return bad("'" + code + "' is not G-code");
      const char* start = code.c_str() + i + 1;
      char* end = nullptr;
      const double value = std::strtod(start, &end);
      if (end == start || !std::isfinite(value)) return bad("'" + code + "' is not G-code");
      words.emplace_back(static_cast<char>(std::toupper(c)), value);
      i = static_cast<std::size_t>(end - code.c_str());
    }
    if (head == "G90") state.absoluteXyz = true;
    if (head == "G91") state.absoluteXyz = false;
    if (head == "M82") state.absoluteE = true;
    if (head == "M83") state.absoluteE = false;
    if (head == "G92") {
      for (const auto& [letter, value] : words) {
        if (letter >= 'X' && letter <= 'Z') state.position[letter - 'X'] = value;
        if (letter == 'E') state.e = value;  // renames E; the filament stays where it is
        if (const std::size_t k = slotOfLetter(letter); k < axisCount) state.axesDegrees[k] = value;
      }
      continue;
    }
    if (head == "G28") {
      bool any = false;
      for (const auto& [letter, value] : words)
        if (letter >= 'X' && letter <= 'Z') {
          state.position[letter - 'X'] = 0.0;
          any = true;
        }
      if (!any) state.position.setZero();
      continue;
    }
    if (!motion) continue;
    for (const auto& [letter, value] : words) {
      if (letter >= 'X' && letter <= 'Z') {
        const int axis = letter - 'X';
        state.position[axis] = state.absoluteXyz ? value : state.position[axis] + value;
      } else if (letter == 'E') {
        const double next = state.absoluteXyz && state.absoluteE ? value : state.e + value;
        move.filamentMm = next - state.e;
        state.e = next;
      } else if (const std::size_t k = slotOfLetter(letter); k < axisCount) {
        state.axesDegrees[k] = state.absoluteXyz ? value : state.axesDegrees[k] + value;
      }
    }
    move.to = state.position;
    move.axesTo = state.axesDegrees;
    if (move.filamentMm < 0.0) {
      state.retractedMm -= move.filamentMm;
    } else if (move.filamentMm > 0.0) {
      move.retractedAtStart = move.extrudes() && (state.retractedMm > retractToleranceMm || state.firmwareRetracted);
      state.retractedMm = std::max(0.0, state.retractedMm - move.filamentMm);
    }
    replay.moves.push_back(move);
  }
  replay.lineCount = lineNumber;
  return replay;
}

std::string slicerSetting(const std::string& gcode, const std::string& key) {
  const std::string marker = "\n; " + key + " = ";
  const std::size_t at = gcode.rfind(marker);
  if (at == std::string::npos) return {};
  const std::size_t start = at + marker.size();
  const std::size_t end = gcode.find('\n', start);
  std::string value = gcode.substr(start, end == std::string::npos ? std::string::npos : end - start);
  while (!value.empty() && std::isspace(static_cast<unsigned char>(value.back()))) value.pop_back();
  return value;
}

}  // namespace multidir::slicing::audit

#include "stitched_program.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cli_args.h"

namespace multidir::cli {
namespace {

// One line's command: the comment and surrounding blanks removed.
std::string commandOf(const std::string& line) {
  std::string code = line.substr(0, line.find(';'));
  const std::size_t first = code.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return code.substr(first, code.find_last_not_of(" \t\r") + 1 - first);
}

std::vector<std::string> words(const std::string& code) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while ((at = code.find_first_not_of(" \t", at)) != std::string::npos) {
    const std::size_t end = code.find_first_of(" \t", at);
    out.push_back(code.substr(at, end == std::string::npos ? std::string::npos : end - at));
    at = end;
  }
  return out;
}

bool number(const std::string& text, double& value) {
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(parsed)) return false;
  value = parsed;
  return true;
}

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

bool isRotaryLetter(char c) { return std::string("ABCUVW").find(c) != std::string::npos; }

// Walks the program's lines before `end`, calling `axis(name, isStepper, value, kind)` for every rotary word:
// kind 'S' sets (G92, SET_POSITION), 'M' moves to the absolute value, 'R' moves by it (G91).
template <typename Visit>
void walkAxes(const std::string& text, std::size_t end, Visit axis) {
  bool relative = false;
  std::size_t begin = 0;
  while (begin < std::min(end, text.size())) {
    std::size_t lineEnd = text.find('\n', begin);
    if (lineEnd == std::string::npos) lineEnd = text.size();
    const std::string code = commandOf(text.substr(begin, lineEnd - begin));
    begin = lineEnd + 1;
    if (code.empty()) continue;
    const std::vector<std::string> w = words(code);
    const std::string head = upper(w[0]);
    if (head == "G90") relative = false;
    if (head == "G91") relative = true;
    if (head == "MANUAL_STEPPER") {
      std::string stepper;
      for (const std::string& word : w)
        if (upper(word.substr(0, 8)) == "STEPPER=") stepper = word.substr(8);
      if (stepper.empty()) continue;
      bool named = false;
      double value = 0;
      for (const std::string& word : w) {
        const std::string key = upper(word.substr(0, word.find('=')));
        const std::string rest = word.find('=') == std::string::npos ? "" : word.substr(word.find('=') + 1);
        if (key == "SET_POSITION" && number(rest, value)) named = true, axis(stepper, true, value, 'S');
        if (key == "MOVE" && number(rest, value)) named = true, axis(stepper, true, value, 'M');
      }
      if (!named) axis(stepper, true, 0.0, 'N');  // enabled or named only
      continue;
    }
    const bool set = head == "G92";
    if (!set && head != "G0" && head != "G1") continue;
    for (std::size_t i = 1; i < w.size(); ++i) {
      const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(w[i][0])));
      double value = 0;
      if (!isRotaryLetter(letter) || !number(w[i].substr(1), value)) continue;
      axis(std::string(1, letter), false, value, set ? 'S' : (relative ? 'R' : 'M'));
    }
  }
}

std::size_t markerLine(const std::string& text, const std::string& marker) {
  std::size_t at = 0;
  while ((at = text.find(marker, at)) != std::string::npos) {
    const bool lineStart = at == 0 || text[at - 1] == '\n';
    const std::size_t after = at + marker.size();
    const bool lineEnd = after == text.size() || text[after] == '\n' || text[after] == '\r';
    if (lineStart && lineEnd) return at;
    at = after;
  }
  return std::string::npos;
}

std::string fixed(double value) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

}  // namespace

StitchedProgramAxes axesTheProgramUses(const std::string& text) {
  StitchedProgramAxes axes;
  walkAxes(text, text.size(), [&](const std::string& name, bool stepper, double, char) {
    std::vector<std::string>& list = stepper ? axes.manualSteppers : axes.letters;
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  });
  return axes;
}

std::map<std::string, double> axisCoordinatesBefore(const std::string& text, std::size_t end) {
  std::map<std::string, double> at;
  walkAxes(text, end, [&](const std::string& name, bool, double value, char kind) {
    if (kind == 'S' || kind == 'M') at[name] = value;
    if (kind == 'R') at[name] += value;
    if (kind == 'N' && !at.count(name)) at[name] = 0.0;
  });
  return at;
}

std::string resumedStitchedProgram(const std::string& text, int from, const std::string& file) {
  const std::string transitionMarker = "; MULTIDIR TRANSITION " + std::to_string(from - 1);
  const std::size_t transition = markerLine(text, transitionMarker);
  const std::size_t start = markerLine(text, "; MULTIDIR START SEQUENCE");
  const auto missing = [&](const std::string& marker) {
    return FileError("multidir run: " + file + " lacks the line '" + marker + "', which a run resumed at step " +
                     std::to_string(from) + " needs: was it stitched by this MultiDir? Slice the job again");
  };
  if (transition == std::string::npos) throw missing(transitionMarker);
  if (start == std::string::npos || start > transition) throw missing("; MULTIDIR START SEQUENCE");
  const std::map<std::string, double> at = axisCoordinatesBefore(text, transition);
  std::string out = text.substr(0, start);
  out += "; MultiDir: resumed at step " + std::to_string(from) +
         ": no homing and no purge line (the steps before it "
         "are on the platform); the platform's axes stand where step " +
         std::to_string(from - 1) + " printed\n";
  std::string letters;
  for (const auto& [name, value] : at) {
    if (name.size() == 1 && isRotaryLetter(name[0]))
      letters += " " + name + fixed(value);
    else
      out += "MANUAL_STEPPER STEPPER=" + name + " ENABLE=1 SET_POSITION=" + fixed(value) + "\n";
  }
  if (!letters.empty()) out += "G92" + letters + "\n";
  // No G90 or M82/M83 here: the transition sets the positioning mode itself before its first move, and a G90
  // would also switch Marlin's extruder to absolute distances.
  out += text.substr(transition);
  return out;
}

}  // namespace multidir::cli

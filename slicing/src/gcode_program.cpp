#include "multidir/slicing/gcode_program.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace multidir::slicing {

namespace {

using core::Error;
using core::ErrorCode;

struct Word {
  char letter;
  double value;
};

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// "G1 X10 Y2.5 E.3" -> words; false when a letter is followed by something that is not a number.
bool splitWords(const std::string& code, std::vector<Word>& words) {
  std::size_t i = 0;
  while (i < code.size()) {
    const unsigned char c = static_cast<unsigned char>(code[i]);
    if (std::isspace(c)) {
      ++i;
      continue;
    }
    if (!std::isalpha(c)) return false;
    const char* start = code.c_str() + i + 1;
    char* end = nullptr;
    const double value = std::strtod(start, &end);
    if (end == start || !std::isfinite(value)) return false;
    words.push_back({static_cast<char>(std::toupper(c)), value});
    i = static_cast<std::size_t>(end - code.c_str());
  }
  return true;
}

// The number after `key` ("MOVE=") in a Klipper command, if any.
bool klipperNumber(const std::string& code, const std::string& upperCode, const char* key, double& value) {
  const std::size_t at = upperCode.find(key);
  if (at == std::string::npos) return false;
  const std::size_t from = at + std::string(key).size();
  char* end = nullptr;
  value = std::strtod(code.c_str() + from, &end);
  return end != code.c_str() + from && std::isfinite(value);
}

// MANUAL_STEPPER STEPPER=name MOVE=deg | SET_POSITION=deg ...
struct ManualStepper {
  std::string stepper;  // upper case
  bool moves = false;
  bool setsPosition = false;
  double degrees = 0.0;
};

bool manualStepper(const std::string& code, ManualStepper& out) {
  const std::string u = upper(code);
  if (u.rfind("MANUAL_STEPPER", 0) != 0) return false;
  out = ManualStepper{};
  if (const std::size_t at = u.find("STEPPER=", 14); at != std::string::npos) {
    const std::size_t end = u.find_first_of(" \t", at);
    out.stepper = u.substr(at + 8, end == std::string::npos ? std::string::npos : end - at - 8);
  }
  out.moves = klipperNumber(code, u, "MOVE=", out.degrees);
  if (!out.moves) out.setsPosition = klipperNumber(code, u, "SET_POSITION=", out.degrees);
  return out.moves || out.setsPosition;
}

}  // namespace

core::Result<GcodeProgram> parseGcode(const std::string& text, const std::string& rotaryAxis, const std::string& name) {
  return parseGcode(text, std::vector<RotaryAxisName>{{rotaryAxis.empty() ? "A" : rotaryAxis, ""}}, name);
}

core::Result<GcodeProgram> parseGcode(const std::string& text, const std::vector<RotaryAxisName>& axes,
                                      const std::string& name) {
  const auto letterOf = [&](std::size_t i) {
    return i < axes.size() && !axes[i].letter.empty() ? static_cast<char>(std::toupper(axes[i].letter[0])) : '\0';
  };
  const char rotaryLetter = axes.empty() ? 'A' : letterOf(0);
  const char secondLetter = letterOf(1);
  const auto stepperOf = [&](std::size_t i) { return i < axes.size() ? upper(axes[i].klipperStepper) : std::string(); };
  const std::string rotaryStepper = stepperOf(0), secondStepper = stepperOf(1);
  GcodeProgram program;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double e = 0.0;
  double rotary = 0.0;
  double second = 0.0;
  bool absoluteXyz = true;
  bool absoluteE = true;
  int step = 0;
  bool inTransition = false;

  std::istringstream in(text);
  std::string line;
  int lineNumber = 0;
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
      }
    }
    std::string code = line.substr(0, semicolon);
    const std::size_t first = code.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    code = code.substr(first);
    while (!code.empty() && std::isspace(static_cast<unsigned char>(code.back()))) code.pop_back();

    ManualStepper manual;
    if (manualStepper(code, manual)) {
      // One axis: any manual stepper is the platform's (as before names were known); two: the one named.
      const bool isFirst = rotaryStepper.empty() || manual.stepper == rotaryStepper;
      const bool isSecond = !isFirst && !secondStepper.empty() && manual.stepper == secondStepper;
      if (manual.setsPosition) {
        if (isFirst) rotary = manual.degrees;
        if (isSecond) second = manual.degrees;
        continue;
      }
      GcodeMove move;
      move.line = lineNumber;
      move.from = move.to = position;
      move.rotaryFromDegrees = rotary;
      move.secondFromDegrees = second;
      if (isFirst) rotary = manual.degrees;
      if (isSecond) second = manual.degrees;
      move.rotaryToDegrees = rotary;
      move.secondToDegrees = second;
      move.commandsRotaryAxis = true;
      move.step = step;
      move.inTransition = inTransition;
      program.moves.push_back(move);
      continue;
    }
    const std::string head = upper(code.substr(0, code.find_first_of(" \t")));
    if (head != "G0" && head != "G1" && head != "G00" && head != "G01" && head != "G90" && head != "G91" &&
        head != "M82" && head != "M83" && head != "G92" && head != "G28" && head != "G10" && head != "G11")
      continue;  // temperatures, fans, Klipper macros...: no motion MultiDir needs to follow
    std::vector<Word> words;
    if (!splitWords(code, words))
      return Error{ErrorCode::MalformedFile, "line " + std::to_string(lineNumber) + " '" + code + "' is not G-code",
                   name};
    if (head == "G90") absoluteXyz = absoluteE = true;
    if (head == "G91") absoluteXyz = absoluteE = false;
    if (head == "M82") absoluteE = true;
    if (head == "M83") absoluteE = false;
    if (head == "G92") {
      for (std::size_t w = 1; w < words.size(); ++w) {
        const Word& word = words[w];
        if (word.letter == 'X') position.x() = word.value;
        if (word.letter == 'Y') position.y() = word.value;
        if (word.letter == 'Z') position.z() = word.value;
        if (word.letter == 'E') e = word.value;
        if (word.letter == rotaryLetter) rotary = word.value;
        if (secondLetter != '\0' && word.letter == secondLetter) second = word.value;
      }
      continue;
    }
    if (head == "G28") {
      // Homing ends at the printer's origin for the axes named (all when none is).
      bool any = false;
      for (std::size_t w = 1; w < words.size(); ++w) {
        const char l = words[w].letter;
        if (l == 'X' || l == 'Y' || l == 'Z') {
          position[l - 'X'] = 0.0;
          any = true;
        }
      }
      if (!any) position.setZero();
      continue;
    }
    if (head == "G90" || head == "G91" || head == "M82" || head == "M83") continue;
    if (head == "G10" || head == "G11") {
      if (words.size() > 1) continue;  // G10 P.. / L..: tool or work offsets, not a retraction
      GcodeMove move;
      move.line = lineNumber;
      move.from = move.to = position;
      move.rotaryFromDegrees = move.rotaryToDegrees = rotary;
      move.secondFromDegrees = move.secondToDegrees = second;
      move.step = step;
      move.inTransition = inTransition;
      move.firmwareRetraction =
          head == "G10" ? GcodeMove::FirmwareRetraction::Retract : GcodeMove::FirmwareRetraction::Unretract;
      program.moves.push_back(move);
      continue;
    }

    GcodeMove move;
    move.line = lineNumber;
    move.from = position;
    move.rotaryFromDegrees = rotary;
    move.secondFromDegrees = second;
    move.step = step;
    move.inTransition = inTransition;
    for (std::size_t w = 1; w < words.size(); ++w) {
      const Word& word = words[w];
      if (word.letter >= 'X' && word.letter <= 'Z') {
        const int axis = word.letter - 'X';
        position[axis] = absoluteXyz ? word.value : position[axis] + word.value;
      } else if (word.letter == 'E') {
        const double next = absoluteE ? word.value : e + word.value;
        move.filamentMm = next - e;
        e = next;
      } else if (word.letter == rotaryLetter) {
        rotary = absoluteXyz ? word.value : rotary + word.value;
        move.commandsRotaryAxis = true;
      } else if (secondLetter != '\0' && word.letter == secondLetter) {
        second = absoluteXyz ? word.value : second + word.value;
        move.commandsRotaryAxis = true;
      }
    }
    move.to = position;
    move.rotaryToDegrees = rotary;
    move.secondToDegrees = second;
    program.moves.push_back(move);
  }
  program.lineCount = lineNumber;
  return program;
}

}  // namespace multidir::slicing

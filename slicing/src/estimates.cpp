#include "multidir/slicing/estimates.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace multidir::slicing {

namespace {

// The number after "= " on a comment line that starts with `key`, searched from the end of the file, where
// PrusaSlicer writes them.
bool commentValue(const std::string& gcode, const std::string& key, std::string& value) {
  const std::size_t at = gcode.rfind("; " + key);
  if (at == std::string::npos) return false;
  const std::size_t eq = gcode.find('=', at);
  const std::size_t end = gcode.find('\n', at);
  if (eq == std::string::npos || (end != std::string::npos && eq > end)) return false;
  value = gcode.substr(eq + 1, end == std::string::npos ? std::string::npos : end - eq - 1);
  return true;
}

bool commentNumber(const std::string& gcode, const std::string& key, double& number) {
  std::string value;
  if (!commentValue(gcode, key, value)) return false;
  char* end = nullptr;
  number = std::strtod(value.c_str(), &end);
  return end != value.c_str() && std::isfinite(number);
}

}  // namespace

bool parseDuration(const std::string& text, double& seconds) {
  std::istringstream in(text);
  std::string part;
  seconds = 0.0;
  bool any = false;
  while (in >> part) {
    if (part.size() < 2) return false;
    const char unit = part.back();
    char* end = nullptr;
    const std::string digits = part.substr(0, part.size() - 1);
    const double n = std::strtod(digits.c_str(), &end);
    if (end != digits.c_str() + digits.size() || n < 0) return false;
    if (unit == 'd') seconds += n * 86400.0;
    else if (unit == 'h') seconds += n * 3600.0;
    else if (unit == 'm') seconds += n * 60.0;
    else if (unit == 's') seconds += n;
    else return false;
    any = true;
  }
  return any;
}

std::string durationText(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  char text[64];
  std::snprintf(text, sizeof text, "%ldh %02ldm %02lds", total / 3600, (total / 60) % 60, total % 60);
  return text;
}

double supportFilamentMm(const std::string& gcode) {
  double total = 0.0, lastE = 0.0;
  bool absoluteE = true, support = false;
  std::istringstream lines(gcode);
  std::string line;
  auto eWord = [](const std::string& code, double& e) {
    for (std::size_t at = code.find(' '); at != std::string::npos; at = code.find(' ', at + 1))
      if (at + 1 < code.size() && code[at + 1] == 'E') {
        char* end = nullptr;
        e = std::strtod(code.c_str() + at + 2, &end);
        return end != code.c_str() + at + 2;
      }
    return false;
  };
  while (std::getline(lines, line)) {
    if (line.rfind(";TYPE:", 0) == 0) {
      support = line.rfind(";TYPE:Support material", 0) == 0;
      continue;
    }
    const std::string code = line.substr(0, line.find(';'));
    if (code.rfind("M82", 0) == 0) absoluteE = true;
    if (code.rfind("M83", 0) == 0) absoluteE = false;
    double e = 0.0;
    if (code.rfind("G92", 0) == 0 && eWord(code, e)) lastE = e;
    if ((code.rfind("G1 ", 0) == 0 || code.rfind("G0 ", 0) == 0) && eWord(code, e)) {
      const double delta = absoluteE ? e - lastE : e;
      if (absoluteE) lastE = e;
      // Extrusion moves go somewhere; E-only moves are retracts and primes, which add nothing laid.
      const bool moves = code.find(" X") != std::string::npos || code.find(" Y") != std::string::npos;
      if (support && moves && delta > 0) total += delta;
    }
  }
  return total;
}

core::Result<Estimate> parseEstimate(const std::string& gcode, const std::string& name) {
  Estimate estimate;
  std::string time;
  if (!commentValue(gcode, "estimated printing time (normal mode)", time) || !parseDuration(time, estimate.printSeconds))
    return core::Error{core::ErrorCode::MalformedFile,
                       "no '; estimated printing time (normal mode) = ...' comment: not a complete PrusaSlicer G-code",
                       name};
  if (!commentNumber(gcode, "filament used [mm]", estimate.filamentMm))
    return core::Error{core::ErrorCode::MalformedFile,
                       "no '; filament used [mm] = ...' comment: not a complete PrusaSlicer G-code", name};
  commentNumber(gcode, "filament used [cm3]", estimate.filamentCm3);
  if (!commentNumber(gcode, "total filament used [g]", estimate.filamentGrams))
    commentNumber(gcode, "filament used [g]", estimate.filamentGrams);
  estimate.supportFilamentMm = supportFilamentMm(gcode);
  // The same filament: its volume per millimetre from the slicer's own totals.
  if (estimate.filamentMm > 0) estimate.supportCm3 = estimate.supportFilamentMm * estimate.filamentCm3 / estimate.filamentMm;
  return estimate;
}

}  // namespace multidir::slicing

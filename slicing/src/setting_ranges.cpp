#include "setting_ranges.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace multidir::slicing {
namespace {

using core::Error;
using core::ErrorCode;

struct Range {
  const char* key;
  double low;
  double high;
  bool lowIncluded;
  bool highIncluded;
  const char* unit;
  bool perExtruder;     // "0.4,0.4": one value per extruder
  bool percentAllowed;  // "150%" of another setting
};

// Temperatures: a hotend up to 500 °C (the hottest all-metal ones print PEEK near 450), a bed up to 200 °C;
// 0 leaves the heater off. Lengths and heights within a printer; speeds up to 2 m/s (well above any printer).
constexpr Range kRanges[] = {
    {"temperature", 0.0, 500.0, true, true, "°C", true, false},
    {"first_layer_temperature", 0.0, 500.0, true, true, "°C", true, false},
    {"bed_temperature", 0.0, 200.0, true, true, "°C", true, false},
    {"first_layer_bed_temperature", 0.0, 200.0, true, true, "°C", true, false},
    {"max_print_height", 0.0, kMaxPrinterCoordinateMm, false, true, "mm", false, false},
    {"nozzle_diameter", 0.0, 10.0, false, false, "mm", true, false},
    {"layer_height", 0.0, 10.0, false, false, "mm", false, false},
    {"first_layer_height", 0.0, 10.0, false, false, "mm", false, true},
    {"extrusion_width", 0.0, 10.0, true, false, "mm", false, true},
    {"retract_length", 0.0, 50.0, true, false, "mm", true, false},
    {"retract_restart_extra", -50.0, 50.0, true, true, "mm", true, false},
    {"retract_speed", 0.0, 2000.0, false, true, "mm/s", true, false},
    {"deretract_speed", 0.0, 2000.0, true, true, "mm/s", true, false},
    {"travel_speed", 0.0, 2000.0, false, true, "mm/s", false, false},
    // MultiDir's own numbers for two firmware axes (the profile's multidir.* comment keys): a tilt axis' zero and
    // limits within one turn either way; a rotation axis may be continuous, so its limits go to 100000 degrees
    // (some 280 turns) and its zero within a turn; the tilt axis' height is a printer coordinate.
    {"multidir.tilt_zero", -360.0, 360.0, true, true, "degrees", false, false},
    {"multidir.tilt_min", -360.0, 360.0, true, true, "degrees", false, false},
    {"multidir.tilt_max", -360.0, 360.0, true, true, "degrees", false, false},
    {"multidir.rotation_zero", -360.0, 360.0, true, true, "degrees", false, false},
    {"multidir.rotation_min", -100000.0, 100000.0, true, true, "degrees", false, false},
    {"multidir.rotation_max", -100000.0, 100000.0, true, true, "degrees", false, false},
    {"multidir.platform_radius", 0.0, 10000.0, true, true, "mm", false, false},
    {"multidir.platform_thickness", 0.0, 1000.0, true, true, "mm", false, false},
    {"multidir.tilt_height", -kMaxPrinterCoordinateMm, kMaxPrinterCoordinateMm, true, true, "mm", false, false},
};

// Percentages: of a layer height or a nozzle, 1000 % at most.
constexpr double kMaxPercent = 1000.0;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string rangeText(const Range& r) {
  std::string text = std::string(r.unit) + " in " + (r.lowIncluded ? "[" : "(") + number(r.low) + ", " +
                     number(r.high) + (r.highIncluded ? "]" : ")");
  if (r.percentAllowed) text += " or a percentage in (0, " + number(kMaxPercent) + "]";
  if (r.perExtruder) text += ", one value per extruder separated by commas";
  return text;
}

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

core::Status checkOne(const Range& r, const std::string& text, const std::string& where) {
  const std::string t = trimmed(text);
  const bool percent = r.percentAllowed && !t.empty() && t.back() == '%';
  const std::string digits = percent ? t.substr(0, t.size() - 1) : t;
  char* end = nullptr;
  const double value = digits.empty() ? 0.0 : std::strtod(digits.c_str(), &end);
  if (digits.empty() || end != digits.c_str() + digits.size() || !std::isfinite(value))
    return Error{ErrorCode::MalformedFile, "'" + t + "' is not a finite number: give " + rangeText(r), where};
  const bool inRange = percent ? value > 0.0 && value <= kMaxPercent
                               : (r.lowIncluded ? value >= r.low : value > r.low) &&
                                     (r.highIncluded ? value <= r.high : value < r.high);
  if (!inRange) return Error{ErrorCode::InvalidParameter, "'" + t + "' is out of range: give " + rangeText(r), where};
  return core::Done{};
}

}  // namespace

core::Status checkSettingValue(const std::string& key, const std::string& value, const std::string& where) {
  for (const Range& r : kRanges) {
    if (key != r.key) continue;
    if (!r.perExtruder || trimmed(value).empty()) return checkOne(r, value, where);
    std::istringstream values(value);
    std::string one;
    while (std::getline(values, one, ','))
      if (core::Status s = checkOne(r, one, where); !s) return s;
    return core::Done{};
  }
  return core::Done{};
}

std::string coordinateRangeText() {
  return "mm in [" + number(-kMaxPrinterCoordinateMm) + ", " + number(kMaxPrinterCoordinateMm) + "]";
}

}  // namespace multidir::slicing

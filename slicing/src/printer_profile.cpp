#include "multidir/slicing/printer_profile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include "setting_ranges.h"

namespace multidir::slicing {

namespace {

namespace fs = std::filesystem;
using core::Error;
using core::ErrorCode;

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const std::size_t last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

bool parseDouble(const std::string& text, double& value) {
  const std::string t = trimmed(text);
  if (t.empty()) return false;
  char* end = nullptr;
  value = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size() && std::isfinite(value);
}

// "x,y" (platform_center, park) or "XxY" (a bed corner).
bool parsePair(const std::string& text, char separator, Eigen::Vector2d& point) {
  const std::size_t at = text.find(separator);
  if (at == std::string::npos) return false;
  return parseDouble(text.substr(0, at), point.x()) && parseDouble(text.substr(at + 1), point.y());
}

// The first value of a per-extruder list ("0.4,0.4").
std::string firstOfList(const std::string& text) { return trimmed(text.substr(0, text.find(','))); }

double polygonArea(const std::vector<Eigen::Vector2d>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

std::string resolvePath(const std::string& pathOrName) {
  std::error_code ec;
  if (fs::is_regular_file(pathOrName, ec)) return pathOrName;
  const bool endsInIni = pathOrName.size() > 4 && pathOrName.compare(pathOrName.size() - 4, 4, ".ini") == 0;
  if (!pathOrName.empty() && pathOrName.find('/') == std::string::npos && !endsInIni) {
    const fs::path shipped = fs::path(MULTIDIR_PRINTERS_DIR) / (pathOrName + ".ini");
    if (fs::is_regular_file(shipped, ec)) return shipped.string();
  }
  return {};
}

std::string shippedList() {
  std::string list;
  for (const std::string& name : builtinPrinterNames()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// One multidir.tilt_* / rotation_* / axis_mount / klipper_*_stepper key of a firmware-2axis printer.
core::Status readTwoAxisKey(const std::string& key, const std::string& value, const std::string& at,
                            TwoAxisPlatform& axes, bool& rotationCenterGiven) {
  if (key == "axis_mount") {
    if (value == "rotation-on-tilt") return core::Done{};
    if (value == "tilt-on-rotation")
      return Error{ErrorCode::InvalidParameter,
                   "'tilt-on-rotation' (a tilt axis carried by a turntable) is not supported: MultiDir drives the "
                   "Open5x arrangement only, the rotation axis riding on the tilt cradle (rotation-on-tilt)",
                   at};
    return Error{ErrorCode::InvalidParameter, "'" + value + "': use rotation-on-tilt (the rotation axis riding on "
                 "the tilt cradle, as Open5x; the only arrangement supported)", at};
  }
  if (key == "klipper_tilt_stepper" || key == "klipper_rotation_stepper") {
    if (value.empty() || value.find_first_of(" \t=") != std::string::npos)
      return Error{ErrorCode::InvalidParameter, "'" + value + "' is not a stepper name: give a [manual_stepper]'s name",
                   at};
    (key == "klipper_tilt_stepper" ? axes.tilt : axes.rotation).klipperStepper = value;
    return core::Done{};
  }
  const bool tilt = key.rfind("tilt_", 0) == 0;
  FirmwareRotaryAxis& axis = tilt ? axes.tilt : axes.rotation;
  const std::string field = key.substr(tilt ? 5 : 9);
  if (field == "axis") {
    if (value.size() != 1 || std::string("ABCUVW").find(value[0]) == std::string::npos)
      return Error{ErrorCode::InvalidParameter, "'" + value + "': one of the letters A B C U V W", at};
    axis.letter = value;
    return core::Done{};
  }
  if (field == "direction") {
    double sign = 0.0;
    if (!parseDouble(value, sign) || (sign != 1.0 && sign != -1.0))
      return Error{ErrorCode::InvalidParameter, "'" + value + "': give 1 (the axis counts as the convention's angle) "
                   "or -1 (against it; docs/slicing.md \"Two firmware axes\")", at};
    axis.direction = sign;
    return core::Done{};
  }
  if (tilt && field == "along") {
    if (value == "X" || value == "x") axes.tiltAlong = TiltAlong::X;
    else if (value == "Y" || value == "y") axes.tiltAlong = TiltAlong::Y;
    else return Error{ErrorCode::InvalidParameter, "'" + value + "': X or Y, the printer axis the tilt axis runs along", at};
    return core::Done{};
  }
  if (!tilt && field == "center") {
    Eigen::Vector2d p;
    if (!parsePair(value, ',', p))
      return Error{ErrorCode::MalformedFile, "'" + value + "' is not X,Y: give X and Y in " + coordinateRangeText(), at};
    if (std::abs(p.x()) > kMaxPrinterCoordinateMm || std::abs(p.y()) > kMaxPrinterCoordinateMm)
      return Error{ErrorCode::InvalidParameter, "'" + value + "' is out of range: give X and Y in " + coordinateRangeText(),
                   at};
    axes.rotationCenter = p;
    rotationCenterGiven = true;
    return core::Done{};
  }
  double* number = field == "zero" ? &axis.zeroDegrees
                   : field == "min" ? &axis.minDegrees
                   : field == "max" ? &axis.maxDegrees
                   : tilt && field == "height" ? &axes.tiltHeightMm
                                               : nullptr;
  if (!number) return Error{ErrorCode::MalformedFile, "unknown MultiDir key (see docs/slicing.md)", at};
  // The range, and the message naming it, live with every other numeric setting's (setting_ranges.h).
  if (core::Status s = checkSettingValue("multidir." + key, value, at); !s) return s;
  parseDouble(value, *number);
  return core::Done{};
}

// What no single key can say: each axis' limits in order, two different letters.
core::Status checkTwoAxisTogether(const TwoAxisPlatform& axes, const std::string& at) {
  for (const auto& [axis, name] : {std::pair<const FirmwareRotaryAxis*, std::string>{&axes.tilt, "tilt"},
                                   {&axes.rotation, "rotation"}})
    if (!(axis->minDegrees < axis->maxDegrees))
      return Error{ErrorCode::InvalidParameter,
                   name + "_min (" + shortNumber(axis->minDegrees) + ") is not below " + name + "_max (" +
                       shortNumber(axis->maxDegrees) + "): give the lower limit first",
                   at + name + "_min"};
  if (axes.tilt.letter == axes.rotation.letter)
    return Error{ErrorCode::InvalidParameter,
                 "the tilt and the rotation axis are both " + axes.tilt.letter + ": give each its own letter",
                 at + "rotation_axis"};
  return core::Done{};
}

}  // namespace

const char* platformDriveName(PlatformDrive drive) {
  switch (drive) {
    case PlatformDrive::None: return "none";
    case PlatformDrive::FirmwareAxis: return "firmware-axis";
    case PlatformDrive::Modbus: return "modbus";
    case PlatformDrive::FirmwareTwoAxis: return "firmware-2axis";
  }
  return "none";
}

const char* dialectName(Dialect dialect) {
  switch (dialect) {
    case Dialect::Klipper: return "klipper";
    case Dialect::Marlin: return "marlin";
    case Dialect::RepRapFirmware: return "rrf";
  }
  return "marlin";
}

core::Result<Dialect> parseDialect(const std::string& text) {
  if (text == "klipper") return Dialect::Klipper;
  if (text == "marlin") return Dialect::Marlin;
  if (text == "rrf" || text == "reprapfirmware") return Dialect::RepRapFirmware;
  return Error{ErrorCode::InvalidParameter, "unknown dialect '" + text + "': use klipper, marlin or rrf", "dialect"};
}

Eigen::Vector2d PrinterProfile::bedMin() const {
  Eigen::Vector2d low = Eigen::Vector2d::Constant(0.0);
  if (bedShape.empty()) return low;
  low = bedShape.front();
  for (const Eigen::Vector2d& p : bedShape) low = low.cwiseMin(p);
  return low;
}

Eigen::Vector2d PrinterProfile::bedMax() const {
  Eigen::Vector2d high = Eigen::Vector2d::Constant(0.0);
  if (bedShape.empty()) return high;
  high = bedShape.front();
  for (const Eigen::Vector2d& p : bedShape) high = high.cwiseMax(p);
  return high;
}

std::vector<std::string> builtinPrinterNames() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(MULTIDIR_PRINTERS_DIR, ec))
    if (entry.path().extension() == ".ini") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

core::Result<PrinterProfile> loadPrinterProfile(const std::string& pathOrName) {
  const std::string path = resolvePath(pathOrName);
  if (path.empty())
    return Error{ErrorCode::FileNotFound,
                 "no printer profile of that name or path; give a PrusaSlicer .ini or one of: " + shippedList(),
                 pathOrName};
  std::ifstream in(path);
  if (!in) return Error{ErrorCode::FileNotFound, "cannot open the printer profile", path};

  PrinterProfile profile;
  profile.path = path;
  profile.name = fs::path(path).stem().string();
  std::map<std::string, std::string> own;  // multidir.* keys
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    std::string text = trimmed(line);
    if (text.empty()) continue;
    bool multidirKey = false;
    if (text[0] == '#' || text[0] == ';') {
      const std::string comment = trimmed(text.substr(1));
      if (comment.rfind("multidir.", 0) != 0) continue;
      text = comment.substr(9);
      multidirKey = true;
    }
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) {
      if (text[0] == '[') continue;  // a section header of a PrusaSlicer bundle
      return Error{ErrorCode::MalformedFile, "line " + std::to_string(lineNumber) + " is not 'key = value'", path};
    }
    (multidirKey ? own : profile.settings)[trimmed(text.substr(0, eq))] = trimmed(text.substr(eq + 1));
  }

  const auto where = [&](const std::string& key) { return path + ": " + key; };
  // Every numeric slicer setting MultiDir reads or passes on, finite and within a printer's range
  // (setting_ranges.h), before any of them is used.
  for (const auto& [key, value] : profile.settings)
    if (core::Status s = checkSettingValue(key, value, where(key)); !s) return s.error();
  const auto coordinate = [](double v) { return std::abs(v) <= kMaxPrinterCoordinateMm; };
  const auto number = [&](const std::map<std::string, std::string>& from, const std::string& key, double& value,
                          bool list) -> core::Status {
    const auto it = from.find(key);
    if (it == from.end()) return core::Done{};
    if (!parseDouble(list ? firstOfList(it->second) : it->second, value))
      return Error{ErrorCode::MalformedFile, "'" + it->second + "' is not a number", where(key)};
    return core::Done{};
  };

  // Bed: PrusaSlicer's default when absent.
  const std::string bedText =
      profile.settings.count("bed_shape") ? profile.settings["bed_shape"] : "0x0,200x0,200x200,0x200";
  std::istringstream corners(bedText);
  std::string corner;
  while (std::getline(corners, corner, ',')) {
    Eigen::Vector2d p;
    if (!parsePair(corner, 'x', p))
      return Error{ErrorCode::MalformedFile,
                   "corner '" + trimmed(corner) + "' is not XxY: give the bed's corners as XxY pairs (0x0,220x0,...)",
                   where("bed_shape")};
    if (!coordinate(p.x()) || !coordinate(p.y()))
      return Error{ErrorCode::InvalidParameter,
                   "corner '" + trimmed(corner) + "' is out of range: give each corner's X and Y in " +
                       coordinateRangeText(),
                   where("bed_shape")};
    profile.bedShape.push_back(p);
  }
  if (profile.bedShape.size() < 3 || polygonArea(profile.bedShape) <= 1e-6)
    return Error{ErrorCode::InvalidParameter,
                 "bed_shape '" + bedText + "' has no area: give the bed's corners as XxY pairs (0x0,220x0,220x220,0x220)",
                 where("bed_shape")};

  for (const auto& [key, value, list] : {std::tuple<const char*, double*, bool>{"max_print_height", &profile.maxPrintHeightMm, false},
                                         {"nozzle_diameter", &profile.nozzleDiameterMm, true},
                                         {"retract_length", &profile.retractLengthMm, true},
                                         {"travel_speed", &profile.travelSpeedMmPerS, false}})
    if (core::Status s = number(profile.settings, key, *value, list); !s) return s.error();
  if (profile.settings.count("start_gcode")) profile.startGcode = profile.settings["start_gcode"];
  if (profile.settings.count("end_gcode")) profile.endGcode = profile.settings["end_gcode"];

  // MultiDir's keys.
  const auto ownWhere = [&](const std::string& key) { return where("multidir." + key); };
  profile.platformCenter = 0.5 * (profile.bedMin() + profile.bedMax());
  profile.park = profile.bedMin();
  bool rotationCenterGiven = false;
  for (const auto& [key, value] : own) {
    if (key == "name") {
      profile.name = value;
    } else if (key == "platform") {
      if (value == "none") profile.platform = PlatformDrive::None;
      else if (value == "firmware-axis") profile.platform = PlatformDrive::FirmwareAxis;
      else if (value == "firmware-2axis") profile.platform = PlatformDrive::FirmwareTwoAxis;
      else if (value == "modbus") profile.platform = PlatformDrive::Modbus;
      else return Error{ErrorCode::InvalidParameter, "'" + value + "': use none, firmware-axis, firmware-2axis or modbus",
                        ownWhere(key)};
    } else if (key == "dialect") {
      const core::Result<Dialect> d = parseDialect(value);
      if (!d) return Error{ErrorCode::InvalidParameter, d.error().message, ownWhere(key)};
      profile.dialect = *d;
    } else if (key == "rotary_axis") {
      if (value.size() != 1 || std::string("ABCUVW").find(value[0]) == std::string::npos)
        return Error{ErrorCode::InvalidParameter, "'" + value + "': one of the letters A B C U V W", ownWhere(key)};
      profile.rotaryAxis = value;
    } else if (key == "klipper_stepper") {
      if (value.empty() || value.find_first_of(" \t=") != std::string::npos)
        return Error{ErrorCode::InvalidParameter, "'" + value + "' is not a stepper name", ownWhere(key)};
      profile.klipperStepper = value;
    } else if (key == "rotary_feed") {
      // 100000 degrees per minute: more than four turns a second, beyond any platform.
      if (!parseDouble(value, profile.rotaryFeedDegreesPerMin) || profile.rotaryFeedDegreesPerMin <= 0.0 ||
          profile.rotaryFeedDegreesPerMin > 100000.0)
        return Error{ErrorCode::InvalidParameter, "'" + value + "' is out of range: give degrees per minute in (0, 100000]",
                     ownWhere(key)};
    } else if (key == "platform_center" || key == "park") {
      Eigen::Vector2d p;
      if (!parsePair(value, ',', p))
        return Error{ErrorCode::MalformedFile, "'" + value + "' is not X,Y: give X and Y in " + coordinateRangeText(),
                     ownWhere(key)};
      if (!coordinate(p.x()) || !coordinate(p.y()))
        return Error{ErrorCode::InvalidParameter,
                     "'" + value + "' is out of range: give X and Y in " + coordinateRangeText(), ownWhere(key)};
      (key == "park" ? profile.park : profile.platformCenter) = p;
    } else if (key == "platform_z") {
      if (!parseDouble(value, profile.platformZMm))
        return Error{ErrorCode::MalformedFile, "'" + value + "' is not a number: give " + coordinateRangeText(),
                     ownWhere(key)};
      if (!coordinate(profile.platformZMm))
        return Error{ErrorCode::InvalidParameter, "'" + value + "' is out of range: give " + coordinateRangeText(),
                     ownWhere(key)};
    } else if (key == "clearance_margin") {
      if (!parseDouble(value, profile.clearanceMarginMm) || profile.clearanceMarginMm < 0.0 || profile.clearanceMarginMm > 1000.0)
        return Error{ErrorCode::InvalidParameter, "'" + value + "' is out of range: give mm in [0, 1000]", ownWhere(key)};
    } else if (key == "step_start_gcode") {
      profile.stepStartGcode = value;
    } else if (key == "platform_radius" || key == "platform_thickness") {
      if (core::Status s = checkSettingValue("multidir." + key, value, ownWhere(key)); !s) return s.error();
      parseDouble(value, key == "platform_radius" ? profile.twoAxis.platformRadiusMm : profile.twoAxis.platformThicknessMm);
    } else if (key == "cradle_box") {
      std::vector<double> corners;
      std::stringstream list(value);
      std::string item;
      while (std::getline(list, item, ',')) {
        double v = 0.0;
        if (!parseDouble(item, v))
          return Error{ErrorCode::MalformedFile, "'" + value + "' is not six numbers: give Xmin,Ymin,Zmin,Xmax,Ymax,Zmax "
                       "in mm (printer coordinates with the tilt at zero)", ownWhere(key)};
        corners.push_back(v);
      }
      if (corners.size() != 6)
        return Error{ErrorCode::MalformedFile, "'" + value + "' is not six numbers: give Xmin,Ymin,Zmin,Xmax,Ymax,Zmax "
                     "in mm (printer coordinates with the tilt at zero)", ownWhere(key)};
      for (double v : corners)
        if (!coordinate(v))
          return Error{ErrorCode::InvalidParameter, "'" + value + "' is out of range: give each in " + coordinateRangeText(),
                       ownWhere(key)};
      const Eigen::Vector3d lo(corners[0], corners[1], corners[2]), hi(corners[3], corners[4], corners[5]);
      if (!(lo.array() < hi.array()).all())
        return Error{ErrorCode::InvalidParameter, "'" + value + "': each minimum must be below its maximum (Xmin,Ymin,Zmin,"
                     "Xmax,Ymax,Zmax)", ownWhere(key)};
      profile.twoAxis.cradle = Eigen::AlignedBox3d(lo, hi);
    } else if (key.rfind("tilt_", 0) == 0 || key.rfind("rotation_", 0) == 0 || key == "axis_mount" ||
               key == "klipper_tilt_stepper" || key == "klipper_rotation_stepper") {
      if (core::Status s = readTwoAxisKey(key, value, ownWhere(key), profile.twoAxis, rotationCenterGiven); !s)
        return s.error();
    } else {
      return Error{ErrorCode::MalformedFile, "unknown MultiDir key (see docs/slicing.md)", ownWhere(key)};
    }
  }
  if (!rotationCenterGiven) profile.twoAxis.rotationCenter = profile.platformCenter;
  if (core::Status s = checkTwoAxisTogether(profile.twoAxis, where("multidir.")); !s) return s.error();
  return profile;
}

core::Result<std::vector<std::pair<std::string, std::string>>> parseSettingAssignments(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> settings;
  std::istringstream words(text);
  std::string pair;
  while (words >> pair) {
    const std::size_t eq = pair.find('=');
    if (eq == std::string::npos || eq == 0)
      return core::Error{core::ErrorCode::InvalidParameter, "'" + pair + "' is not KEY=VALUE (layer_height=0.3)",
                         "slicer settings"};
    settings.emplace_back(pair.substr(0, eq), pair.substr(eq + 1));
  }
  return settings;
}

}  // namespace multidir::slicing

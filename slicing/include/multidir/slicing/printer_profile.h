#pragma once
// A printer as MultiDir slices for it: a PrusaSlicer .ini (every slicer setting, loaded as it is by the
// slicer) plus MultiDir's own keys, written as comment lines the slicer ignores:
//
//   # multidir.platform = firmware-axis      none | firmware-axis | firmware-2axis | modbus: who turns it
//   # multidir.dialect = klipper             klipper | marlin | rrf: how a firmware axis is turned
//   # multidir.rotary_axis = A               the G-code axis letter of the platform
//   # multidir.klipper_stepper = rotary_a    Klipper: the [manual_stepper] that drives it
//   # multidir.rotary_feed = 1800            degrees per minute while turning
//   # multidir.platform_center = 110,110     printer XY of the platform centre (default: the bed's centre)
//   # multidir.platform_z = 0                printer Z of the platform plane at rest
//   # multidir.park = 5,215                  printer XY where the nozzle waits while the platform turns
//   # multidir.clearance_margin = 5          mm above the swept part while the platform turns
//   # multidir.step_start_gcode = G92 E0     start of steps 2.. (they print on plastic: no homing or purge)
//
// firmware-2axis (two_axis.h: a tilt axis with the rotation axis riding on its cradle, as Open5x):
//   # multidir.axis_mount = rotation-on-tilt the only arrangement supported
//   # multidir.tilt_axis = U                 G-code letters of the two axes (A B C U V W, different)
//   # multidir.rotation_axis = V
//   # multidir.tilt_zero = 0                 each axis' coordinate at rest (level; azimuth 0), degrees
//   # multidir.tilt_direction = 1            +1 or -1: the axis' coordinate per degree of the convention's angle
//   # multidir.tilt_min = -90                each axis' limits in its own coordinate, degrees
//   # multidir.tilt_max = 90                 (and rotation_zero, rotation_direction, rotation_min, rotation_max)
//   # multidir.tilt_along = X                X | Y: the printer axis the tilt axis runs along
//   # multidir.tilt_height = 0               printer Z of the tilt axis, mm
//   # multidir.rotation_center = 110,110     printer XY of the rotation axis at tilt zero (default: platform_center)
//   # multidir.klipper_tilt_stepper = tilt   Klipper: the [manual_stepper]s that drive them
//   # multidir.klipper_rotation_stepper = rotation
//   # multidir.platform_radius = 0           the rotary table's radius (0: the plan's platform disc), mm
//   # multidir.platform_thickness = 5        its thickness below the platform plane, mm
//   # multidir.cradle_box = 60,70,-40,160,150,-5   the tilt cradle: a box in printer coordinates at tilt zero
//
// Shipped profiles live in resources/printers/NAME.ini (marlin-220, klipper-rotary, robot-0.8, open5x-rrf,
// klipper-2axis); the format is documented in docs/slicing.md.
#include <Eigen/Core>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/slicing/two_axis.h"

namespace multidir::slicing {

// Who turns the platform between steps.
enum class PlatformDrive {
  None,          // an ordinary printer: it can print the first step only
  FirmwareAxis,  // the printer's firmware (an A axis): one stitched program, job.gcode
  Modbus,        // MultiDir over Modbus (the hardware panel's print run): one program per step
  FirmwareTwoAxis,  // the firmware's tilt and rotation axes (Open5x, two_axis.h): one stitched program, job.gcode
};

// How a firmware axis is driven.
enum class Dialect { Klipper, Marlin, RepRapFirmware };

const char* platformDriveName(PlatformDrive drive);  // "none", "firmware-axis", "firmware-2axis", "modbus"
const char* dialectName(Dialect dialect);            // "klipper", "marlin", "rrf"
// Errors: InvalidParameter listing the dialects there are.
core::Result<Dialect> parseDialect(const std::string& text);

struct PrinterProfile {
  std::string path;  // the .ini
  std::string name;  // multidir.name, else the file's stem

  // From the slicer settings (defaults are PrusaSlicer's own when the .ini leaves a key out).
  std::vector<Eigen::Vector2d> bedShape;  // bed_shape: the bed polygon, printer XY (mm)
  double maxPrintHeightMm = 200.0;        // max_print_height
  double nozzleDiameterMm = 0.4;          // nozzle_diameter (first extruder)
  double retractLengthMm = 2.0;           // retract_length (first extruder)
  double travelSpeedMmPerS = 130.0;       // travel_speed
  std::string startGcode;                 // start_gcode, escaped as in the .ini ("\n" for new lines)
  std::string endGcode;                   // end_gcode, escaped likewise

  // MultiDir's keys.
  PlatformDrive platform = PlatformDrive::None;
  Dialect dialect = Dialect::Marlin;
  std::string rotaryAxis = "A";
  std::string klipperStepper = "rotary_a";
  double rotaryFeedDegreesPerMin = 1800.0;
  Eigen::Vector2d platformCenter = Eigen::Vector2d::Zero();
  double platformZMm = 0.0;
  Eigen::Vector2d park = Eigen::Vector2d::Zero();
  double clearanceMarginMm = 5.0;
  std::string stepStartGcode = "G92 E0";  // escaped as in the .ini
  TwoAxisPlatform twoAxis;                 // firmware-2axis: the two axes (rotationCenter defaults to platformCenter)

  // Every `key = value` setting of the .ini, for the slicer's keys not listed above.
  std::map<std::string, std::string> settings;

  Eigen::Vector2d bedMin() const;  // bounding box of bedShape
  Eigen::Vector2d bedMax() const;
};

// The shipped profiles' names, sorted ("klipper-2axis", "klipper-rotary", "marlin-220", "open5x-rrf", "robot-0.8").
std::vector<std::string> builtinPrinterNames();

// Reads a profile: a path to a .ini, or the name of a shipped one. Checks bed_shape (at least three corners,
// positive area, each coordinate within +-10000 mm), every numeric slicer setting MultiDir reads or passes on
// (temperatures, heights, nozzle, layer heights, widths, retraction, speeds: finite and within a physical
// range, docs/slicing.md "Printer profiles") and every multidir.* key, naming the first that is wrong with the
// file, the key and the range: "my.ini: temperature: '1e308' is out of range: give °C in [0, 500], ...".
// Errors: FileNotFound (no such file or shipped name; the message lists the shipped names), MalformedFile
// (a line or value that cannot be read, a number that is not finite), InvalidParameter (a value out of range).
core::Result<PrinterProfile> loadPrinterProfile(const std::string& pathOrName);

// Slicer settings typed as text, "KEY=VALUE KEY=VALUE" separated by white space ("layer_height=0.3
// fill_density=0%"), in order: what `multidir slice --set` and the studio's Slice dialog take. Empty text: none.
// Errors: InvalidParameter naming the first word that is not KEY=VALUE.
core::Result<std::vector<std::pair<std::string, std::string>>> parseSettingAssignments(const std::string& text);

}  // namespace multidir::slicing

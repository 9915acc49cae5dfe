#pragma once
// The physical range of every numeric setting MultiDir reads from a printer profile or passes to the slicer
// (the profile's own, the --set overrides, the first-layer temperatures it derives for later steps). The slicer
// takes whatever it is given: a temperature of 1e308 became `M104 S1` (cast to an int), a bed of 1e308 mm
// overflowed every placement. So each value must be finite and within what a printer can do, and a value that
// is not is refused naming the file, the key and the range.
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::slicing {

// The largest printer coordinate MultiDir accepts, mm: 10 m, beyond any printer it drives and far below where
// doubles lose a micrometre.
constexpr double kMaxPrinterCoordinateMm = 10000.0;

// Checks a numeric value against its key's range when the key has one (other keys pass): every value of a
// per-extruder list ("205,210"), a percentage where the slicer takes one ("150%"). `where` names the file and
// key ("my.ini: temperature"). Errors: MalformedFile (not a finite number), InvalidParameter (out of range); the
// message gives the range and its unit.
core::Status checkSettingValue(const std::string& key, const std::string& value, const std::string& where);

// "mm in [-10000, 10000]": the range of a printer coordinate, for messages.
std::string coordinateRangeText();

}  // namespace multidir::slicing

#pragma once
// Print time and filament, as the slicer states them in its G-code's closing comments:
//   ; filament used [mm] = 1499.18
//   ; filament used [cm3] = 3.61
//   ; total filament used [g] = 4.47          (0 when the profile gives no filament density)
//   ; estimated printing time (normal mode) = 1h 13m 58s
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::slicing {

struct Estimate {
  double printSeconds = 0.0;
  double filamentMm = 0.0;
  double filamentCm3 = 0.0;
  double filamentGrams = 0.0;  // 0 when the profile has no filament density
  // Of the filament, what the slicer lays as support (";TYPE:Support material" and its interface): the
  // support volume the assembly sheet and docs/apart.md compare.
  double supportFilamentMm = 0.0;
  double supportCm3 = 0.0;

  Estimate& operator+=(const Estimate& other) {
    printSeconds += other.printSeconds;
    filamentMm += other.filamentMm;
    filamentCm3 += other.filamentCm3;
    filamentGrams += other.filamentGrams;
    supportFilamentMm += other.supportFilamentMm;
    supportCm3 += other.supportCm3;
    return *this;
  }
};

// "1d 2h 3m 4s", "13m 58s", "45s" -> seconds; false for anything else.
bool parseDuration(const std::string& text, double& seconds);

// "1h 02m 03s" style text of a duration (whole seconds).
std::string durationText(double seconds);

// Reads the estimate comments of a PrusaSlicer G-code. Errors: MalformedFile naming `name` when the time or
// the filament length is missing (a G-code not written by PrusaSlicer, or cut short).
// The filament extruded under the slicer's support features (";TYPE:Support material", ";TYPE:Support material
// interface") by moves in X or Y (retracts and primes excepted), following M82/M83 and G92 E (mm of filament).
double supportFilamentMm(const std::string& gcode);

core::Result<Estimate> parseEstimate(const std::string& gcode, const std::string& name);

}  // namespace multidir::slicing

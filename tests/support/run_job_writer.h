#pragma once
// Sliced print jobs as `multidir slice` writes them, for the `multidir run` tests, and the machine profile of
// the platform they were made for.
#include <string>

namespace multidir::test {

// Step k's program (a "; MULTIDIR STEP k" section): heats (about 18 simulated seconds), then 20 moves of 10 mm
// at 1200 mm/min at z 0.3; `heatersLeftOn`: the bed heated too and both left on at the end, for the next step
// (as robot-0.8.ini's end G-code leaves the bed on).
std::string stepGcode(int step, bool heatersLeftOn = false);

// A sliced job of two steps in `dir`, G-code beside it, sliced for marlin-220 (a Modbus platform): 4-DOF at 0
// and 30 degrees (90 with `heatersLeftOn`, a long turn), or 5-DOF at tilt 0 and tilt 40 / azimuth 90. Beside
// the folder, `platform.json` is the machine profile of the platform it was made for (platformProfileBeside):
// 4-DOF -90..90 degrees in steps of 1, 5-DOF up to 60 degrees of tilt.
void writeJob(const std::string& dir, bool sliced = true, bool robot = false, bool heatersLeftOn = false);

// The machine profile writeJob writes beside the job folder `dir`.
std::string platformProfileBeside(const std::string& dir);

// Writes a 4-DOF machine profile from `minDegrees` to `maxDegrees` in steps of 1 degree to `path`.
void writeRotaryProfile(const std::string& path, double minDegrees, double maxDegrees);

}  // namespace multidir::test

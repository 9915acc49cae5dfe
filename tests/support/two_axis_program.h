#pragma once
// A stitched program for a printer with two rotary axes in its firmware (issue 26), hand-written in exactly the
// lines the slicer's stitcher writes (docs/slicing.md): the axes' set-up at rest, step 1 printed level, a
// transition (retract, lift, park, M400, the turns, M400, return, prime), step 2 printed at its axis coordinates.
// RepRapFirmware and Marlin turn G-code letters (`G92 U.. V..`, `G1 U.. F..`), Klipper two [manual_stepper]s.
// Each step's extrusions are squares of 10 mm at 1200 mm/min on two layers; the time of every line is summed
// here from the moves' lengths and feed rates as the firmware takes them, so a test can compare the printer's.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace multidir::test {

struct TwoAxisMachineSetup {
  std::string tiltLetter = "U";
  std::string rotationLetter = "V";
  std::string tiltStepper = "tilt";
  std::string rotationStepper = "rotation";
  double tiltZero = 5.0;        // the firmware's coordinate at rest: need not be 0
  double tiltDirection = -1.0;  // coordinate = zero + direction * angle
  double rotationZero = -30.0;
  double rotationDirection = 1.0;
};

struct TwoAxisProgram {
  std::string text;
  double moveSeconds = 0.0;   // the sum of every line's move time
  int extrusionsPerStep = 8;  // 2 layers x 4 sides, in each step
  double tiltAt[2] = {0, 0};  // each step's firmware coordinates
  double rotationAt[2] = {0, 0};
  double tiltDegrees = 35.2;  // step 2's convention angles (step 1 prints at rest)
  double rotationDegrees = -120.0;
};

inline std::string twoAxisNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

// `klipper`: MANUAL_STEPPER lines (SPEED in degrees per second); else G-code letters (F in degrees per minute).
inline TwoAxisProgram twoAxisProgram(bool klipper, const TwoAxisMachineSetup& m = {}) {
  TwoAxisProgram p;
  p.tiltAt[0] = m.tiltZero;
  p.rotationAt[0] = m.rotationZero;
  p.tiltAt[1] = m.tiltZero + m.tiltDirection * p.tiltDegrees;
  p.rotationAt[1] = m.rotationZero + m.rotationDirection * p.rotationDegrees;
  const double turnFeed = 1800.0;  // degrees per minute: 30 degrees per second
  std::string& t = p.text;
  double x = 0, y = 0, z = 0;
  const auto moveTo = [&](double nx, double ny, double nz, double feed, const std::string& extra) {
    const double length = std::sqrt((nx - x) * (nx - x) + (ny - y) * (ny - y) + (nz - z) * (nz - z));
    p.moveSeconds += length / (feed / 60.0);
    t += "G1 X" + twoAxisNumber(nx) + " Y" + twoAxisNumber(ny) + " Z" + twoAxisNumber(nz) + extra + " F" +
         twoAxisNumber(feed) + "\n";
    x = nx;
    y = ny;
    z = nz;
  };
  const auto squares = [&](double cx, double cy) {
    for (int layer = 1; layer <= 2; ++layer) {
      moveTo(cx, cy, 0.3 * layer, 1200.0, "");
      moveTo(cx + 10, cy, z, 1200.0, " E0.5");
      moveTo(cx + 10, cy + 10, z, 1200.0, " E0.5");
      moveTo(cx, cy + 10, z, 1200.0, " E0.5");
      moveTo(cx, cy, z, 1200.0, " E0.5");
    }
  };
  const auto extruderOnly = [&](double e) {
    p.moveSeconds += std::abs(e) / (2100.0 / 60.0);
    t += "G1 E" + twoAxisNumber(e) + " F2100\n";
  };
  t += "; MultiDir test program: two steps on a firmware-2axis printer\nG90\nM83\n";
  t += "; MULTIDIR START SEQUENCE\n; (a printer's homing and purge line go here)\n";
  t += "; MultiDir: the platform's axes, at rest\n";
  if (klipper) {
    t += "MANUAL_STEPPER STEPPER=" + m.tiltStepper + " ENABLE=1 SET_POSITION=" + twoAxisNumber(m.tiltZero) + "\n";
    t += "MANUAL_STEPPER STEPPER=" + m.rotationStepper + " ENABLE=1 SET_POSITION=" + twoAxisNumber(m.rotationZero) +
         "\n";
  } else {
    t += "G92 " + m.tiltLetter + twoAxisNumber(m.tiltZero) + " " + m.rotationLetter + twoAxisNumber(m.rotationZero) +
         "\n";
  }
  t += "; MULTIDIR STEP 1\n";
  squares(100, 100);
  t += "; MULTIDIR TRANSITION 1\n";
  extruderOnly(-0.8);
  moveTo(x, y, 20.0, 600.0, "");
  moveTo(5.0, 215.0, 20.0, 6000.0, "");
  t += "M400 ; let the queued moves end\n";
  const double tiltTurn = std::abs(p.tiltAt[1] - p.tiltAt[0]);
  const double rotationTurn = std::abs(p.rotationAt[1] - p.rotationAt[0]);
  p.moveSeconds += tiltTurn / (turnFeed / 60.0) + rotationTurn / (turnFeed / 60.0);
  if (klipper) {
    t += "MANUAL_STEPPER STEPPER=" + m.tiltStepper + " MOVE=" + twoAxisNumber(p.tiltAt[1]) +
         " SPEED=" + twoAxisNumber(turnFeed / 60.0) + "\n";
    t += "MANUAL_STEPPER STEPPER=" + m.rotationStepper + " MOVE=" + twoAxisNumber(p.rotationAt[1]) +
         " SPEED=" + twoAxisNumber(turnFeed / 60.0) + "\n";
  } else {
    t += "G1 " + m.tiltLetter + twoAxisNumber(p.tiltAt[1]) + " F" + twoAxisNumber(turnFeed) + "\n";
    t += "G1 " + m.rotationLetter + twoAxisNumber(p.rotationAt[1]) + " F" + twoAxisNumber(turnFeed) + "\n";
  }
  t += "M400 ; wait until the platform stands\n";
  moveTo(120.0, 100.0, 20.0, 6000.0, "");
  extruderOnly(0.8);
  t += "; MULTIDIR STEP 2\n";
  squares(120, 100);
  t += "; MULTIDIR END SEQUENCE\n";
  moveTo(x, y, 40.0, 600.0, "");
  t += "M84\n";
  return p;
}

}  // namespace multidir::test

#pragma once
// G-code read back as moves, so MultiDir can check what a slicer wrote instead of trusting it. Understands
// what PrusaSlicer and MultiDir's stitching write: G0/G1 (X Y Z E F and the rotary axis), G90/G91, M82/M83,
// G92, G28, G10/G11 without parameters (firmware retraction), Klipper's MANUAL_STEPPER ... MOVE=, and MultiDir's
// section markers (below). Other commands are
// kept out of the moves; their lines still count.
//
// Section markers (comments MultiDir writes into a stitched program):
//   ; MULTIDIR STEP k          the moves that follow belong to step k
//   ; MULTIDIR TRANSITION k    the moves that follow turn the platform from step k to step k + 1
//   ; MULTIDIR START SEQUENCE  the printer's start (homing, heating, purge): step 0
//   ; MULTIDIR END SEQUENCE    the printer's end: step 0
#include <Eigen/Core>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"

namespace multidir::slicing {

struct GcodeMove {
  int line = 0;                                   // 1-based line of the file
  Eigen::Vector3d from = Eigen::Vector3d::Zero();  // printer coordinates, mm
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  double filamentMm = 0.0;      // filament pushed by this move (negative: retracted)
  double rotaryFromDegrees = 0.0;  // the platform's (first) axis: the firmware axis, or the tilt of two
  double rotaryToDegrees = 0.0;
  double secondFromDegrees = 0.0;  // the second axis of a two-axis platform: its rotation
  double secondToDegrees = 0.0;
  int step = 0;                 // the section it lies in: the step (from 1), 0 before any marker
  bool inTransition = false;    // inside a "; MULTIDIR TRANSITION" section (step is the step it leaves)
  // The move commands the platform's axis (a G0/G1 with the rotary letter, or MANUAL_STEPPER ... MOVE=), even
  // to where the parser believes it is: a program does not know where the platform stands when it starts.
  bool commandsRotaryAxis = false;
  // G10 / G11 without parameters: the firmware retracts / unretracts the filament by its own length (a move
  // that changes nothing else). G10 with P or L words sets offsets (RepRapFirmware) and is no move.
  enum class FirmwareRetraction { None, Retract, Unretract };
  FirmwareRetraction firmwareRetraction = FirmwareRetraction::None;

  bool movesXy() const { return (to.head<2>() - from.head<2>()).squaredNorm() > 1e-12; }
  bool movesZ() const { return std::abs(to.z() - from.z()) > 1e-9; }
  bool rotates() const {
    return std::abs(rotaryToDegrees - rotaryFromDegrees) > 1e-9 || std::abs(secondToDegrees - secondFromDegrees) > 1e-9;
  }
  // Lays down plastic: pushes filament while moving in XY.
  bool extrudes() const { return filamentMm > 1e-9 && movesXy(); }
};

struct GcodeProgram {
  std::vector<GcodeMove> moves;
  int lineCount = 0;
};

// How a program names one of the platform's axes: its G-code letter and, for Klipper, its [manual_stepper].
struct RotaryAxisName {
  std::string letter = "A";
  std::string klipperStepper;  // empty: any MANUAL_STEPPER ... MOVE= turns it (one axis only)
};

// Errors: MalformedFile naming `name` and the line of a G0/G1 word that is not a number.
core::Result<GcodeProgram> parseGcode(const std::string& text, const std::string& rotaryAxis = "A",
                                      const std::string& name = "G-code");

// The same for a platform with one or two axes (the first: GcodeMove::rotary*, the second: second*). Klipper's
// MANUAL_STEPPER lines turn the axis whose stepper they name (SET_POSITION= renames its position, as G92 does);
// one naming another stepper still counts as commanding the platform (commandsRotaryAxis), turning neither.
core::Result<GcodeProgram> parseGcode(const std::string& text, const std::vector<RotaryAxisName>& axes,
                                      const std::string& name);

}  // namespace multidir::slicing

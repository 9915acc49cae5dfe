#pragma once
// What `multidir run` reads from a stitched program (the one G-code file `multidir slice` writes for a platform
// the printer's firmware turns: slicing/src/stitch.cpp, docs/slicing.md): the axes it turns, and the program a
// run resumed at a later step sends. Read from the program itself, so the checks hold for whatever it says.
#include <map>
#include <string>
#include <vector>

namespace multidir::cli {

struct StitchedProgramAxes {
  std::vector<std::string> letters;         // G0/G1/G92 words of A B C U V W (RepRapFirmware, Marlin)
  std::vector<std::string> manualSteppers;  // MANUAL_STEPPER STEPPER=NAME (Klipper)
};

// The rotary axes the program moves or sets, each once, in the order they first appear.
StitchedProgramAxes axesTheProgramUses(const std::string& text);

// The firmware coordinates of every axis the program names (by letter or stepper name) once its lines before
// byte `end` ran (G90/G91 followed; SET_POSITION and G92 set, MOVE and G0/G1 move).
std::map<std::string, double> axisCoordinatesBefore(const std::string& text, std::size_t end);

// The program a run resumed at step `from` (2 or later) sends, for a printer that printed the steps before it
// and still stands as step from-1 left it (homed; the platform's axes where that step printed): the slicer's
// lines before the start sequence (temperatures; no homing, no purge line), the axes declared at step from-1's
// coordinates, then everything from the transition after step from-1 on (retract, lift above the swept part,
// park, turn to step `from`, return, prime, the steps). Throws FileError naming `file` and the missing marker.
std::string resumedStitchedProgram(const std::string& text, int from, const std::string& file);

}  // namespace multidir::cli

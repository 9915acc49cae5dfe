#pragma once
// A step's program split into parts the controller accepts (docs/robot-cell.md, "Programs the controller
// accepts"): each part a complete `def ... end` program of at most the cell's maxProgramBytes, cut only before a
// travel move or a re-orientation (the extruder idle), so no extrusion spans two parts. Part 1 keeps the step's
// start (tool, outputs, the joint moves from home to the approach); every later part sets the tool, the nozzle's
// set point (held, no wait), the fan and the extruder (stopped) as the step has them where it starts, and goes on
// from where the part before ended (the arm at rest at its last movel's end): no gap, no move twice. Every part
// but the last stops the extruder before its end; the last keeps the step's end (the joint move home). The movel
// register's numbers go on across the parts, so a number names one movel of the step.
#include <cstddef>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"

namespace multidir::robot::detail {

// A resumed part (hardware/robot_pause.h) is the rest of the part after the move a pause finished, with a few
// lines of its own before it (tool, outputs, the heat wait, the way back down): parts are cut this much below
// the bound so their resumed rest also fits.
constexpr std::size_t kResumeReserveBytes = 1024;

struct ProgramPart {
  std::string text;
  int firstMovel = 0;  // the step's number (1-based, the movel register's) of the part's first movel
  int movels = 0;
};

// `script` as convertStep writes it, split when it is above maxBytes - kResumeReserveBytes (one part, the
// script itself, when it is not). CheckFailed naming the step when a stretch of extrusion between two idle moves
// does not fit in one part (what to do: raise maxProgramBytes), or when the step needs more than 999 parts.
core::Result<std::vector<ProgramPart>> splitStepProgram(const std::string& script, int step, std::size_t maxBytes);

// "step-02.script" for a step in one part, "step-02-part-003.script" for part 3 of a split one.
std::string partFileName(int step, int part, int parts);

}  // namespace multidir::robot::detail

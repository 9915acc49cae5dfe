#pragma once
// Pausing a robot job's step at a safe point and resuming it where it stopped (docs/robot-cell.md, "Pause and
// resume"): the step's program (as `multidir robot-program` writes it) read as its list of movel; where the arm
// was paused found on that list; the short program that finishes the move under way, stops the extruder and
// lifts the part off the nozzle; the program that goes back down and runs the rest of the step.
#include <array>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/robot/robot_program.h"

namespace multidir::hardware {

struct StepScript {
  std::vector<std::string> lines;            // the program's lines, without their ends
  std::vector<int> movels;                   // the index in `lines` of each movel, in order
  std::vector<std::array<double, 3>> ends;   // each movel's target position (mm, base frame)
};

// The step's program read line by line. MalformedFile naming the line when a movel's pose cannot be read, or
// when the program has no movel or no `def` line.
core::Result<StepScript> parseStepScript(const std::string& text, const std::string& name);

// What the pause and resume programs need from the cell (OUT/cell.json).
struct PauseGeometry {
  std::array<double, 3> nozzleAxis{0.0, 0.0, 1.0};  // unit, base frame, from the tip up into the extruder
  double liftMm = robot::kStepApproachLiftMm;       // the platform backs off the nozzle this far, as at a step's ends
  double travelSpeedMmPerS = 200.0;
  double toolAccelMmPerS2 = 1200.0;
};

// The movel under way when the arm stood still at `tcpMm` (mm, base frame): the first from line index `fromLine`
// on (the layer the robot last reported: paths of the same layer may cross, those of different layers lie a layer
// apart) whose straight path (from the previous movel's end; the first from its end lifted by liftMm, the step's
// approach) passes within `toleranceMm` of it; -1 when none does (the arm is in a movej: home, the approach).
// Of that movel and those right after it that also pass within the tolerance (near its end, the next movels'
// first parts do), the nearest: the one the arm is on. At the end of one movel and the start of the next, either
// is right: the pause finishes the one it names.
int movelUnderWay(const StepScript& script, const PauseGeometry& geometry, const std::array<double, 3>& tcpMm,
                  double toleranceMm, int fromLine);

// The program that takes the arm from where it was paused within movel `index` to that movel's end at its own
// speed and extrusion rate, then stops the extruder and lifts the platform liftMm off the nozzle.
std::string pauseProgram(const StepScript& script, const PauseGeometry& geometry, int index);

// The step from after movel `index` on: the tool, the nozzle's set point (waiting for it), the fan as the program
// had them there; down from the lifted point to that movel's end (the approach lift), the extruder's rate in
// effect; then the program's own lines after that movel, to its end.
std::string resumeProgram(const StepScript& script, const PauseGeometry& geometry, int index);

}  // namespace multidir::hardware

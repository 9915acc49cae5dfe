#pragma once
// The job posed on the robot cell, for the viewer's cell view (docs/robot-cell.md, "Studio"): the cell and the
// motion its programs command (robot::robotJobMotion), and the positions a slider steps through: every move of
// every step in printing order (a step refused before its first move still has one position, the arm at home).
// Pure data, no VTK.
#include <vector>

#include "multidir/robot/cell.h"
#include "multidir/robot/job_motion.h"

namespace multidir::ui {

struct CellMotion {
  robot::Cell cell;
  std::vector<robot::StepMotion> steps;
};

struct CellPosition {
  int step = 0;    // 0-based index into CellMotion::steps
  int sample = 0;  // 0-based index into the step's samples (0 when it has none)
  bool operator==(const CellPosition& o) const { return step == o.step && sample == o.sample; }
};

// How many positions the slider has (0 for no steps).
int cellPositionCount(const CellMotion& motion);
// The position of slider value `index`, clamped to [0, count - 1].
CellPosition cellPositionAt(const CellMotion& motion, int index);

}  // namespace multidir::ui

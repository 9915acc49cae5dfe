#pragma once
// The reach map "Find extruder position" made (robot/reach_map.h; docs/robot-cell.md, "Reach map"), for the
// viewer's cell view: the map and the cell it was scored for. Pure data, no VTK.
//
// A map is scored for everything of the cell but where its nozzle tip is (the tip is what the map places:
// reachScore puts the cell's tip at each sampled position), so it stays true while only the tip moves ("Use this
// position" among them) and is stale as soon as anything else of the cell changes: the arm, its limits, the
// nozzle axis, the flange-to-platform transform, the platform, the table, the margins or the home pose.
#include "multidir/robot/cell.h"
#include "multidir/robot/reach_map.h"

namespace multidir::ui {

struct CellReachMap {
  robot::ReachMap map;
  robot::Cell cell;        // the cell the map was scored for
  double gridMm = 100.0;   // the map's spacing (robot::ReachMapOptions::gridMm)
};

// True when `map` was scored for `cell`: the two cells agree in everything but the nozzle tip.
bool reachMapFitsCell(const CellReachMap& map, const robot::Cell& cell);

}  // namespace multidir::ui

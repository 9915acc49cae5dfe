#include "ui/viewer/cell_reach_map.h"

#include "multidir/robot/cell_file.h"

namespace multidir::ui {

bool reachMapFitsCell(const CellReachMap& map, const robot::Cell& cell) {
  // The cell file's text holds every key the cell has (cellJson: what parseCell reads), so two cells whose texts
  // agree once their tips agree differ in nothing else.
  robot::Cell scored = map.cell;
  scored.nozzleTipMm = cell.nozzleTipMm;
  return robot::cellJson(scored) == robot::cellJson(cell);
}

}  // namespace multidir::ui

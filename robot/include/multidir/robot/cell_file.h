#pragma once
// The cell file written (docs/robot-cell.md, "The cell file"): the inverse of parseCell, so the studio's Machine
// tab can save a cell it edited and `multidir cell check` and robot-program read it back unchanged.
#include <filesystem>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/robot/cell.h"

namespace multidir::robot {

// The cell as the file's JSON (format "multidir-robot-cell", version 1): every key parseCell reads, angles in
// degrees, rotations as rotation vectors in degrees. parseCell of the text gives back the cell (to the
// printed precision, 1e-9 mm and degrees).
std::string cellJson(const Cell& cell);

// Writes cellJson to `path` atomically (beside it, then renamed). Errors: WriteFailed naming the path.
core::Status writeCell(const Cell& cell, const std::filesystem::path& path);

}  // namespace multidir::robot

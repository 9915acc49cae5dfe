#pragma once
// The cell view's colours (ui/viewer/cell_scene.h), shared with MeshViewerWidget's colour getters the tests use.
namespace multidir::ui {

inline constexpr double kCellArmRgb[3] = {0.62, 0.66, 0.72};
inline constexpr double kCellPlatformRgb[3] = {0.35, 0.35, 0.38};
inline constexpr double kCellBodyRgb[3] = {0.55, 0.55, 0.55};
inline constexpr double kCellTableRgb[3] = {0.58, 0.55, 0.50};
inline constexpr double kCellPartRgb[3] = {0.95, 0.62, 0.12};
inline constexpr double kCellToolpathRgb[3] = {0.15, 0.35, 0.95};
inline constexpr double kCellToolpathPointRgb[3] = {0.0, 1.0, 1.0};
inline constexpr double kCellNozzleRgb[3] = {0.75, 0.1, 0.85};
inline constexpr double kCellWarningRgb[3] = {0.95, 0.05, 0.05};

}  // namespace multidir::ui

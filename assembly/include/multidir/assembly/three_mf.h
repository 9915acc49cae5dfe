#pragma once
// The parts and dowels of a plan printed apart as one 3MF file (core specification, written with lib3mf):
// each item an object whose mesh lies in its own laid frame (its box corner at the origin) and a build item
// that places it on its plate; plate k is shifted by k x (bed width + kPlateGapMm) along X, so slicers that
// know no plates show them side by side.
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "multidir/assembly/plates.h"
#include "multidir/core/common/result.h"

namespace multidir::assembly {

inline constexpr double kPlateGapMm = 20.0;

struct ThreeMfItem {
  std::string name;
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  double volumeMm3 = 0.0;  // of the object's mesh
  Eigen::Matrix<double, 3, 4> transform = Eigen::Matrix<double, 3, 4>::Zero();  // the build item's
};

// What write3mf writes for a layout (so a test can compare what is read back with it).
std::vector<ThreeMfItem> threeMfItems(const PlateLayout& layout, const PlateOptions& options);

// Errors: WriteFailed (naming the path) when lib3mf cannot write it.
core::Status write3mf(const PlateLayout& layout, const PlateOptions& options, const std::string& path);

// Reads a 3MF's build items back with lib3mf. Errors: MalformedFile naming the path.
core::Result<std::vector<ThreeMfItem>> read3mf(const std::string& path);

}  // namespace multidir::assembly

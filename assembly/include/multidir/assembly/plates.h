#pragma once
// The parts and dowels of a plan printed apart laid out on as few plates of a printer's bed as they fit:
// each part cut face down (core::layOnBed), each dowel standing on an end, packed in shelves (rows), largest
// first (docs/apart.md, "Plates").
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::assembly {

struct PlateOptions {
  Eigen::Vector2d bedMin = Eigen::Vector2d::Zero();     // the bed's box (printer XY, mm)
  Eigen::Vector2d bedMax = Eigen::Vector2d(220, 220);
  double maxHeightMm = 250.0;
  double marginMm = 5.0;   // kept free along the bed's edges (the slicer's skirt)
  double spacingMm = 5.0;  // between neighbours
};

struct PlateItem {
  std::string name;              // "part-01", "dowel-03"
  int plate = 0;                 // 0-based
  core::TriangleMesh mesh;       // laid and placed: printer coordinates of its plate
  Eigen::Isometry3d modelToPlate = Eigen::Isometry3d::Identity();  // model frame -> plate
};

struct PlateLayout {
  std::vector<PlateItem> items;  // parts first, in their order, then dowels
  int plates = 0;
};

// Errors: InvalidParameter naming the item that does not fit an empty bed (its size and the bed's).
core::Result<PlateLayout> arrangeOnPlates(const std::vector<core::TriangleMesh>& parts,
                                          const std::vector<core::Vec3>& printingDirections,
                                          const std::vector<core::TriangleMesh>& dowels,
                                          const std::vector<core::Vec3>& dowelAxes, const PlateOptions& options);

// The items of one plate as one mesh (their shells side by side), for the slicer.
core::TriangleMesh plateMesh(const PlateLayout& layout, int plate);

}  // namespace multidir::assembly

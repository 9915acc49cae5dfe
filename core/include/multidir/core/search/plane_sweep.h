#pragma once
// One-pass evaluation of every candidate plane of one normal (the search's hot loop).
//
// For a fixed unit normal n, the part of a solid above the plane {n.x = t} changes with the offset t in a
// way that is piecewise polynomial per triangle: the area of a triangle above the plane is quadratic in t
// between its vertex heights, and (by the divergence theorem with the field (n.x - t) n, which vanishes on the
// cut) the volume above is cubic. Summing those pieces over a uniform grid of offsets with difference arrays
// costs O(F + offsets) per normal and never clips the mesh.
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

// Offsets firstMm, firstMm + stepMm, ... (count of them) along one normal.
struct OffsetGrid {
  double firstMm = 0.0;
  double stepMm = 1.0;  // > 0
  int count = 0;
  double offsetAt(int j) const { return firstMm + stepMm * j; }
};

// What lies above each plane of the grid.
struct SweepProfile {
  std::vector<double> volumeAboveMm3;
  // Area above the plane of faces that would be risky if the part above were printed along the normal.
  std::vector<double> riskyAreaAlongNormalMm2;
  // Area above the plane of faces flagged risky for the solid's current printing direction.
  std::vector<double> riskyAreaFlaggedMm2;
};

// Sweeps the planes of `grid` along `unitNormal` through `solid` (closed, outward normals).
// `riskyFlags` holds one flag per face (risky for the current printing direction, e.g. from
// analyzeOverhang); `sinAlphaMax` = sin(alpha_max) decides which faces are risky along the normal.
SweepProfile sweepPlanes(const TriangleMesh& solid, const Vec3& unitNormal, const OffsetGrid& grid,
                         const std::vector<char>& riskyFlags, double sinAlphaMax);

}  // namespace multidir::core

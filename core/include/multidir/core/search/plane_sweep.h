#pragma once
// One-pass evaluation of every candidate plane of one normal (the search's hot loop).
//
// For a fixed unit normal n, the part of a solid above the plane {n.x = t} changes with the offset t in a
// way that is piecewise polynomial per triangle: the area of a triangle above the plane is quadratic in t
// between its vertex heights, and (by the divergence theorem with the field (n.x - t) n, which vanishes on the
// cut) the volume above is cubic. Summing those pieces over a uniform grid of offsets with difference arrays
// costs O(F + offsets) per normal and never clips the mesh.
#include <array>
#include <cstdint>
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
  // R(M+, plane): area of faces that would be risky if the part above were printed along the normal. Only
  // the cap rests on the material below the plane (it is not a face of the solid, so it is not summed);
  // every other down-facing face above the plane hangs over air (docs/jg-definition.md).
  std::vector<double> riskyAreaAlongNormalMm2;
  // Area above the plane of the risky parts of faces for the solid's current printing direction.
  std::vector<double> riskyAreaFlaggedMm2;
  double topMm = 0.0;  // the solid's highest level along the normal
};

// Sweeps the planes of `grid` along `unitNormal` through `solid` (closed, outward normals).
// `riskyShare` holds, per face, the share of its area that is risky for the solid's current printing
// direction (OverhangAnalysis::riskyFaceAreaMm2 over the face's area; empty: none). A face's share is taken
// to be spread evenly over it. `sinAlphaMax` = sin(alpha_max) decides which faces are risky along the normal.
SweepProfile sweepPlanes(const TriangleMesh& solid, const Vec3& unitNormal, const OffsetGrid& grid,
                         const std::vector<double>& riskyShare, double sinAlphaMax);

// The same, for many normals through one solid: the per-face data is prepared once. sweep() is const and
// may run on several threads at once. The solid must outlive the sweeper.
class PlaneSweeper {
 public:
  PlaneSweeper(const TriangleMesh& solid, const std::vector<double>& riskyShare, double sinAlphaMax);
  SweepProfile sweep(const Vec3& unitNormal, const OffsetGrid& grid) const;
  // Each vertex's level along the normal (unitNormal . v), and sweep() with them given: a caller that also
  // needs the solid's extent along the normal (for the grid) reads the vertices once.
  std::vector<double> levels(const Vec3& unitNormal) const;
  SweepProfile sweep(const Vec3& unitNormal, const OffsetGrid& grid, const std::vector<double>& levels) const;
  // Some faces of the solid (indices into its triangles) with their corners listed once, made once for many
  // normals: a sweep of them reads each corner's level once, not once per face around it.
  struct FaceSet {
    std::vector<std::int32_t> faces;
    std::vector<std::int32_t> vertices;                // the faces' corners, each once
    std::vector<std::array<std::int32_t, 3>> corners;  // per face, its corners' positions in `vertices`
  };
  FaceSet faceSet(const std::vector<std::int32_t>& faces) const;
  // The sums over some faces only; topMm is left at 0. A solid that differs from another by a few faces has
  // the other's profile minus those faces plus its own.
  SweepProfile sweepFaces(const Vec3& unitNormal, const OffsetGrid& grid, const FaceSet& faces) const;

 private:
  struct Sums;
  void addFace(Sums& sums, const Vec3& unitNormal, std::size_t f, double ha, double hb, double hc, int ja, int jb,
               int jc) const;

  // What the sweep reads of a face, side by side in memory.
  struct FaceData {
    Vec3 unitNormal = Vec3::Zero();
    double area = 0.0;
    double riskyArea = 0.0;  // share * area
  };
  const TriangleMesh& m_solid;
  std::vector<FaceData> m_faces;
  double m_sinAlpha;
};

}  // namespace multidir::core

#pragma once
// Overhang analysis (the paper's Eq. 1): a face is risky for printing direction d when
// n.d + sin(alpha_max) < 0, i.e. it faces downward more steeply than the printer can bridge.
// A risky face needs support unless printed material (or the bed) lies directly below it. What lies below
// depends on what the region stands on (docs/jg-definition.md, the one definition of J_G):
//  - on the platform, the bed is the plane through the mesh's lowest point along d, and the part of a face
//    within supportedBandMm above it rests on the bed;
//  - on a cut plane, only the cap (the faces lying in the base plane) rests on the material printed before;
//    everything else above the plane hangs over air, however close to the plane it is.
#include <array>

#include "multidir/core/common/result.h"
#include "multidir/core/common/units.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

// What a region stands on while it is printed.
enum class RegionBase {
  Platform,  // the bed, at the region's lowest level
  CutPlane,  // the cap it shares with the material printed before it, at the region's lowest level
};

struct OverhangOptions {
  double alphaMaxDegrees = kDefaultAlphaMaxDegrees;        // in [0, 90)
  double supportedBandMm = kDefaultSupportedBandMm;  // >= 0; used on the platform only
  RegionBase base = RegionBase::Platform;
};

struct OverhangAnalysis {
  std::vector<char> risky;  // one flag per face: its normal is risky and part of it lies above the band
  std::vector<double> riskyFaceAreaMm2;  // per face: the risky part's area (0 for safe faces)
  double riskyAreaMm2 = 0.0;
  std::size_t riskyFaces = 0;
  double platformHeightMm = 0.0;  // min over vertices of d.x: the bed or the base plane
};

// How far (mm) a corner may lie from a region's base plane and still count as lying in it: 1e-6 of the
// largest coordinate (at least 1 mm), over five times what a binary STL's rounding can move a height (float:
// 6e-8 per coordinate, three coordinates). It scales with the coordinates so that a region read back from its
// STL keeps its cap.
double inPlaneToleranceMm(const TriangleMesh& mesh);

// Checks the options and the direction (finite, non-zero; it is normalised).
Status validate(const OverhangOptions& options);

// Risky faces and area of `mesh` printed along `printingDirection`. Errors: InvalidParameter.
Result<OverhangAnalysis> analyzeOverhang(const TriangleMesh& mesh, const Vec3& printingDirection,
                                         const OverhangOptions& options = {});

// The risky area (mm^2) of a solid printed alone along `direction`, standing on the platform or bed at its
// lowest level (rule 2 of docs/jg-definition.md): the J_G of a pose, and of a part printed apart. An analysis
// that fails is an error, never "no risky area". Errors: InvalidParameter.
Result<double> riskyAreaOnPlatform(const TriangleMesh& solid, const Vec3& direction, double alphaMaxDegrees,
                                   double supportedBandMm);

// Area of a triangle (given its corners' heights and its area) that lies above `level`.
double triangleAreaAbove(std::array<double, 3> heights, double area, double level);

// Parses an up direction as the command line and GUI accept it: "x", "-y", "+z" or "a,b,c".
Result<Vec3> parseDirection(const std::string& text);

}  // namespace multidir::core

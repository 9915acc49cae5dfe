#pragma once
// Overhang analysis (the paper's Eq. 1): a face is risky for printing direction d when
// n.d + sin(alpha_max) < 0, i.e. it faces downward more steeply than the printer can bridge.
// The platform is the plane through the mesh's lowest point along d; the part of a face within
// supportedBandMm above it is supported by it, so only the part of a risky face above that band counts.
#include <array>

#include "multidir/core/common/result.h"
#include "multidir/core/common/units.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

struct OverhangOptions {
  double alphaMaxDegrees = kDefaultAlphaMaxDegrees;        // in [0, 90)
  double supportedBandMm = kDefaultSupportedBandMm;  // >= 0
};

struct OverhangAnalysis {
  std::vector<char> risky;  // one flag per face: its normal is risky and part of it lies above the band
  std::vector<double> riskyFaceAreaMm2;  // per face: the risky part's area (0 for safe faces)
  double riskyAreaMm2 = 0.0;
  std::size_t riskyFaces = 0;
  double platformHeightMm = 0.0;  // min over vertices of d.x
};

// Checks the options and the direction (finite, non-zero; it is normalised).
Status validate(const OverhangOptions& options);

// Risky faces and area of `mesh` printed along `printingDirection`. Errors: InvalidParameter.
Result<OverhangAnalysis> analyzeOverhang(const TriangleMesh& mesh, const Vec3& printingDirection,
                                         const OverhangOptions& options = {});

// Area of a triangle (given its corners' heights and its area) that lies above `level`.
double triangleAreaAbove(std::array<double, 3> heights, double area, double level);

// Parses an up direction as the command line and GUI accept it: "x", "-y", "+z" or "a,b,c".
Result<Vec3> parseDirection(const std::string& text);

}  // namespace multidir::core

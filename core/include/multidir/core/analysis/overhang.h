#pragma once
// Overhang analysis (the paper's Eq. 1): a face is risky for printing direction d when
// n.d + sin(alpha_max) < 0, i.e. it faces downward more steeply than the printer can bridge.
// Faces lying on the platform (the plane through the mesh's lowest point along d) are supported by it.
#include "multidir/core/common/result.h"
#include "multidir/core/common/units.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

struct OverhangOptions {
  double alphaMaxDegrees = kDefaultAlphaMaxDegrees;        // in [0, 90)
  double platformToleranceMm = kDefaultPlatformToleranceMm;  // >= 0
};

struct OverhangAnalysis {
  std::vector<char> risky;  // one flag per face
  double riskyAreaMm2 = 0.0;
  std::size_t riskyFaces = 0;
  double platformHeightMm = 0.0;  // min over vertices of d.x
};

// Checks the options and the direction (finite, non-zero; it is normalised).
Status validate(const OverhangOptions& options);

// Risky faces and area of `mesh` printed along `printingDirection`. Errors: InvalidParameter.
Result<OverhangAnalysis> analyzeOverhang(const TriangleMesh& mesh, const Vec3& printingDirection,
                                         const OverhangOptions& options = {});

// Parses an up direction as the command line and GUI accept it: "x", "-y", "+z" or "a,b,c".
Result<Vec3> parseDirection(const std::string& text);

}  // namespace multidir::core

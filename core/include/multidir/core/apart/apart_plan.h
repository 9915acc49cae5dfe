#pragma once
// A plan printed apart on an ordinary printer (docs/apart.md): every connected piece of every region is a part
// of its own, laid on the bed on its cut face (the first region on the model's bottom), and parts that share
// cut-face area are joined there (by dowels, assembly/). A part that does not fit the printer's build volume
// is cut further, each half keeping its printing direction.
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/common/units.h"
#include "multidir/core/geometry/plane.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/decomposition.h"

namespace multidir::core {

// The box a printer can print into (mm): the bed's width and depth and the largest print height.
struct BuildVolume {
  double xMm = 0.0;
  double yMm = 0.0;
  double zMm = 0.0;
};

struct ApartOptions {
  // Where parts must fit, laid on the bed (any turn about the vertical). All zero: no limit.
  BuildVolume buildVolume;
  // More parts than this (after cutting oversized ones) is refused: the model is too big for the printer.
  int maxParts = 64;
  double alphaMaxDegrees = kDefaultAlphaMaxDegrees;
  double supportedBandMm = kDefaultSupportedBandMm;
};

struct ApartPart {
  TriangleMesh mesh;        // model frame (mm), closed; cut faces keep their plane id (FaceOrigin::cap)
  Vec3 printingDirection;   // unit: the part is laid on the bed with this pointing up
  int region = 0;           // the plan's region it comes from
  double volumeMm3 = 0.0;
  // Risky area along printingDirection with the bed at the part's lowest level (docs/jg-definition.md,
  // "Printed apart"): the part's share of J_G apart.
  double riskyAreaMm2 = 0.0;
};

// Two parts that touch on a cut plane: `upper` lies on the plane's positive side, `lower` on the other.
struct ApartJoint {
  int lower = 0;
  int upper = 0;
  Plane plane;             // the cut (normal from lower to upper)
  std::int32_t planeId = 0;  // the caps' FaceOrigin index
  double areaMm2 = 0.0;    // area of the upper part's cut face that lies on the lower part's
};

struct ApartPlan {
  std::vector<ApartPart> parts;
  std::vector<ApartJoint> joints;
  std::vector<Plane> planes;  // by plane id: the plan's clipping planes, then the cuts added to fit the bed
  int cutsToFit = 0;          // planes added because a part did not fit the build volume
  double jgMm2 = 0.0;         // J_G apart: the parts' risky areas summed
};

// The plan's parts, cut further until each fits `options.buildVolume`. A region of several pieces gives a
// part per piece (a piece that is a cavity stays with the region's other pieces). Errors: TooLarge
// when more than maxParts parts would be needed (names the build volume and the largest part) or a part
// cannot be cut to fit (thinner than the cut could print).
Result<ApartPlan> apartPlan(const Decomposition& plan, const ApartOptions& options = {});

}  // namespace multidir::core

#pragma once
// Dowels that join the parts of a plan printed apart (docs/apart.md, "Dowels"): for every joint (two parts
// sharing cut-face area) round holes drilled into both faces and separate printed dowels that fill them
// up to a clearance. What a PrusaSlicer or OrcaSlicer user knows from the cut tool's dowel connectors, with
// the clearances in absolute millimetres in radius and in depth, a chamfer at each hole's mouth, a minimum
// wall around every hole, at least two dowels per joint where the face has room, and different diameters so
// that two parts fit together one way only.
#include <string>
#include <vector>

#include "multidir/core/apart/apart_plan.h"
#include "multidir/core/common/result.h"

namespace multidir::assembly {

using core::Vec3;

struct DowelOptions {
  // Dowel diameter: diameterShare x sqrt(joint area), rounded down to 0.5 mm, within [min, max] (mm).
  double diameterShare = 0.2;
  double minDiameterMm = 3.0;
  double maxDiameterMm = 8.0;
  // Dowel length: lengthRatio x diameter (half in each part); shortened down to 1 x diameter where a part
  // is not deep enough.
  double lengthRatio = 2.0;
  // The second and later dowels of a joint are this much thinner than the first, so the parts fit one way.
  double keyStepMm = 1.0;
  double radialClearanceMm = 0.15;  // hole radius minus dowel radius
  double depthClearanceMm = 0.3;    // hole depth minus the dowel's half length, in each part
  double chamferMm = 0.5;           // 45-degree chamfer at each hole's mouth (radial and deep)
  double minWallMm = 1.2;           // plastic left around and below every hole (three 0.4 mm perimeters)
  int dowelsPerJoint = 2;           // wanted where the face has room (1 where only one fits)
  int segments = 32;                // facets around a hole or a dowel
};

// Names the first option out of range.
core::Status validate(const DowelOptions& options);

struct Dowel {
  int joint = 0;              // index into ApartPlan::joints
  Vec3 centre;                // on the joint's plane (model frame, mm)
  Vec3 axis;                  // unit, the joint's plane normal (from its lower part into its upper part)
  double diameterMm = 0.0;
  double lengthMm = 0.0;
  double holeRadiusMm(const DowelOptions&) const;  // diameter / 2 + radial clearance
  double holeDepthMm(const DowelOptions&) const;  // length / 2 + depth clearance
};

struct JointDowels {
  int joint = 0;
  int count = 0;
  std::string note;  // why fewer than wanted ("the face has room for one dowel"), empty otherwise
};

struct DowelLayout {
  std::vector<Dowel> dowels;
  std::vector<JointDowels> joints;  // one per joint of the plan
};

// Where the dowels go: on a grid over each joint's shared face, the points whose hole (with chamfer and wall)
// stays inside the face, whose parts are deep enough on both sides (rays along the axis at the hole's centre
// and around its wall), and which keep a wall from every hole already placed in either part; of those the two
// farthest apart, then more where room. Deterministic. Cost: grid points x rays x part faces per joint.
DowelLayout placeDowels(const core::ApartPlan& plan, const DowelOptions& options);

// The parts with their holes drilled (CGAL corefinement; every result checked to be a closed, oriented
// solid) and the dowels as separate solids (model frame). Errors: Internal naming the part when a boolean
// fails or its result is not a closed oriented solid.
struct DrilledParts {
  std::vector<core::TriangleMesh> parts;   // as ApartPlan::parts
  std::vector<core::TriangleMesh> dowels;  // as DowelLayout::dowels
  double clearanceVolumeMm3 = 0.0;         // the holes' volume not filled by dowels (exact for the facets)
};
core::Result<DrilledParts> drillParts(const core::ApartPlan& plan, const DowelLayout& layout,
                                      const DowelOptions& options);

// The closed solid a hole removes (its part of the tool inside the part, the chamfer included, plus a margin
// outside the face) and a dowel, as meshes: used by drillParts and by tests.
core::TriangleMesh holeTool(const Dowel& dowel, bool intoUpper, const DowelOptions& options);
core::TriangleMesh dowelSolid(const Dowel& dowel, const DowelOptions& options);
// The volume of the hole inside its part (the tool's volume on the part's side of the face).
double holeVolumeMm3(const Dowel& dowel, const DowelOptions& options);

// The least distance from a hole's surface inside the part to the part's outer surface, the joint's own cut
// face excepted: the wall the hole leaves (mm). `undrilled` is the part before drilling.
double holeWallMm(const core::TriangleMesh& undrilled, std::int32_t jointPlaneId, const Dowel& dowel, bool intoUpper,
                  const DowelOptions& options);

}  // namespace multidir::assembly

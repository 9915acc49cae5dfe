#pragma once
// Where supports must touch a region (the paper's Section V): uniform samples of its risky faces (face
// overhangs), plus edges and vertices that hang lower than everything around them (edge and point overhangs).
#include <vector>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/supports/support_options.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

enum class OverhangKind { Face, Edge, Point };

struct OverhangSample {
  Vec3 position;            // on the mesh surface, mm
  OverhangKind kind = OverhangKind::Face;
  std::int32_t face = -1;   // a face of the mesh at the sample
  double edgeLengthMm = 0.0;  // an edge sample: the length of the edge it stands for
};

// Samples of `mesh` printed along `printingDirection` (unit):
//  - face overhangs: the part of each risky face above the supported band (as analyzeOverhang counts it),
//    sampled on a square grid of spacing R perpendicular to the direction (grid lines through the origin,
//    so neighbouring faces share one grid); a connected risky patch that no grid point hits gets one sample
//    at the centroid of its largest face;
//  - edge overhangs: an edge whose two faces both face down (but neither is risky), whose other corners
//    both lie higher, and which itself rises less steeply than the faces may (|e.d| < cos alpha), sampled
//    every R along it; edges of caps (cut faces, FaceOrigin::Cap) are left out;
//  - point overhangs: a vertex lower along the direction than all its neighbours where the surface faces down
//    (the sum of its faces' area vectors points down: the solid lies above it, air below), unless a sample
//    lies within R/2 already. The bottom of a pit in a top surface rests on the solid under it: no sample.
// On the platform, everything within the supported band above the mesh's lowest level is left out (it rests
// on the bed); above a cut plane only the base plane itself is (the cap rests on the material below).
// Cost: O(F + samples). Errors: InvalidParameter (options, direction).
Result<std::vector<OverhangSample>> sampleOverhangs(const TriangleMesh& mesh, const Vec3& printingDirection,
                                                    const SupportOptions& options = {},
                                                    RegionBase base = RegionBase::Platform);

}  // namespace multidir::core

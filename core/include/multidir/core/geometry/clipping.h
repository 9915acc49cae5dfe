#pragma once
// Exact clipping of a closed solid by a plane: the two sides, each closed by a cap in the plane, with the
// provenance of every face (model surface or cap of plane k) that J_G and supports need.
#include <cstdint>

#include "multidir/core/common/result.h"
#include "multidir/core/common/units.h"
#include "multidir/core/geometry/plane.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

// The largest plane tolerance clipByPlane accepts (mm): a micrometre, below any printer's resolution.
constexpr double kMaxPlaneToleranceMm = 1e-3;

struct ClipOptions {
  // Vertices within this distance (mm) of the plane are moved onto it and count as lying in it. At most
  // kMaxPlaneToleranceMm: it absorbs rounding, it does not reshape the solid.
  double planeToleranceMm = kDefaultPlaneToleranceMm;
  // Checks that the input is closed and consistently oriented with positive volume (O(F), a few ms per
  // 100k triangles). Callers that clip a clipper's own output again may turn it off; index ranges and
  // finiteness are checked always.
  bool checkClosed = true;
};

struct ClipResult {
  TriangleMesh below;  // the side the plane's normal points away from, closed by a cap facing +normal
  TriangleMesh above;  // the side the plane's normal points to, closed by a cap facing -normal
  // Per face of `below`: the index of the input face it is an unchanged copy of (not split, no corner moved
  // onto the plane), or -1. Lets a caller update per-face sums instead of recomputing them (the search).
  std::vector<std::int32_t> belowSourceFace;
};

// Splits a closed, consistently oriented solid by `plane`.
//
// Each side is a closed, consistently oriented mesh (an empty mesh when nothing lies on that side) whose
// volumes add up to the input's. Faces crossing the plane are split; the point where an edge crosses is
// computed once, so both sides share it exactly. Cap faces use only the cross-section's own vertices and carry
// FaceOrigin::cap(planeId); every other face keeps the origin of the input face it comes from.
// Vertices within options.planeToleranceMm of the plane are snapped onto it. A face lying in the plane stays
// with the side it bounds: facing +normal it is the top of `below` and `above` gets no cap there; facing
// -normal it is the bottom of `above`. A vertex where one side would pinch (two parts touching at a point
// of the plane) is duplicated so that each side stays a 2-manifold. Unused vertices are dropped.
//
// Cost: O(F) for the faces plus the cap triangulation (close to linear in the cross-section's size).
// Thread-safe: no shared state.
// Errors: InvalidParameter (plane normal not finite or not unit length within 1e-9, offset or tolerance not
// finite, tolerance negative or above kMaxPlaneToleranceMm, origins.size() != triangles.size()); EmptyMesh; NonFiniteVertex;
// NotManifold, OpenBoundary, InconsistentOrientation (input not a closed oriented solid, when checked);
// Internal when the cross-section cannot be closed (a bug: please report the input).
Result<ClipResult> clipByPlane(const TriangleMesh& solid, const Plane& plane, std::int32_t planeId,
                               const ClipOptions& options = {});

}  // namespace multidir::core

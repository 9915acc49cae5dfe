#pragma once
// Criterion II without clipping: most candidate planes the beam tries on a branchy model (a chess knight's
// head, a handle) are refused because the part below would leave a piece hanging in the air. Finding that
// out by clipping costs a cut, a cap triangulation and a float check per candidate; this test needs one pass
// over the faces and answers "certainly" or "cannot tell", never wrongly "certainly".
#include "multidir/core/geometry/plane.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

// True only when the part of `solid` below `plane` certainly has a connected piece whose lowest point lies
// above `platformLevelMm` along `up`, whatever the clip does within `marginMm` of the plane (snapping
// vertices, re-placing the plane by micrometres). Pieces are the faces below the plane joined through shared
// vertices; a piece that reaches the plane may be joined to another one by the cap where one's cross-section
// lies inside the other's (and through such caps to further pieces), so it counts as floating only when no
// chain of pieces with overlapping cross-section boxes links it to a piece that may reach the platform.
// How far clipping pieces of `model` may move a point: snapping (at most 1e-3 of a face's height, so of the
// model's size), the plane tolerance, and the search's re-placements of a plane (micrometres).
double clipMarginMm(const TriangleMesh& model);

bool certainlyLeavesFloatingPiece(const TriangleMesh& solid, const Plane& plane, const Vec3& up,
                                  double platformLevelMm, double marginMm);

}  // namespace multidir::core::detail

#pragma once
// Connected solids of a mesh, and whether each rests on the printing platform (the paper's Criterion II:
// what remains below a clipping plane must stay connected to the platform).
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/common/units.h"
#include "multidir/core/geometry/clipping.h"
#include "multidir/core/geometry/plane.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

// Splits a mesh into its connected solids: faces connected through shared vertices (caps included) form a
// shell, and a shell turned inwards (negative volume: the wall of a cavity) joins the smallest shell around it.
// Each solid keeps its faces' origins and only the vertices it uses, in order of first use; solids come in
// order of their first face. An empty mesh gives no solids.
// Cost: O(F) plus, per cavity shell, one ray test against the shells around it.
// Errors: InvalidParameter when a vertex index is out of range or origins.size() != triangles.size().
Result<std::vector<TriangleMesh>> connectedSolids(const TriangleMesh& mesh);

// Lowest point of the mesh along the plane's normal, minus the plane's offset (mm): 0 when the mesh rests on
// the plane, negative when it goes through it. 0 for an empty mesh.
double heightAbove(const TriangleMesh& mesh, const Plane& platform);

// Whether the solid rests on the platform: its lowest point along platform.normal is within toleranceMm of
// the platform plane (a solid reaching further through the platform does not rest on it).
bool touchesPlatform(const TriangleMesh& solid, const Plane& platform,
                     double toleranceMm = kDefaultPlatformToleranceMm);

struct PlacedSolid {
  TriangleMesh mesh;
  bool touchesPlatform = false;
};

// connectedSolids() with touchesPlatform() for each.
Result<std::vector<PlacedSolid>> connectedSolidsOnPlatform(const TriangleMesh& mesh, const Plane& platform,
                                                           double toleranceMm = kDefaultPlatformToleranceMm);

struct ClipSolids {
  std::vector<TriangleMesh> below;
  std::vector<TriangleMesh> above;
};

// The connected solids on each side of a clip.
Result<ClipSolids> connectedSolids(const ClipResult& clip);

}  // namespace multidir::core

#pragma once
// A plan from given clipping planes rather than from a search: what editing a plan and reopening a project
// need. The regions, their directions, angles and J_G come out as the search would report them for the same
// planes, and every criterion the search enforces on a cut is checked, so an edited plan is one the search
// could have returned.
#include <vector>

#include "multidir/core/search/decomposition.h"

namespace multidir::core {

// Rebuilds a plan from its clipping planes in clipping order (plane k cuts region N-k off what is left of the
// model). `machine` must carry the rotation axis the plan used (Decomposition::rotationAxis for 4-DOF); the
// options give alpha_max, the supported band and the platform tolerance (the search-only options are unused,
// and so is the minimal volume V/w: a person may cut a small region off on purpose).
// Errors (InvalidParameter, `where` = "plane K", K from 1): a plane the machine cannot print along; a plane
// that cuts the platform region (Criterion III); a plane that leaves nothing above or nothing below; a cut
// after which a solid below no longer stands on the platform (Criterion II). Also validate() errors of the
// machine and options, and EmptyMesh.
Result<Decomposition> planFromClippingPlanes(const TriangleMesh& model, const MachineSpec& machine,
                                             const SearchOptions& options, const std::vector<Plane>& clippingPlanes);

}  // namespace multidir::core

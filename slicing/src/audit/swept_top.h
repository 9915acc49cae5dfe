#pragma once
// The highest z a set of points reaches while they turn about an axis through the origin (the audit's own,
// for the turn check (e)).
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::slicing::audit {

// The highest z of `points` turned about `axisUnit` (right-hand rule, through the origin) by every angle
// between 0 and `turnRadians` (either sign). Exact: a point's z over the turn is c + A cos s + B sin s, whose
// maximum lies at an end of the arc or at its peak inside it. Empty `points`: -infinity.
double sweptTop(const std::vector<core::Vec3>& points, const core::Vec3& axisUnit, double turnRadians);

}  // namespace multidir::slicing::audit

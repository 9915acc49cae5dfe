#pragma once
// How high the nozzle must be while the platform turns: above the highest point the printed part reaches
// over the whole turn (the swept volume's top), plus a margin.
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/plan/print_job.h"

namespace multidir::slicing {

// The highest z that `points` reach while they turn about the line through the origin along `axisUnit`, by
// every angle between 0 and `turnRadians` (either sign; right-hand rule about the axis). Exact: each point's
// z is c + A cos t + B sin t over the arc, whose maximum is at an end or where the derivative vanishes.
// Empty `points`: -infinity.
double sweptTopZ(const std::vector<core::Vec3>& points, const core::Vec3& axisUnit, double turnRadians);

// The same along any unit `direction`: the largest direction . R(t) q over the arc (sweptTopZ is direction +Z).
// With -direction it gives the smallest, negated: the swept part's extent on the bed, side by side.
double sweptMax(const std::vector<core::Vec3>& points, const core::Vec3& axisUnit, double turnRadians,
                const core::Vec3& direction);

// A bound for any motion that turns the part about the origin (a robot arm's tilt and azimuth): no point
// rises above its distance from the origin. Empty `points`: -infinity.
double anyTurnTopZ(const std::vector<core::Vec3>& points);

// Every point printed up to step k (from 0: the regions and supports of steps 1..k + 1), posed for step k (the
// machine frame): what turns with the platform after that step.
std::vector<core::Vec3> printedPoints(const core::PrintJob& job, std::size_t k);

}  // namespace multidir::slicing

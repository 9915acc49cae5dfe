#pragma once
// The face two parts share at a joint, in the joint plane's frame, and rays through a part: what the dowels'
// and the part numbers' placement both measure (docs/apart.md).
#include <array>
#include <vector>

#include "geometry_kernels.h"
#include "multidir/core/apart/apart_plan.h"

namespace multidir::assembly {

using Point2 = Eigen::Vector2d;

bool inTriangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c);
double segmentDistance(const Point2& p, const Point2& a, const Point2& b);

// The shared face of a joint in the plane's frame: the upper part's cut-face triangles that lie on the lower
// part's cut face, and the shared region's boundary edges.
struct SharedFace {
  std::vector<std::array<Point2, 3>> triangles;
  std::vector<std::array<Point2, 2>> boundary;
  double areaMm2 = 0.0;
  Point2 low = Point2::Constant(INFINITY), high = Point2::Constant(-INFINITY);
  bool contains(const Point2& p) const;
  double distanceToBoundary(const Point2& p) const;
};

SharedFace sharedFace(const core::ApartPlan& plan, const core::ApartJoint& joint, const Frame& frame);

// How far a ray from the face goes through the part before it leaves (its own face excepted).
double depthAlong(const core::TriangleMesh& part, std::int32_t planeId, const Vec3& origin, const Vec3& direction);

}  // namespace multidir::assembly

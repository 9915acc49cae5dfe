#include "multidir/core/apart/apart_plan.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>

#include "common/fixed_text.h"
#include "mesh/mesh_shells.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/apart/bed_fit.h"
#include "multidir/core/geometry/clipping.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core {
namespace {

// The connected pieces of a region, each a part; when a piece is a cavity (negative volume) the region is
// kept whole, since a cavity belongs to the piece around it.
std::vector<TriangleMesh> piecesOf(const TriangleMesh& mesh) {
  const FaceComponents components = faceComponents(mesh);
  if (components.count <= 1) return {mesh};
  std::vector<TriangleMesh> pieces;
  for (const std::vector<std::int32_t>& faces : detail::facesOfComponents(components)) {
    TriangleMesh piece = detail::extractFaces(mesh, faces);
    // extractFaces keeps no origins: the cut faces must still name their planes (the joints).
    piece.origins.clear();
    for (std::int32_t f : faces) piece.origins.push_back(mesh.origins[static_cast<std::size_t>(f)]);
    if (signedVolume(piece) <= 0) return {mesh};
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// The plane moved along its normal (by at most a few hundredths of a millimetre) so that no vertex lies
// within a micrometre of it: a cut through vertices would leave slivers a binary STL cannot keep.
Plane clearOfVertices(Plane plane, const TriangleMesh& mesh) {
  constexpr double kClearanceMm = 1e-3;
  for (int attempt = 0; attempt < 32; ++attempt) {
    const bool touches = std::any_of(mesh.vertices.begin(), mesh.vertices.end(), [&](const Vec3& v) {
      return std::abs(plane.signedDistance(v)) < kClearanceMm;
    });
    if (!touches) break;
    plane.offset += 2.7 * kClearanceMm;
  }
  return plane;
}

std::string millimetres(double value) { return detail::fixedText(value, 1); }

std::string volumeText(const BuildVolume& v) {
  return millimetres(v.xMm) + " x " + millimetres(v.yMm) + " x " + millimetres(v.zMm) + " mm";
}

// The extent of a mesh along a unit axis: lowest and highest level.
std::pair<double, double> extentAlong(const TriangleMesh& mesh, const Vec3& axis) {
  double low = INFINITY, high = -INFINITY;
  for (const Vec3& p : mesh.vertices) {
    low = std::min(low, axis.dot(p));
    high = std::max(high, axis.dot(p));
  }
  return {low, high};
}

// The plane that halves an oversized part: across its height when it is too tall, else across the longest
// extent of its footprint (every degree in the bed's plane), so the halves keep the printing direction, their
// cut is vertical and as small as the part allows.
Plane halvingPlane(const TriangleMesh& mesh, const Vec3& direction, const BedPose& pose, const BuildVolume& v) {
  const Vec3 up = direction.normalized();
  Vec3 axis = up;
  if (pose.sizeMm.z() <= v.zMm) {
    // The footprint's smallest box (every degree over 90), cut across its longer side: a bar is cut square.
    const Vec3 helper = std::abs(up.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 u = up.cross(helper).normalized(), w = up.cross(u);
    double smallest = INFINITY;
    for (int degrees = 0; degrees < 90; ++degrees) {
      const double a = degToRad(degrees);
      const Vec3 x = std::cos(a) * u + std::sin(a) * w, y = up.cross(x);
      const auto [xLow, xHigh] = extentAlong(mesh, x);
      const auto [yLow, yHigh] = extentAlong(mesh, y);
      const double area = (xHigh - xLow) * (yHigh - yLow);
      if (area < smallest * (1 - 1e-9)) {
        smallest = area;
        axis = xHigh - xLow >= yHigh - yLow ? x : y;
      }
    }
  }
  const auto [low, high] = extentAlong(mesh, axis);
  return clearOfVertices(Plane{axis, 0.5 * (low + high)}, mesh);
}

// 2D point in triangle, on the plane's own axes.
struct PlaneAxes {
  Vec3 u, v;
  explicit PlaneAxes(const Vec3& n) {
    const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    u = n.cross(helper).normalized();
    v = n.cross(u);
  }
  Eigen::Vector2d at(const Vec3& p) const { return {u.dot(p), v.dot(p)}; }
};

bool inTriangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                const Eigen::Vector2d& c) {
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& x, const Eigen::Vector2d& y) {
    return (x - o).x() * (y - o).y() - (x - o).y() * (y - o).x();
  };
  const double d1 = cross(a, b, p), d2 = cross(b, c, p), d3 = cross(c, a, p);
  const bool negative = d1 < 0 || d2 < 0 || d3 < 0, positive = d1 > 0 || d2 > 0 || d3 > 0;
  return !(negative && positive);
}

struct CapFaces {
  std::vector<std::array<Eigen::Vector2d, 3>> triangles;
  std::vector<double> areas;
};

// Joints: on each plane, every part whose cap faces it from above against every part whose cap faces it
// from below, with the area of the upper cap whose triangles' centroids lie on the lower cap.
std::vector<ApartJoint> jointsOf(const std::vector<ApartPart>& parts, const std::vector<Plane>& planes) {
  std::vector<ApartJoint> joints;
  for (std::size_t id = 0; id < planes.size(); ++id) {
    const Plane& plane = planes[id];
    const PlaneAxes axes(plane.normal);
    std::map<int, CapFaces> uppers, lowers;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      const TriangleMesh& mesh = parts[p].mesh;
      for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!mesh.origins[f].isCap() || mesh.origins[f].index != static_cast<std::int32_t>(id)) continue;
        const Vec3 n = mesh.areaNormal(f);
        CapFaces& side = n.dot(plane.normal) < 0 ? uppers[static_cast<int>(p)] : lowers[static_cast<int>(p)];
        side.triangles.push_back({axes.at(mesh.corner(f, 0)), axes.at(mesh.corner(f, 1)), axes.at(mesh.corner(f, 2))});
        side.areas.push_back(0.5 * n.norm());
      }
    }
    for (const auto& [upper, upperCap] : uppers)
      for (const auto& [lower, lowerCap] : lowers) {
        double area = 0.0;
        for (std::size_t t = 0; t < upperCap.triangles.size(); ++t) {
          const auto& tri = upperCap.triangles[t];
          const Eigen::Vector2d centroid = (tri[0] + tri[1] + tri[2]) / 3.0;
          for (const auto& other : lowerCap.triangles)
            if (inTriangle(centroid, other[0], other[1], other[2])) {
              area += upperCap.areas[t];
              break;
            }
        }
        if (area > 0) joints.push_back(ApartJoint{lower, upper, plane, static_cast<std::int32_t>(id), area});
      }
  }
  return joints;
}

}  // namespace

Result<ApartPlan> apartPlan(const Decomposition& plan, const ApartOptions& options) {
  if (plan.regions.empty()) return Error{ErrorCode::InvalidParameter, "the plan has no regions", "plan"};
  ApartPlan apart;
  apart.planes = plan.clippingPlanes;

  struct Pending {
    TriangleMesh mesh;
    Vec3 direction;
    int region;
  };
  std::deque<Pending> pending;
  for (std::size_t r = 0; r < plan.regions.size(); ++r)
    for (TriangleMesh& piece : piecesOf(plan.regions[r].mesh))
      pending.push_back({std::move(piece), plan.regions[r].printingDirection.normalized(), static_cast<int>(r)});

  const BuildVolume& volume = options.buildVolume;
  while (!pending.empty()) {
    Pending next = std::move(pending.front());
    pending.pop_front();
    const BedPose pose = layOnBed(next.mesh, next.direction, volume);
    if (pose.fits) {
      ApartPart part;
      part.volumeMm3 = signedVolume(next.mesh);
      // Rule 2 of docs/jg-definition.md: each part printed alone on the bed.
      auto risky = riskyAreaOnPlatform(next.mesh, next.direction, options.alphaMaxDegrees, options.supportedBandMm);
      if (!risky.ok()) return risky.error();
      part.riskyAreaMm2 = *risky;
      part.mesh = std::move(next.mesh);
      part.printingDirection = next.direction;
      part.region = next.region;
      apart.jgMm2 += part.riskyAreaMm2;
      apart.parts.push_back(std::move(part));
      continue;
    }
    if (static_cast<int>(apart.parts.size() + pending.size()) + 2 > options.maxParts)
      return Error{ErrorCode::TooLarge,
                   "the model needs more than " + std::to_string(options.maxParts) +
                       " parts to fit the build volume " + volumeText(volume) + " (a part of region " +
                       std::to_string(next.region + 1) + " lies " + millimetres(pose.sizeMm.x()) + " x " +
                       millimetres(pose.sizeMm.y()) + " x " + millimetres(pose.sizeMm.z()) +
                       " mm): use a larger printer or scale the model down",
                   "build volume"};
    const Plane cut = halvingPlane(next.mesh, next.direction, pose, volume);
    const std::int32_t id = static_cast<std::int32_t>(apart.planes.size());
    auto clipped = clipByPlane(next.mesh, cut, id);
    if (!clipped.ok() || clipped->above.empty() || clipped->below.empty())
      return Error{ErrorCode::TooLarge,
                   "a part of region " + std::to_string(next.region + 1) + " (" + millimetres(pose.sizeMm.x()) +
                       " x " + millimetres(pose.sizeMm.y()) + " x " + millimetres(pose.sizeMm.z()) +
                       " mm) does not fit the build volume " + volumeText(volume) +
                       " and cannot be cut to fit: use a larger printer or scale the model down",
                   "build volume"};
    apart.planes.push_back(cut);
    ++apart.cutsToFit;
    for (TriangleMesh* side : {&clipped->below, &clipped->above})
      for (TriangleMesh& piece : piecesOf(*side)) pending.push_back({std::move(piece), next.direction, next.region});
  }
  apart.joints = jointsOf(apart.parts, apart.planes);
  return apart;
}

}  // namespace multidir::core

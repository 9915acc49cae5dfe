#include "multidir/core/geometry/connectivity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

#include "detail/mesh_indices.h"
#include "multidir/core/geometry/line_triangle.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core {
namespace {

struct Shell {
  double volume = 0.0;
  BoundingBox box;
  bool hasBox = false;
  std::vector<std::int32_t> faces;
  std::int32_t solid = -1;
};

bool boxInside(const BoundingBox& inner, const BoundingBox& outer) {
  return (inner.min.array() >= outer.min.array()).all() && (inner.max.array() <= outer.max.array()).all();
}

// Parity of the crossings of a ray from q with the shell's faces. The ray's direction is
// skewed off every axis so that it rarely grazes an edge of an axis-aligned model.
bool insideShell(const Vec3& q, const Shell& shell, const TriangleMesh& mesh) {
  const Vec3 dir = Vec3(0.5377, 0.6211, 0.5702).normalized();
  bool inside = false;
  for (std::int32_t f : shell.faces) {
    const std::optional<double> t =
        lineTriangleParameter(q, dir, mesh.corner(f, 0), mesh.corner(f, 1), mesh.corner(f, 2));
    if (t && *t > 0.0) inside = !inside;
  }
  return inside;
}

}  // namespace

Result<std::vector<TriangleMesh>> connectedSolids(const TriangleMesh& mesh) {
  if (Status s = detail::checkFaceIndices(mesh, "mesh"); !s) return s.error();
  std::vector<TriangleMesh> solids;
  if (mesh.triangles.empty()) return solids;

  const FaceComponents components = faceComponents(mesh);
  std::vector<Shell> shells(components.count);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    Shell& shell = shells[components.componentOfFace[f]];
    shell.faces.push_back(static_cast<std::int32_t>(f));
    const Vec3& a = mesh.corner(f, 0);
    shell.volume += a.dot(mesh.corner(f, 1).cross(mesh.corner(f, 2))) / 6.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.corner(f, k);
      if (!shell.hasBox) {
        shell.box.min = shell.box.max = p;
        shell.hasBox = true;
      }
      shell.box.min = shell.box.min.cwiseMin(p);
      shell.box.max = shell.box.max.cwiseMax(p);
    }
  }

  // Component ids follow the first face, so solids come in face order.
  std::int32_t solidCount = 0;
  for (Shell& shell : shells)
    if (shell.volume >= 0.0) shell.solid = solidCount++;
  std::vector<std::int32_t> bySize(shells.size());
  std::iota(bySize.begin(), bySize.end(), 0);
  std::sort(bySize.begin(), bySize.end(),
            [&](std::int32_t a, std::int32_t b) { return shells[a].volume < shells[b].volume; });
  for (Shell& cavity : shells) {
    if (cavity.volume >= 0.0) continue;
    const Vec3& probe = mesh.corner(cavity.faces.front(), 0);
    for (std::int32_t candidate : bySize) {
      const Shell& outer = shells[candidate];
      if (outer.volume < 0.0 || !boxInside(cavity.box, outer.box)) continue;
      if (insideShell(probe, outer, mesh)) {
        cavity.solid = outer.solid;
        break;
      }
    }
    // An inward shell inside no other is kept as a solid of its own rather than dropped.
    if (cavity.solid < 0) cavity.solid = solidCount++;
  }

  solids.resize(solidCount);
  std::vector<std::vector<std::int32_t>> facesOfSolid(solidCount);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    facesOfSolid[shells[components.componentOfFace[f]].solid].push_back(static_cast<std::int32_t>(f));
  // A vertex belongs to one shell, so one map serves every solid.
  std::vector<std::int32_t> local(mesh.vertices.size(), -1);
  for (std::int32_t s = 0; s < solidCount; ++s) {
    TriangleMesh& solid = solids[s];
    solid.triangles.reserve(facesOfSolid[s].size());
    solid.origins.reserve(facesOfSolid[s].size());
    for (std::int32_t f : facesOfSolid[s]) {
      Triangle t = mesh.triangles[f];
      for (std::int32_t& v : t) {
        if (local[v] < 0) {
          local[v] = static_cast<std::int32_t>(solid.vertices.size());
          solid.vertices.push_back(mesh.vertices[v]);
        }
        v = local[v];
      }
      solid.triangles.push_back(t);
      solid.origins.push_back(mesh.origins[f]);
    }
  }
  return solids;
}

double heightAbove(const TriangleMesh& mesh, const Plane& platform) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t) lowest = std::min(lowest, platform.signedDistance(mesh.vertices[v]));
  return std::isfinite(lowest) ? lowest : 0.0;
}

bool touchesPlatform(const TriangleMesh& solid, const Plane& platform, double toleranceMm) {
  if (solid.empty()) return false;
  return std::abs(heightAbove(solid, platform)) <= toleranceMm;
}

Result<std::vector<PlacedSolid>> connectedSolidsOnPlatform(const TriangleMesh& mesh, const Plane& platform,
                                                           double toleranceMm) {
  Result<std::vector<TriangleMesh>> solids = connectedSolids(mesh);
  if (!solids) return solids.error();
  std::vector<PlacedSolid> placed;
  placed.reserve(solids->size());
  for (TriangleMesh& solid : solids.value()) {
    const bool touches = touchesPlatform(solid, platform, toleranceMm);
    placed.push_back({std::move(solid), touches});
  }
  return placed;
}

Result<ClipSolids> connectedSolids(const ClipResult& clip) {
  Result<std::vector<TriangleMesh>> below = connectedSolids(clip.below);
  if (!below) return below.error();
  Result<std::vector<TriangleMesh>> above = connectedSolids(clip.above);
  if (!above) return above.error();
  return ClipSolids{std::move(below.value()), std::move(above.value())};
}

}  // namespace multidir::core

#include "multidir/core/mesh/mesh_resolution.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <unordered_map>

#include "detail/edge_key.h"
#include "mesh/quadric_decimation.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core {

Result<TriangleMesh> subdivided(const TriangleMesh& mesh, int levels) {
  if (levels < 0 || levels > 6)
    return Error{ErrorCode::InvalidParameter, "subdivide 0 to 6 times (each multiplies the faces by 4)", "subdivide"};
  if (static_cast<double>(mesh.triangles.size()) * std::pow(4.0, levels) > 2147483647.0)
    return Error{ErrorCode::InvalidParameter, "that many subdivisions would make more than 2^31 faces", "subdivide"};
  TriangleMesh current = mesh;
  for (int level = 0; level < levels; ++level) {
    TriangleMesh next;
    next.vertices = current.vertices;
    next.triangles.reserve(current.triangles.size() * 4);
    // Each edge's midpoint once, shared by the edge's two faces so the result stays closed.
    std::unordered_map<std::uint64_t, std::int32_t> midpoints;
    midpoints.reserve(current.triangles.size() * 2);
    auto midpoint = [&](std::int32_t a, std::int32_t b) {
      const std::uint64_t key = detail::undirectedEdgeKey(a, b);
      auto [it, inserted] = midpoints.emplace(key, static_cast<std::int32_t>(next.vertices.size()));
      if (inserted) next.vertices.push_back(0.5 * (current.vertices[a] + current.vertices[b]));
      return it->second;
    };
    for (const Triangle& t : current.triangles) {
      const std::int32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.triangles.push_back({t[0], ab, ca});
      next.triangles.push_back({ab, t[1], bc});
      next.triangles.push_back({ca, bc, t[2]});
      next.triangles.push_back({ab, bc, ca});
    }
    next.resetOrigins();
    current = std::move(next);
  }
  return current;
}

Result<DecimationResult> decimated(const TriangleMesh& mesh, std::size_t targetFaces, double freeToleranceMm,
                                   double maxVolumeChangePercent, int threads, std::size_t fineBelowFaces,
                                   double fineToleranceMm) {
  if (targetFaces < 100)
    return Error{ErrorCode::InvalidParameter, "decimate to at least 100 faces", "decimate"};
  if (!(freeToleranceMm >= 0.0 && std::isfinite(freeToleranceMm)))
    return Error{ErrorCode::InvalidParameter, "the decimation tolerance must be a finite length >= 0 mm", "decimate"};
  if (threads < 0) return Error{ErrorCode::InvalidParameter, "the decimation's threads must be >= 0 (0: all)", "decimate"};
  // The decimator checks the input is a closed oriented 2-manifold on its own (a mesh from loadMesh is, but a
  // caller may pass any mesh), from the vertex lists it builds anyway; the census, which sorts every
  // half-edge, only runs to say what is wrong.
  std::optional<TriangleMesh> simplified = detail::quadricDecimation(mesh, targetFaces, freeToleranceMm, threads, fineBelowFaces,
                                                                            fineToleranceMm);
  if (!simplified) {
    const std::int32_t vertexCount = static_cast<std::int32_t>(mesh.vertices.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for (const std::int32_t v : mesh.triangles[f])
        if (v < 0 || v >= vertexCount)
          return Error{ErrorCode::InvalidParameter,
                       "face " + std::to_string(f) + " names vertex " + std::to_string(v) + " of " +
                           std::to_string(vertexCount) + "; load the mesh with loadMesh",
                       "decimate"};
    const EdgeCensus census = edgeCensus(mesh);
    return Error{ErrorCode::NotManifold,
                 "only a closed, consistently oriented 2-manifold can be decimated (" + std::to_string(census.boundary) +
                     " open, " + std::to_string(census.nonManifold) + " non-manifold, " +
                     std::to_string(census.misoriented) + " misoriented edges, " +
                     std::to_string(census.nonManifoldVertices) + " non-manifold vertices); repair the mesh first",
                 "decimate"};
  }
  DecimationResult out;
  out.mesh = std::move(*simplified);
  const double before = signedVolume(mesh), after = signedVolume(out.mesh);
  out.volumeChangePercent = before > 0 ? 100.0 * std::abs(after - before) / before : 100.0;
  if (!edgeCensus(out.mesh).closedOriented())
    return Error{ErrorCode::CheckFailed, "the decimated mesh is not closed any more", "decimate"};
  if (!(out.volumeChangePercent <= maxVolumeChangePercent)) {
    char text[160];
    std::snprintf(text, sizeof text, "decimating changed the volume by %.2f %% (at most %.2f %% allowed)",
                  out.volumeChangePercent, maxVolumeChangePercent);
    return Error{ErrorCode::CheckFailed, text, "decimate"};
  }
  return out;
}

}  // namespace multidir::core

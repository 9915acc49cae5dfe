#include <algorithm>

#include "mesh/mesh_shells.h"
#include "multidir/core/mesh/mesh_io.h"

namespace multidir::core {

MeshStatistics computeStatistics(const TriangleMesh& mesh) {
  return detail::computeStatistics(mesh, !mesh.empty() && edgeCensus(mesh).closedOriented());
}

MeshStatistics detail::computeStatistics(const TriangleMesh& mesh, bool closedOriented) {
  MeshStatistics s;
  s.triangles = mesh.triangles.size();
  const FaceComponents components = faceComponents(mesh);
  // Faces and used vertices of each shell.
  std::vector<long long> faces(static_cast<std::size_t>(components.count), 0), vertices(faces.size(), 0);
  std::vector<char> used(mesh.vertices.size(), 0);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto shell = static_cast<std::size_t>(components.componentOfFace[f]);
    ++faces[shell];
    for (std::int32_t v : mesh.triangles[f])
      if (!used[static_cast<std::size_t>(v)]) {
        used[static_cast<std::size_t>(v)] = 1;
        ++vertices[shell];
      }
  }
  s.vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  s.shells = static_cast<std::size_t>(components.count);
  s.bounds = boundingBox(mesh);
  s.areaMm2 = surfaceArea(mesh);
  s.volumeMm3 = signedVolume(mesh);
  s.closed = closedOriented;
  if (s.closed) {
    // A closed shell has 3F/2 edges, so chi = V - E + F = V - F/2 = 2 - 2g.
    for (std::size_t shell = 0; shell < faces.size(); ++shell) s.genus += (2 - (vertices[shell] - faces[shell] / 2)) / 2;
  }
  return s;
}

}  // namespace multidir::core

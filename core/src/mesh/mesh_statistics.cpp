#include <algorithm>

#include "mesh/mesh_shells.h"
#include "multidir/core/mesh/mesh_io.h"

namespace multidir::core {

MeshStatistics computeStatistics(const TriangleMesh& mesh) {
  MeshStatistics s;
  s.triangles = mesh.triangles.size();
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t) used[static_cast<std::size_t>(v)] = 1;
  s.vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  const FaceComponents components = faceComponents(mesh);
  s.shells = static_cast<std::size_t>(components.count);
  s.bounds = boundingBox(mesh);
  s.areaMm2 = surfaceArea(mesh);
  s.volumeMm3 = signedVolume(mesh);
  s.closed = !mesh.empty() && edgeCensus(mesh).closedOriented();
  if (s.closed) {
    // chi = 2 - 2g for each closed orientable shell.
    for (const auto& faces : detail::facesOfComponents(components))
      s.genus += (2 - eulerCharacteristic(detail::extractFaces(mesh, faces))) / 2;
  }
  return s;
}

}  // namespace multidir::core

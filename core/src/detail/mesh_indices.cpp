#include "detail/mesh_indices.h"

#include <cstdint>

namespace multidir::core::detail {

Status checkFaceIndices(const TriangleMesh& mesh, const std::string& what) {
  if (mesh.origins.size() != mesh.triangles.size())
    return Error{ErrorCode::InvalidParameter,
                 "the " + what + " has " + std::to_string(mesh.origins.size()) + " face origins for " +
                     std::to_string(mesh.triangles.size()) + " faces; call resetOrigins() after building a mesh",
                 what + ".origins"};
  const auto vertexCount = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (std::int32_t v : mesh.triangles[f])
      if (v < 0 || v >= vertexCount)
        return Error{
            ErrorCode::InvalidParameter,
            "vertex index " + std::to_string(v) + " is outside the " + std::to_string(vertexCount) + " vertices",
            "face " + std::to_string(f)};
  return Done{};
}

}  // namespace multidir::core::detail

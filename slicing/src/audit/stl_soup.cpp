#include "stl_soup.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace multidir::slicing::audit {

namespace {

using core::Error;
using core::ErrorCode;

void addTriangle(core::TriangleMesh& mesh, const core::Vec3& a, const core::Vec3& b, const core::Vec3& c) {
  const auto base = static_cast<std::int32_t>(mesh.vertices.size());
  mesh.vertices.push_back(a);
  mesh.vertices.push_back(b);
  mesh.vertices.push_back(c);
  mesh.triangles.push_back({base, base + 1, base + 2});
}

}  // namespace

core::Result<core::TriangleMesh> readStlSoup(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::FileNotFound, "cannot read the file", path};
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string bytes = buffer.str();
  core::TriangleMesh mesh;
  std::uint32_t count = 0;
  if (bytes.size() >= 84) std::memcpy(&count, bytes.data() + 80, 4);
  if (bytes.size() >= 84 && bytes.size() == 84 + 50 * static_cast<std::size_t>(count)) {
    for (std::uint32_t t = 0; t < count; ++t) {
      const char* record = bytes.data() + 84 + 50 * static_cast<std::size_t>(t) + 12;
      core::Vec3 corner[3];
      for (int k = 0; k < 3; ++k) {
        float xyz[3];
        std::memcpy(xyz, record + 12 * k, 12);
        if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
          return Error{ErrorCode::MalformedFile,
                       "triangle " + std::to_string(t) + " has a coordinate that is not finite", path};
        corner[k] = core::Vec3(xyz[0], xyz[1], xyz[2]);
      }
      addTriangle(mesh, corner[0], corner[1], corner[2]);
    }
  } else {
    std::istringstream text(bytes);
    std::string word;
    std::vector<core::Vec3> corners;
    while (text >> word) {
      if (word != "vertex") continue;
      core::Vec3 v;
      if (!(text >> v.x() >> v.y() >> v.z()) || !v.allFinite())
        return Error{ErrorCode::MalformedFile, "a vertex is not three finite numbers (neither binary nor ASCII STL?)",
                     path};
      corners.push_back(v);
      if (corners.size() == 3) {
        addTriangle(mesh, corners[0], corners[1], corners[2]);
        corners.clear();
      }
    }
  }
  if (mesh.triangles.empty())
    return Error{ErrorCode::MalformedFile, "no triangles (neither a binary STL of the right size nor ASCII STL)", path};
  mesh.resetOrigins();
  return mesh;
}

}  // namespace multidir::slicing::audit

// saveMesh: text formats with every double kept (17 significant digits), binary or ASCII STL.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "multidir/core/common/atomic_file.h"
#include "mesh/mesh_formats.h"
#include "multidir/core/mesh/mesh_io.h"

namespace multidir::core {
namespace {

namespace fs = std::filesystem;

void writeOff(const TriangleMesh& mesh, std::ostream& out) {
  out << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
  for (const Vec3& p : mesh.vertices) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Triangle& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

void writeObj(const TriangleMesh& mesh, std::ostream& out) {
  out << "# written by MultiDir, millimetres\n";
  for (const Vec3& p : mesh.vertices) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Triangle& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

void writePly(const TriangleMesh& mesh, std::ostream& out) {
  out << "ply\nformat ascii 1.0\ncomment written by MultiDir, millimetres\n"
      << "element vertex " << mesh.vertices.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : mesh.vertices) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Triangle& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

}  // namespace

Status saveMesh(const TriangleMesh& mesh, const std::string& path, const SaveOptions& options) {
  const fs::path target(path);
  const std::string name = target.filename().string();
  std::string ext = target.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".stl" && ext != ".obj" && ext != ".off" && ext != ".ply")
    return Error{ErrorCode::UnsupportedFormat,
                 "cannot save as '" + ext + "'; MultiDir writes .stl, .obj, .off and .ply", name};
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (std::int32_t v : mesh.triangles[f])
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size())
        return Error{ErrorCode::InvalidParameter,
                     "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", which does not exist",
                     name};

  // Written beside the target and renamed into place: a failed save leaves any old file as it was.
  return writeFileAtomically(path, name, [&](std::ostream& out) -> Status {
    out.precision(17);
    if (ext == ".stl") return detail::writeStl(mesh, out, options.asciiStl);
    if (ext == ".off") writeOff(mesh, out);
    else if (ext == ".obj") writeObj(mesh, out);
    else writePly(mesh, out);
    return Done{};
  });
}

}  // namespace multidir::core

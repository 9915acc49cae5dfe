#include "mesh/mesh_shells.h"

#include <cmath>
#include <unordered_map>

#include "multidir/core/common/units.h"

namespace multidir::core::detail {

std::vector<std::vector<std::int32_t>> facesOfComponents(const FaceComponents& components) {
  std::vector<std::vector<std::int32_t>> out(static_cast<std::size_t>(components.count));
  for (std::size_t f = 0; f < components.componentOfFace.size(); ++f)
    out[static_cast<std::size_t>(components.componentOfFace[f])].push_back(static_cast<std::int32_t>(f));
  return out;
}

TriangleMesh extractFaces(const TriangleMesh& mesh, const std::vector<std::int32_t>& faces) {
  TriangleMesh out;
  std::unordered_map<std::int32_t, std::int32_t> newIndex;
  newIndex.reserve(faces.size());
  out.triangles.reserve(faces.size());
  for (std::int32_t f : faces) {
    Triangle t = mesh.triangles[static_cast<std::size_t>(f)];
    for (std::int32_t& v : t) {
      auto [it, inserted] = newIndex.emplace(v, static_cast<std::int32_t>(out.vertices.size()));
      if (inserted) out.vertices.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
      v = it->second;
    }
    out.triangles.push_back(t);
  }
  return out;
}

double windingNumber(const TriangleMesh& shell, const Vec3& point) {
  double total = 0.0;
  for (const Triangle& t : shell.triangles) {
    const Vec3 a = shell.vertices[static_cast<std::size_t>(t[0])] - point;
    const Vec3 b = shell.vertices[static_cast<std::size_t>(t[1])] - point;
    const Vec3 c = shell.vertices[static_cast<std::size_t>(t[2])] - point;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    // Van Oosterom and Strackee's formula for the solid angle of a triangle.
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return total / (4.0 * kPi);
}

}  // namespace multidir::core::detail

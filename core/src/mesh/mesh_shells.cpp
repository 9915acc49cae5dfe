#include "mesh/mesh_shells.h"

#include <algorithm>
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

Containment containment(const TriangleMesh& shell, const TriangleMesh& other, const BoundingBox& otherBox) {
  // A point on the box's faces may still be on `other`'s surface; the slack keeps such points for the
  // winding-number test, which then calls them undecided.
  const double slack = 1e-9 * std::max(1.0, (otherBox.max - otherBox.min).norm());
  const Vec3 low = otherBox.min - Vec3::Constant(slack), high = otherBox.max + Vec3::Constant(slack);
  std::vector<std::size_t> inBox;
  std::size_t outside = 0;
  for (std::size_t v = 0; v < shell.vertices.size(); ++v) {
    const Vec3& p = shell.vertices[v];
    if ((p.array() < low.array()).any() || (p.array() > high.array()).any()) ++outside;
    else inBox.push_back(v);
  }
  std::size_t inside = 0;
  const std::size_t probes = std::min(inBox.size(), kContainmentProbes);
  for (std::size_t k = 0; k < probes; ++k) {
    const std::size_t v = inBox[k * inBox.size() / probes];
    const double winding = std::abs(windingNumber(other, shell.vertices[v]));
    if (winding > 0.75) ++inside;
    else if (winding < 0.25) ++outside;
  }
  if (inside > 0 && outside > 0) return Containment::Crossing;
  return inside > 0 ? Containment::Inside : Containment::Outside;
}

}  // namespace multidir::core::detail

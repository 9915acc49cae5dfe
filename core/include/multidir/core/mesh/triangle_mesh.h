#pragma once
// The solid MultiDir works on: an indexed triangle mesh in millimetres, plus where each face came from.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()
#include <array>
#include <cstdint>
#include <vector>

namespace multidir::core {

// Where a face came from. A face of the loaded model is {Surface, its index in the loaded mesh};
// a face of the cap that clipping plane k closed is {Cap, k}. Clipping keeps the origin of every
// piece of a split face, so J_G and supports can tell model surface from cut surface.
struct FaceOrigin {
  enum class Kind : std::uint8_t { Surface, Cap };
  Kind kind = Kind::Surface;
  std::int32_t index = 0;  // Surface: face index in the loaded mesh; Cap: clipping plane id

  static FaceOrigin surface(std::int32_t face) { return {Kind::Surface, face}; }
  static FaceOrigin cap(std::int32_t planeId) { return {Kind::Cap, planeId}; }
  bool isCap() const { return kind == Kind::Cap; }
  bool operator==(const FaceOrigin& o) const { return kind == o.kind && index == o.index; }
  bool operator!=(const FaceOrigin& o) const { return !(*this == o); }
};

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<std::int32_t, 3>;

// Invariants of a mesh that passed checking (MeshCheck): every index is in range, faces are
// counter-clockwise seen from outside (normals point out), every edge has exactly two faces,
// volume is positive, and origins.size() == triangles.size().
struct TriangleMesh {
  std::vector<Vec3> vertices;        // mm
  std::vector<Triangle> triangles;   // vertex indices, CCW from outside
  std::vector<FaceOrigin> origins;   // one per triangle

  std::size_t faceCount() const { return triangles.size(); }
  std::size_t vertexCount() const { return vertices.size(); }
  bool empty() const { return triangles.empty(); }

  const Vec3& corner(std::size_t face, int k) const { return vertices[triangles[face][k]]; }
  // Unnormalised normal: its length is twice the face's area.
  Vec3 areaNormal(std::size_t face) const {
    const Vec3& a = corner(face, 0);
    return (corner(face, 1) - a).cross(corner(face, 2) - a);
  }
  double faceArea(std::size_t face) const { return 0.5 * areaNormal(face).norm(); }
  Vec3 faceNormal(std::size_t face) const { return areaNormal(face).normalized(); }

  // Gives every face a Surface origin equal to its own index (done once after loading).
  void resetOrigins() {
    origins.resize(triangles.size());
    for (std::size_t f = 0; f < triangles.size(); ++f) origins[f] = FaceOrigin::surface(static_cast<std::int32_t>(f));
  }
};

}  // namespace multidir::core

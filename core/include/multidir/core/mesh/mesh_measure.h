#pragma once
// Measures of a triangle mesh that every module needs: volume, area, bounds, and an edge census that
// tells whether the mesh is a closed, consistently oriented 2-manifold.
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

struct BoundingBox {
  Vec3 min = Vec3::Constant(0.0);
  Vec3 max = Vec3::Constant(0.0);
  Vec3 size() const { return max - min; }
  Vec3 center() const { return 0.5 * (min + max); }
};

// Signed volume (mm^3) by the divergence theorem: positive for a closed mesh whose normals point out.
double signedVolume(const TriangleMesh& mesh);
// Sum of face areas (mm^2).
double surfaceArea(const TriangleMesh& mesh);
// Axis-aligned bounds of the vertices that faces use; all zero for an empty mesh.
BoundingBox boundingBox(const TriangleMesh& mesh);

// How the undirected edges of a mesh are shared. A closed, consistently oriented 2-manifold surface has
// boundary == nonManifold == misoriented == 0 and nonManifoldVertices == 0.
struct EdgeCensus {
  std::size_t edges = 0;             // distinct undirected edges
  std::size_t boundary = 0;          // edges with exactly one face
  std::size_t nonManifold = 0;       // edges with three or more faces
  std::size_t misoriented = 0;       // two-face edges traversed the same way by both faces
  std::size_t nonManifoldVertices = 0;  // vertices whose faces form more than one fan
  bool closedOriented() const { return boundary == 0 && nonManifold == 0 && misoriented == 0 && nonManifoldVertices == 0; }
};
EdgeCensus edgeCensus(const TriangleMesh& mesh);

// Connected components through shared vertices: the component index of each face, and their count.
struct FaceComponents {
  std::vector<std::int32_t> componentOfFace;
  std::int32_t count = 0;
};
FaceComponents faceComponents(const TriangleMesh& mesh);

// Euler characteristic V - E + F over the vertices that faces use.
long long eulerCharacteristic(const TriangleMesh& mesh);

}  // namespace multidir::core

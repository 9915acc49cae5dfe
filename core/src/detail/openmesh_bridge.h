#pragma once
// Our TriangleMesh to and from OpenMesh's half-edge mesh, for the algorithms OpenMesh does well (edge
// collapses, quadric decimation). Only .cpp files of core include this: OpenMesh stays out of the API.
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

struct OpenMeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using HalfEdgeMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshTraits>;

inline Vec3 toEigen(const OpenMesh::Vec3d& p) { return Vec3(p[0], p[1], p[2]); }

// A closed, consistently oriented 2-manifold as a half-edge mesh with vertex, edge and face status. Errors
// (NotManifold, InvalidParameter) say what is wrong and that `what` (e.g. "coarsen") needs a repaired mesh.
Status toHalfEdgeMesh(const TriangleMesh& input, HalfEdgeMesh& mesh, const std::string& what);
// Back, after garbage collection: faces in OpenMesh's order, origins reset.
TriangleMesh fromHalfEdgeMesh(HalfEdgeMesh& mesh);

}  // namespace multidir::core::detail

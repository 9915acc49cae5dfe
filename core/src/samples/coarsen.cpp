// OpenMesh's VectorT has a deliberately empty default constructor, and its property vectors push such
// values; GCC then warns about a copy of uninitialised memory deep inside std::vector. The values are
// always overwritten before use, so the warning is silenced for this file only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "multidir/core/samples/coarsen.h"

#include "detail/openmesh_bridge.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "multidir/core/common/units.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core::samples {
namespace {

using Mesh = detail::HalfEdgeMesh;
using detail::toEigen;

// 4 sqrt(3) area / (sum of squared edge lengths): 1 for an equilateral triangle, 0 for a degenerate one.
double quality(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double squares = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  if (squares <= 0.0) return 0.0;
  return 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / squares;
}

class EdgeCollapser {
 public:
  // Collapses never add vertices, so the point array stays where it is; reading it directly avoids
  // OpenMesh's by-name property look-up on every access.
  EdgeCollapser(Mesh& mesh, const CoarsenOptions& options)
      : m_mesh(mesh),
        m_points(mesh.points()),
        m_options(options),
        m_cosMaxTurn(std::cos(degToRad(options.maxNormalTurnDegrees))) {}

  // One sweep over the edges in index order; returns how many collapses it made.
  std::size_t sweep() {
    std::size_t collapses = 0;
    for (std::size_t e = 0; e < m_mesh.n_edges(); ++e) {
      const Mesh::EdgeHandle edge(static_cast<int>(e));
      if (m_mesh.status(edge).deleted()) continue;
      const Mesh::HalfedgeHandle h0 = m_mesh.halfedge_handle(edge, 0);
      if (length(h0) >= m_options.minEdgeMm) continue;
      for (Mesh::HalfedgeHandle h : {h0, m_mesh.opposite_halfedge_handle(h0)}) {
        if (collapseKeepsShape(h) && m_mesh.is_collapse_ok(h)) {
          m_mesh.collapse(h);
          ++collapses;
          break;
        }
      }
    }
    return collapses;
  }

 private:
  Vec3 point(Mesh::VertexHandle v) const { return toEigen(m_points[v.idx()]); }
  double length(Mesh::HalfedgeHandle h) const {
    return (point(m_mesh.to_vertex_handle(h)) - point(m_mesh.from_vertex_handle(h))).norm();
  }

  // Moving the from-vertex onto the to-vertex: checks the edges and faces that would change.
  bool collapseKeepsShape(Mesh::HalfedgeHandle h) const {
    const Mesh::VertexHandle from = m_mesh.from_vertex_handle(h);
    const Mesh::VertexHandle to = m_mesh.to_vertex_handle(h);
    const Vec3 target = point(to);
    for (Mesh::VertexHandle w : m_mesh.vv_range(from))
      if (w != to && (point(w) - target).norm() > m_options.maxEdgeMm) return false;
    for (Mesh::FaceHandle f : m_mesh.vf_range(from)) {
      std::array<Vec3, 3> before{};
      std::array<Vec3, 3> after{};
      int k = 0;
      bool touchesTo = false;
      for (Mesh::VertexHandle v : m_mesh.fv_range(f)) {
        touchesTo = touchesTo || v == to;
        before[k] = point(v);
        after[k] = v == from ? target : before[k];
        ++k;
      }
      if (touchesTo) continue;  // this face disappears with the edge
      const Vec3 oldNormal = (before[1] - before[0]).cross(before[2] - before[0]);
      const Vec3 newNormal = (after[1] - after[0]).cross(after[2] - after[0]);
      const double oldLength = oldNormal.norm();
      const double newLength = newNormal.norm();
      if (!(newLength > 0.0) || !(oldLength > 0.0)) return false;
      if (oldNormal.dot(newNormal) < m_cosMaxTurn * oldLength * newLength) return false;
      const double required = std::min(m_options.minFaceQuality, quality(before[0], before[1], before[2]));
      if (quality(after[0], after[1], after[2]) < required) return false;
    }
    return true;
  }

  Mesh& m_mesh;
  const Mesh::Point* m_points;
  const CoarsenOptions& m_options;
  double m_cosMaxTurn;
};

Error invalid(const std::string& message) { return Error{ErrorCode::InvalidParameter, message, "coarsen"}; }

}  // namespace

Result<TriangleMesh> collapseShortEdges(const TriangleMesh& input, const CoarsenOptions& options) {
  if (!(std::isfinite(options.minEdgeMm) && options.minEdgeMm >= 0.0))
    return invalid("the shortest edge to keep must be a finite length >= 0 mm");
  if (!(std::isfinite(options.maxEdgeMm) && options.maxEdgeMm > options.minEdgeMm))
    return invalid("the longest edge a collapse may create must be finite and above the shortest edge to keep");
  if (!(options.maxNormalTurnDegrees >= 0.0 && options.maxNormalTurnDegrees <= 90.0))
    return invalid("the largest normal turn must be in [0, 90] degrees");
  if (!(options.minFaceQuality >= 0.0 && options.minFaceQuality < 1.0))
    return invalid("the face quality bound must be in [0, 1)");
  if (options.maxPasses < 0) return invalid("the number of passes must be >= 0");

  Mesh mesh;
  if (Status s = detail::toHalfEdgeMesh(input, mesh, "coarsened"); !s) return s.error();

  EdgeCollapser collapser(mesh, options);
  for (int pass = 0; pass < options.maxPasses; ++pass)
    if (collapser.sweep() == 0) break;
  return detail::fromHalfEdgeMesh(mesh);
}

}  // namespace multidir::core::samples

#include "search/floating_pieces.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "detail/union_find.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/geometry/clipping.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core::detail {
namespace {

struct Piece {
  double lowestMm = std::numeric_limits<double>::infinity();  // along up, less the margin where the clip may move
  bool reachesPlane = false;
  // Box of its cross-section (and corners near it) in the plane's own coordinates: nested cross-sections
  // have nested boxes there.
  Eigen::Vector2d boxMin = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d boxMax = Eigen::Vector2d::Constant(-std::numeric_limits<double>::infinity());
};

bool boxesOverlap(const Piece& a, const Piece& b, double margin) {
  return ((a.boxMin.array() - margin) <= b.boxMax.array()).all() && ((b.boxMin.array() - margin) <= a.boxMax.array()).all();
}

}  // namespace

double clipMarginMm(const TriangleMesh& model) {
  const BoundingBox box = boundingBox(model);
  return 2e-3 * (box.max - box.min).norm() + kMaxPlaneToleranceMm + 64.0 * inPlaneToleranceMm(model);
}

bool certainlyLeavesFloatingPiece(const TriangleMesh& solid, const Plane& plane, const Vec3& up,
                                  double platformLevelMm, double marginMm) {
  // Signed distances; "below" includes everything the clip might still put below (within the margin), which
  // joins more and keeps the answer on the safe side.
  std::vector<double> distance(solid.vertices.size());
  for (std::size_t v = 0; v < distance.size(); ++v) distance[v] = plane.signedDistance(solid.vertices[v]);
  auto below = [&](std::int32_t v) { return distance[v] < marginMm; };

  UnionFind sets(solid.vertices.size());
  std::vector<char> inFaceBelow(solid.vertices.size(), 0);  // a corner below the plane of some face
  for (const Triangle& t : solid.triangles) {
    std::int32_t first = -1;
    for (std::int32_t v : t) {
      if (!below(v)) continue;
      inFaceBelow[static_cast<std::size_t>(v)] = 1;
      if (first < 0) first = v;
      else sets.unite(first, v);
    }
  }
  std::vector<std::int32_t> pieceOfRoot(solid.vertices.size(), -1);
  std::vector<Piece> pieces;
  // Any two directions across the normal: only the boxes' nesting matters.
  const Vec3 across = std::abs(plane.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = plane.normal.cross(across).normalized();
  const Vec3 v = plane.normal.cross(u);
  auto addToBox = [&](Piece& piece, const Vec3& p) {
    const Eigen::Vector2d inPlane(u.dot(p), v.dot(p));
    piece.reachesPlane = true;
    piece.boxMin = piece.boxMin.cwiseMin(inPlane);
    piece.boxMax = piece.boxMax.cwiseMax(inPlane);
  };
  auto pieceOf = [&](std::int32_t vertex) -> Piece& {
    std::int32_t& id = pieceOfRoot[sets.find(vertex)];
    if (id < 0) {
      id = static_cast<std::int32_t>(pieces.size());
      pieces.emplace_back();
    }
    return pieces[id];
  };
  // A piece's lowest point and box are a minimum and a maximum over its corners below the plane and the points
  // where its faces' edges cross the plane: each corner counts once, whichever faces hold it (it used to be
  // measured once per face around it), and only the faces that cross the plane have crossings.
  for (std::size_t a = 0; a < distance.size(); ++a) {
    if (!inFaceBelow[a]) continue;
    Piece& piece = pieceOf(static_cast<std::int32_t>(a));
    const Vec3& pa = solid.vertices[a];
    // A corner farther than the margin from the plane is never moved by the clip: its height is exact.
    // Points at the plane may move by up to the margin.
    if (distance[a] <= -marginMm) {
      piece.lowestMm = std::min(piece.lowestMm, up.dot(pa));
    } else {
      piece.lowestMm = std::min(piece.lowestMm, up.dot(pa) - marginMm);
      addToBox(piece, pa);
    }
  }
  for (const Triangle& t : solid.triangles) {
    const bool negative[3] = {distance[t[0]] < 0.0, distance[t[1]] < 0.0, distance[t[2]] < 0.0};
    if (negative[0] == negative[1] && negative[1] == negative[2]) continue;  // no edge crosses the plane
    // A corner below 0 is below the margin too: the face's piece is that corner's.
    Piece& piece = pieceOf(t[negative[0] ? 0 : negative[1] ? 1 : 2]);
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = t[k], b = t[(k + 1) % 3];
      if (negative[k] == negative[(k + 1) % 3]) continue;
      const Vec3& pa = solid.vertices[a];
      const Vec3 crossing = pa + (solid.vertices[b] - pa) * (distance[a] / (distance[a] - distance[b]));
      piece.lowestMm = std::min(piece.lowestMm, up.dot(crossing) - marginMm);
      addToBox(piece, crossing);
    }
  }
  const double level = platformLevelMm;
  // Pieces at the plane whose boxes overlap may share a cap (one's cross-section inside the other's), and
  // through it others: group them, and a group with a piece that may stand may stand as a whole.
  UnionFind groups(pieces.size());
  for (std::size_t a = 0; a < pieces.size(); ++a)
    for (std::size_t b = a + 1; b < pieces.size(); ++b)
      if (pieces[a].reachesPlane && pieces[b].reachesPlane && boxesOverlap(pieces[a], pieces[b], marginMm))
        groups.unite(static_cast<std::int32_t>(a), static_cast<std::int32_t>(b));
  std::vector<char> groupMayStand(pieces.size(), 0);
  for (std::size_t p = 0; p < pieces.size(); ++p)
    if (pieces[p].lowestMm <= level) groupMayStand[groups.find(static_cast<std::int32_t>(p))] = 1;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    if (pieces[p].lowestMm <= level) continue;
    if (!pieces[p].reachesPlane) return true;  // a whole shell below the plane, clear of the platform
    if (!groupMayStand[groups.find(static_cast<std::int32_t>(p))]) return true;
  }
  return false;
}

}  // namespace multidir::core::detail

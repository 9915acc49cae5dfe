#include "multidir/core/geometry/clipping.h"
#include "detail/edge_key.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "geometry/cross_section_cap.h"
#include "detail/huge_pages.h"
#include "detail/mesh_indices.h"
#include "detail/union_find.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core {
namespace {

constexpr double kUnitLengthTolerance = 1e-9;
// How close (relative to its heights) a vertex must be to be moved onto the plane: see PlaneSplitter::snapData.
constexpr double kSnapRatio = 1e-3;

Status checkPlane(const Plane& plane, const ClipOptions& options) {
  if (!plane.normal.allFinite() || std::abs(plane.normal.norm() - 1.0) > kUnitLengthTolerance)
    return Error{ErrorCode::InvalidParameter,
                 "the clipping plane's normal must be a finite unit vector (its length is " +
                     std::to_string(plane.normal.norm()) + "); normalise it first",
                 "plane.normal"};
  if (!std::isfinite(plane.offset))
    return Error{ErrorCode::InvalidParameter, "the clipping plane's offset is not finite", "plane.offset"};
  // Vertices within the tolerance are moved onto the plane: that is meant to absorb rounding, and a larger
  // move changes the solid (5 mm left open sides and lost 4.5 % of a model's volume).
  if (!std::isfinite(options.planeToleranceMm) || options.planeToleranceMm < 0.0 ||
      options.planeToleranceMm > kMaxPlaneToleranceMm)
    return Error{ErrorCode::InvalidParameter,
                 "the plane tolerance must be a distance from 0 to " + std::to_string(kMaxPlaneToleranceMm) +
                     " mm (it absorbs rounding; vertices within it are moved onto the plane), not " +
                     std::to_string(options.planeToleranceMm),
                 "planeToleranceMm"};
  return Done{};
}

// Every half-edge a->b must meet exactly one b->a and no second a->b: closed, manifold edges, one orientation.
// Outgoing edges per vertex in a counting-sorted array keep this O(F) without hashing.
Status checkClosedOriented(const TriangleMesh& mesh) {
  const std::size_t vertexCount = mesh.vertices.size();
  std::vector<std::int32_t> first(vertexCount + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t) ++first[v + 1];
  for (std::size_t i = 0; i < vertexCount; ++i) first[i + 1] += first[i];
  std::vector<std::int32_t> target(mesh.triangles.size() * 3);
  {
    std::vector<std::int32_t> cursor(first.begin(), first.end() - 1);
    for (const Triangle& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) target[cursor[t[k]]++] = t[(k + 1) % 3];
  }
  auto count = [&](std::int32_t from, std::int32_t to) {
    return std::count(target.begin() + first[from], target.begin() + first[from + 1], to);
  };

  std::size_t open = 0, misoriented = 0, nonManifold = 0;
  std::size_t firstOpen = 0, firstMisoriented = 0, firstNonManifold = 0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = t[k], b = t[(k + 1) % 3];
      const auto forward = count(a, b);
      const auto backward = count(b, a);
      if (a == b || forward + backward > 2) {
        if (nonManifold++ == 0) firstNonManifold = f;
      } else if (forward == 2) {
        if (misoriented++ == 0) firstMisoriented = f;
      } else if (backward == 0) {
        if (open++ == 0) firstOpen = f;
      }
    }
  }
  const std::string advice =
      "; clipping needs a closed, consistently oriented solid (load it with loadMesh, "
      "which repairs or rejects such meshes)";
  if (nonManifold > 0)
    return Error{ErrorCode::NotManifold,
                 std::to_string(nonManifold) + " face edges are shared by more than two faces or degenerate" + advice,
                 "face " + std::to_string(firstNonManifold)};
  if (misoriented > 0)
    return Error{ErrorCode::InconsistentOrientation,
                 std::to_string(misoriented) + " face edges are traversed the same way by both their faces" + advice,
                 "face " + std::to_string(firstMisoriented)};
  if (open > 0)
    return Error{ErrorCode::OpenBoundary, std::to_string(open) + " edges have only one face" + advice,
                 "face " + std::to_string(firstOpen)};
  if (signedVolume(mesh) <= 0.0)
    return Error{ErrorCode::InconsistentOrientation,
                 "the solid is inside out (its volume is not positive): its faces must be counter-clockwise seen "
                 "from outside",
                 "solid"};
  return Done{};
}

Status checkSolid(const TriangleMesh& mesh, bool checkClosed) {
  if (mesh.triangles.empty() || mesh.vertices.empty())
    return Error{ErrorCode::EmptyMesh, "there is nothing to clip: the solid has no faces", "solid"};
  if (Status indices = detail::checkFaceIndices(mesh, "solid"); !indices.ok()) return indices;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!mesh.vertices[v].allFinite())
      return Error{ErrorCode::NonFiniteVertex, "a vertex coordinate is NaN or infinite", "vertex " + std::to_string(v)};
  if (checkClosed) return checkClosedOriented(mesh);
  return Done{};
}

// Faces of one side with vertex ids in the clipper's numbering: input vertices first, then edge crossings.
struct SideFaces {
  std::vector<Triangle> triangles;
  std::vector<FaceOrigin> origins;
  std::vector<std::int32_t> sourceFace;  // input face kept unchanged, or -1
  void add(std::int32_t a, std::int32_t b, std::int32_t c, FaceOrigin origin, std::int32_t source = -1) {
    triangles.push_back({a, b, c});
    origins.push_back(origin);
    sourceFace.push_back(source);
  }
};

class PlaneSplitter {
 public:
  PlaneSplitter(const TriangleMesh& solid, const Plane& plane, double tolerance)
      : m_solid(solid), m_plane(plane), m_side(solid.vertices.size()) {
    // A vertex is snapped only when its distance is at most its reach (the move along the surface is at least
    // as long as the distance), and a reach is at most kSnapRatio of a face's height, so of the solid's
    // diagonal: only the vertices that close to the plane need the faces around them (snapData). Measuring
    // every face for every clip was most of a clip's own time on a million faces.
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 high = -low;
    for (const Vec3& p : solid.vertices) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    const double largestReach = 2.0 * kSnapRatio * (high - low).norm();  // twice: no rounding can exceed it
    const std::size_t vertexCount = solid.vertices.size();
    std::vector<std::int32_t> near;  // in vertex order
    for (std::size_t v = 0; v < vertexCount; ++v) {
      const double d = std::abs(plane.signedDistance(solid.vertices[v]));
      if (d > tolerance && d <= largestReach) near.push_back(static_cast<std::int32_t>(v));
    }
    const SnapData snap = snapData(solid, near);
    // The sides first and the few vertices moved onto the plane aside, so that the positions (the solid's
    // vertices, then the crossings) can be copied once into a buffer that already has room for the crossings:
    // copying the vertices and growing the copy for the first crossing filled three times the vertices' size
    // in fresh pages on every clip (docs/architecture.md, "Million-triangle models").
    std::vector<std::pair<std::int32_t, Vec3>> moved;  // (vertex, position on the plane), in vertex order
    for (std::size_t v = 0, n = 0; v < vertexCount; ++v) {
      const Vec3& p = solid.vertices[v];
      const double d = plane.signedDistance(p);
      const bool isNear = n < near.size() && near[n] == static_cast<std::int32_t>(v);
      if (std::abs(d) <= tolerance) {
        m_side[v] = 0;
        moved.emplace_back(static_cast<std::int32_t>(v), p - d * plane.normal);
      } else if (const std::optional<Vec3> move =
                     isNear ? volumeKeepingSnap(d, snap.normal[n], snap.reach[n]) : std::nullopt) {
        m_side[v] = 0;
        Vec3 q = p + *move;
        q -= plane.signedDistance(q) * plane.normal;  // rounding
        moved.emplace_back(static_cast<std::int32_t>(v), q);
      } else {
        m_side[v] = d > 0.0 ? 1 : -1;
      }
      if (isNear) ++n;
    }
    // A face with corners on both sides makes at most two crossings (edges in the plane make none).
    std::size_t crossingBound = 0;
    for (const Triangle& t : solid.triangles) {
      const int s0 = m_side[t[0]], s1 = m_side[t[1]], s2 = m_side[t[2]];
      if ((s0 < 0 || s1 < 0 || s2 < 0) && (s0 > 0 || s1 > 0 || s2 > 0)) crossingBound += 2;
    }
    detail::reserveInHugePages(m_positions, vertexCount + crossingBound);
    m_positions.assign(solid.vertices.begin(), solid.vertices.end());
    for (const auto& [v, p] : moved) m_positions[static_cast<std::size_t>(v)] = p;
    m_crossings.reserve(crossingBound);
  }


  // A plane that passes a hair from a vertex cuts slivers: a sliver-thin strip of each face at the vertex,
  // and cap triangles between crossing points a hair apart (the cap of 2.7 % of random clips had one). Such a
  // vertex is moved onto the plane instead, when the move is at most kSnapRatio of its smallest height in
  // the faces around it (so each face's area changes by at most that fraction, and none turns over).
  // The move goes along the surface, perpendicular to the vertex's area-weighted normal: the solid's volume
  // is linear in one vertex's position with that normal as gradient, so it does not change (unless the plane
  // is nearly tangent there; then the vertex moves along the plane's normal).
  struct SnapData {
    std::vector<double> reach;  // mm
    std::vector<Vec3> normal;   // sum of the faces' (b - a) x (c - a) around the vertex
  };
  // For the vertices `near` (ascending), in their order: the faces around each summed in face order.
  static SnapData snapData(const TriangleMesh& solid, const std::vector<std::int32_t>& near) {
    SnapData data{std::vector<double>(near.size(), std::numeric_limits<double>::infinity()),
                  std::vector<Vec3>(near.size(), Vec3::Zero())};
    if (near.empty()) return data;
    std::vector<char> isNear(solid.vertices.size(), 0);
    for (std::int32_t v : near) isNear[static_cast<std::size_t>(v)] = 1;
    for (const Triangle& t : solid.triangles) {
      if (!isNear[t[0]] && !isNear[t[1]] && !isNear[t[2]]) continue;
      const Vec3& a = solid.vertices[t[0]];
      const Vec3& b = solid.vertices[t[1]];
      const Vec3& c = solid.vertices[t[2]];
      const Vec3 areaNormal = (b - a).cross(c - a);
      const double twiceArea = areaNormal.norm();
      const double opposite[3] = {(c - b).norm(), (a - c).norm(), (b - a).norm()};
      for (int k = 0; k < 3; ++k) {
        if (!isNear[t[k]]) continue;
        const auto slot = static_cast<std::size_t>(std::lower_bound(near.begin(), near.end(), t[k]) - near.begin());
        const double height = opposite[k] > 0.0 ? twiceArea / opposite[k] : 0.0;
        data.reach[slot] = std::min(data.reach[slot], kSnapRatio * height);
        data.normal[slot] += areaNormal;
      }
    }
    for (double& r : data.reach)
      if (!std::isfinite(r)) r = 0.0;
    return data;
  }
  // The move that brings a vertex at signed distance d onto the plane along its surface, if short enough.
  std::optional<Vec3> volumeKeepingSnap(double d, const Vec3& vertexNormal, double reach) const {
    const double length = vertexNormal.norm();
    if (!(length > 0.0) || !(reach > 0.0)) return std::nullopt;
    const Vec3 unit = vertexNormal / length;
    const Vec3 along = m_plane.normal - m_plane.normal.dot(unit) * unit;  // the plane's normal in the tangent plane
    const double alongSquared = along.squaredNorm();  // = along . plane normal
    // A plane (nearly) tangent to the surface there: no short move along the surface reaches it.
    if (alongSquared < 1e-6) return std::nullopt;
    const Vec3 move = -d / alongSquared * along;
    if (move.norm() > reach) return std::nullopt;
    return move;
  }

  void splitFaces() {
    const std::size_t faceCount = m_solid.triangles.size();
    // Huge pages (detail/huge_pages.h): only the part a side fills is ever touched, in 2 MiB faults.
    detail::reserveInHugePages(m_below.triangles, faceCount);
    detail::reserveInHugePages(m_below.origins, faceCount);
    detail::reserveInHugePages(m_above.triangles, faceCount);
    detail::reserveInHugePages(m_above.origins, faceCount);
    detail::reserveInHugePages(m_below.sourceFace, faceCount);
    detail::reserveInHugePages(m_above.sourceFace, faceCount);
    for (std::size_t f = 0; f < faceCount; ++f)
      splitFace(m_solid.triangles[f], m_solid.origins[f], static_cast<std::int32_t>(f));
  }

  // The cap's boundary: the edges in the plane of `below` that no other face of `below` shares, reversed so
  // that the cap lies on their left seen from +normal. The other edges in the plane, of either side, go to
  // `meshEdges`.
  void findCapEdges(std::vector<detail::CapEdge>& capEdges, std::vector<detail::CapEdge>& meshEdges) const {
    std::vector<std::uint64_t> cut;
    for (const Triangle& t : m_below.triangles)
      for (int k = 0; k < 3; ++k)
        if (onPlane(t[k]) && onPlane(t[(k + 1) % 3])) cut.push_back(detail::directedEdgeKey(t[k], t[(k + 1) % 3]));
    std::sort(cut.begin(), cut.end());
    for (std::uint64_t key : cut) {
      const auto a = static_cast<std::int32_t>(key >> 32);
      const auto b = static_cast<std::int32_t>(key & 0xffffffffu);
      if (!std::binary_search(cut.begin(), cut.end(), detail::directedEdgeKey(b, a)))
        capEdges.push_back({b, a});
      else if (a < b)
        meshEdges.push_back({a, b});
    }
    for (const Triangle& t : m_above.triangles)
      for (int k = 0; k < 3; ++k)
        if (onPlane(t[k]) && onPlane(t[(k + 1) % 3])) meshEdges.push_back({t[k], t[(k + 1) % 3]});
  }

  const std::vector<Vec3>& positions() const { return m_positions; }
  SideFaces& below() { return m_below; }
  SideFaces& above() { return m_above; }
  // Input vertices that lie in the plane: the only places where a side can pinch.
  bool inPlaneInputVertex(std::int32_t v) const {
    return v < static_cast<std::int32_t>(m_side.size()) && m_side[v] == 0;
  }

 private:
  bool onPlane(std::int32_t v) const { return v >= static_cast<std::int32_t>(m_side.size()) || m_side[v] == 0; }

  SideFaces& sideOf(int sign) { return sign < 0 ? m_below : m_above; }

  // The point where edge (a, b) crosses the plane, made once per edge so both faces of the edge and both
  // sides share it; computed from the lower index so it does not depend on which face asks first.
  std::int32_t crossing(std::int32_t a, std::int32_t b) {
    if (a > b) std::swap(a, b);
    auto [it, inserted] = m_crossings.emplace(detail::directedEdgeKey(a, b), static_cast<std::int32_t>(m_positions.size()));
    if (inserted) {
      const Vec3& pa = m_positions[a];
      const Vec3& pb = m_positions[b];
      const double da = m_plane.signedDistance(pa);
      const double db = m_plane.signedDistance(pb);
      Vec3 p = pa + (pb - pa) * (da / (da - db));
      p -= m_plane.signedDistance(p) * m_plane.normal;
      m_positions.push_back(p);
    }
    return it->second;
  }

  void splitFace(const Triangle& t, FaceOrigin origin, std::int32_t face) {
    const int s[3] = {m_side[t[0]], m_side[t[1]], m_side[t[2]]};
    const bool anyBelow = s[0] < 0 || s[1] < 0 || s[2] < 0;
    const bool anyAbove = s[0] > 0 || s[1] > 0 || s[2] > 0;
    if (!anyBelow && !anyAbove) {
      // In the plane: a face looking up is the top of the part below, one looking down the bottom of the part
      // above; either way the other side is open there and gets the cap.
      const Vec3 n = (m_positions[t[1]] - m_positions[t[0]]).cross(m_positions[t[2]] - m_positions[t[0]]);
      sideOf(n.dot(m_plane.normal) >= 0.0 ? -1 : 1).add(t[0], t[1], t[2], origin);
      return;
    }
    if (!anyBelow || !anyAbove) {
      // Unchanged only when no corner was moved onto the plane.
      const bool unchanged = s[0] != 0 && s[1] != 0 && s[2] != 0;
      sideOf(anyBelow ? -1 : 1).add(t[0], t[1], t[2], origin, unchanged ? face : -1);
      return;
    }
    // Rotate so that corner 0 is the odd one out: the corner in the plane, or the lone corner on its side.
    int r = 0;
    const int zeros = (s[0] == 0) + (s[1] == 0) + (s[2] == 0);
    for (int k = 0; k < 3; ++k) {
      const bool lone = zeros == 1 ? s[k] == 0 : s[k] != s[(k + 1) % 3] && s[k] != s[(k + 2) % 3];
      if (lone) r = k;
    }
    const std::int32_t v0 = t[r], v1 = t[(r + 1) % 3], v2 = t[(r + 2) % 3];
    const int s0 = s[r], s1 = s[(r + 1) % 3], s2 = s[(r + 2) % 3];
    if (zeros == 1) {
      const std::int32_t x = crossing(v1, v2);
      sideOf(s1).add(v0, v1, x, origin);
      sideOf(s2).add(v0, x, v2, origin);
      return;
    }
    const std::int32_t x1 = crossing(v0, v1);
    const std::int32_t x2 = crossing(v0, v2);
    sideOf(s0).add(v0, x1, x2, origin);
    // The quad x1 v1 v2 x2 on the other side, cut along its shorter diagonal.
    SideFaces& other = sideOf(s1);
    if ((m_positions[v1] - m_positions[x2]).squaredNorm() <= (m_positions[x1] - m_positions[v2]).squaredNorm()) {
      other.add(x1, v1, x2, origin);
      other.add(v1, v2, x2, origin);
    } else {
      other.add(x1, v1, v2, origin);
      other.add(x1, v2, x2, origin);
    }
  }

  const TriangleMesh& m_solid;
  const Plane& m_plane;
  std::vector<Vec3> m_positions;
  std::vector<std::int8_t> m_side;
  std::unordered_map<std::uint64_t, std::int32_t> m_crossings;
  SideFaces m_below;
  SideFaces m_above;
};

// Where a side touches itself at a single point of the plane (two lumps meeting at a vertex), the faces
// around that vertex form several fans; each fan after the first gets its own copy of the vertex.
void separatePinchedVertices(TriangleMesh& mesh, const std::vector<std::int32_t>& candidates) {
  if (candidates.empty()) return;
  std::vector<std::int32_t> slot(mesh.vertices.size(), -1);
  for (std::size_t i = 0; i < candidates.size(); ++i) slot[candidates[i]] = static_cast<std::int32_t>(i);
  std::vector<std::vector<std::int32_t>> facesAround(candidates.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (std::int32_t v : mesh.triangles[f])
      if (slot[v] >= 0) facesAround[slot[v]].push_back(static_cast<std::int32_t>(f));

  std::vector<std::pair<std::int32_t, std::int32_t>> neighbours;  // (other vertex, position in fan list)
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const std::int32_t v = candidates[i];
    const auto& faces = facesAround[i];
    if (faces.size() < 2) continue;
    neighbours.clear();
    for (std::size_t j = 0; j < faces.size(); ++j)
      for (std::int32_t w : mesh.triangles[faces[j]])
        if (w != v) neighbours.emplace_back(w, static_cast<std::int32_t>(j));
    std::sort(neighbours.begin(), neighbours.end());
    detail::UnionFind fans(faces.size());
    for (std::size_t k = 1; k < neighbours.size(); ++k)
      if (neighbours[k].first == neighbours[k - 1].first) fans.unite(neighbours[k].second, neighbours[k - 1].second);
    const std::int32_t firstFan = fans.find(0);
    std::vector<std::pair<std::int32_t, std::int32_t>> copyOfFan;  // (fan root, new vertex)
    for (std::size_t j = 0; j < faces.size(); ++j) {
      const std::int32_t fan = fans.find(static_cast<std::int32_t>(j));
      if (fan == firstFan) continue;
      auto it = std::find_if(copyOfFan.begin(), copyOfFan.end(), [fan](const auto& c) { return c.first == fan; });
      if (it == copyOfFan.end()) {
        copyOfFan.emplace_back(fan, static_cast<std::int32_t>(mesh.vertices.size()));
        mesh.vertices.push_back(mesh.vertices[v]);
        it = copyOfFan.end() - 1;
      }
      for (std::int32_t& corner : mesh.triangles[faces[j]])
        if (corner == v) corner = it->second;
    }
  }
}

// One side as a mesh of its own: only the vertices its faces use, numbered in order of first use.
TriangleMesh assembleSide(SideFaces&& faces, const std::vector<Triangle>& cap, bool capFacesNormal,
                          std::int32_t planeId, const PlaneSplitter& splitter,
                          std::vector<std::int32_t>* sourceFace = nullptr) {
  for (const Triangle& t : cap) {
    if (capFacesNormal)
      faces.add(t[0], t[1], t[2], FaceOrigin::cap(planeId));
    else
      faces.add(t[0], t[2], t[1], FaceOrigin::cap(planeId));
  }
  TriangleMesh mesh;
  if (faces.triangles.empty()) return mesh;
  const std::vector<Vec3>& positions = splitter.positions();
  std::vector<std::int32_t> local(positions.size(), -1);
  std::vector<std::int32_t> pinchCandidates;
  // A closed side has about half as many vertices as faces: one allocation instead of a doubling series.
  detail::reserveInHugePages(mesh.vertices, std::min(positions.size(), faces.triangles.size() / 2 + 2));
  for (Triangle& t : faces.triangles) {
    for (std::int32_t& v : t) {
      if (local[v] < 0) {
        local[v] = static_cast<std::int32_t>(mesh.vertices.size());
        mesh.vertices.push_back(positions[v]);
        if (splitter.inPlaneInputVertex(v)) pinchCandidates.push_back(local[v]);
      }
      v = local[v];
    }
  }
  mesh.triangles = std::move(faces.triangles);
  mesh.origins = std::move(faces.origins);
  if (sourceFace) *sourceFace = std::move(faces.sourceFace);
  separatePinchedVertices(mesh, pinchCandidates);
  return mesh;
}

}  // namespace

Result<ClipResult> clipByPlane(const TriangleMesh& solid, const Plane& plane, std::int32_t planeId,
                               const ClipOptions& options) {
  if (Status s = checkPlane(plane, options); !s) return s.error();
  if (Status s = checkSolid(solid, options.checkClosed); !s) return s.error();

  PlaneSplitter splitter(solid, plane, options.planeToleranceMm);
  splitter.splitFaces();
  std::vector<detail::CapEdge> capEdges, meshEdges;
  splitter.findCapEdges(capEdges, meshEdges);
  Result<std::vector<Triangle>> cap = detail::triangulateCap(capEdges, meshEdges, splitter.positions(), plane);
  if (!cap) return cap.error();

  ClipResult result;
  result.below = assembleSide(std::move(splitter.below()), cap.value(), true, planeId, splitter, &result.belowSourceFace);
  result.above = assembleSide(std::move(splitter.above()), cap.value(), false, planeId, splitter);
  return result;
}

}  // namespace multidir::core

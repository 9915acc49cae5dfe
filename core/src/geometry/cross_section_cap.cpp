#include "geometry/cross_section_cap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "multidir/core/geometry/polygon_triangulation.h"

namespace multidir::core::detail {
namespace {

struct Loop {
  std::vector<std::int32_t> vertices;  // local indices
  double area = 0.0;                   // signed, counter-clockwise positive
  Vec2 min;
  Vec2 max;
};

// An orthonormal basis (u, v) of the plane with u x v = normal, so counter-clockwise in (u, v) is
// counter-clockwise seen from +normal.
void planeBasis(const Vec3& normal, Vec3& u, Vec3& v) {
  const Vec3 helper = std::abs(normal.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  u = helper.cross(normal).normalized();
  v = normal.cross(u);
}

// The angle (0, 2 pi] swept clockwise from `back` to `out`. Following the smallest one traces the boundary of
// one face of the planar arrangement, so loops that touch at a vertex are separated the way the region is.
double clockwiseAngle(const Vec2& back, const Vec2& out) {
  const double ccw = std::atan2(back.x() * out.y() - back.y() * out.x(), back.dot(out));
  const double cw = -ccw;
  if (cw <= 0.0) return cw + 2.0 * 3.14159265358979323846;
  return cw;
}

bool pointInLoop(const Vec2& q, const Loop& loop, const std::vector<Vec2>& points) {
  bool inside = false;
  const std::size_t n = loop.vertices.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = points[loop.vertices[i]];
    const Vec2& b = points[loop.vertices[j]];
    if ((a.y() > q.y()) != (b.y() > q.y())) {
      const double x = a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (q.x() < x) inside = !inside;
    }
  }
  return inside;
}

bool boxContains(const Loop& outer, const Loop& inner) {
  return outer.min.x() <= inner.min.x() && outer.min.y() <= inner.min.y() && outer.max.x() >= inner.max.x() &&
         outer.max.y() >= inner.max.y();
}

// A point of `hole` to test against `outer`: one of its vertices that `outer` does not share (loops touch
// only at shared vertices), else the middle of its first edge.
Vec2 testPoint(const Loop& hole, const Loop& outer, const std::vector<Vec2>& points, std::vector<std::int32_t>& stamp,
               std::int32_t stampValue) {
  for (std::int32_t v : outer.vertices) stamp[v] = stampValue;
  for (std::int32_t v : hole.vertices)
    if (stamp[v] != stampValue) return points[v];
  return 0.5 * (points[hole.vertices[0]] + points[hole.vertices[1]]);
}

Result<std::vector<Loop>> chainLoops(const std::vector<CapEdge>& edges, const std::vector<std::int32_t>& localOf,
                                     const std::vector<Vec2>& points) {
  const auto vertexCount = static_cast<std::int32_t>(points.size());
  const auto edgeCount = static_cast<std::int32_t>(edges.size());
  // Outgoing edges of each local vertex, by counting sort.
  std::vector<std::int32_t> first(vertexCount + 1, 0);
  for (const CapEdge& e : edges) ++first[localOf[e[0]] + 1];
  for (std::int32_t i = 0; i < vertexCount; ++i) first[i + 1] += first[i];
  std::vector<std::int32_t> outgoing(edgeCount);
  {
    std::vector<std::int32_t> cursor(first.begin(), first.end() - 1);
    for (std::int32_t e = 0; e < edgeCount; ++e) outgoing[cursor[localOf[edges[e][0]]]++] = e;
  }

  std::vector<char> used(edgeCount, 0);
  std::vector<Loop> loops;
  std::vector<std::int32_t> candidates;
  for (std::int32_t start = 0; start < edgeCount; ++start) {
    if (used[start]) continue;
    Loop loop;
    for (std::int32_t e = start, steps = 0;; ++steps) {
      if (steps > edgeCount)
        return Error{ErrorCode::Internal, "the cross-section's edges do not close into loops", "clipping cap"};
      used[e] = 1;
      const std::int32_t from = localOf[edges[e][0]];
      const std::int32_t to = localOf[edges[e][1]];
      loop.vertices.push_back(from);
      candidates.clear();
      for (std::int32_t k = first[to]; k < first[to + 1]; ++k)
        if (!used[outgoing[k]] || outgoing[k] == start) candidates.push_back(outgoing[k]);
      if (candidates.empty())
        return Error{ErrorCode::Internal,
                     "the cross-section has an open chain of " + std::to_string(loop.vertices.size()) +
                         " edges; the solid was probably not closed",
                     "clipping cap"};
      std::int32_t next = candidates.front();
      if (candidates.size() > 1) {
        const Vec2 back = points[from] - points[to];
        double bestAngle = std::numeric_limits<double>::infinity();
        for (std::int32_t c : candidates) {
          const double angle = clockwiseAngle(back, points[localOf[edges[c][1]]] - points[to]);
          if (angle < bestAngle) {
            bestAngle = angle;
            next = c;
          }
        }
      }
      if (next == start) break;
      e = next;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

// 4 sqrt(3) area / (sum of squared edges): 1 for an equilateral triangle, 0 for a degenerate one.
double triangleQuality(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double twiceArea = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  const double squares = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return squares > 0.0 ? 2.0 * std::sqrt(3.0) * twiceArea / squares : 0.0;
}

std::uint64_t undirected(std::int32_t a, std::int32_t b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

// Ear clipping must sometimes clip a corner between nearly collinear loop points, which leaves a triangle of
// almost no area (2.7 % of random clips had one). Such a sliver shares its long edge with a neighbour; flipping
// that edge (the two triangles' other diagonal) removes it when the quadrilateral they form is convex. A flip
// is made only when it raises the smaller quality of the pair, so the loop ends; each triangle is looked at a
// bounded number of times. Diagonals in `avoid` (edges the side meshes already have) are never created, nor
// edges the cap already has (either would make an edge with four faces).
// Whether the undirected edge a-b is one of `forbidden` (sorted undirected keys).
bool isForbidden(const std::vector<std::uint64_t>& forbidden, std::int32_t a, std::int32_t b) {
  return !forbidden.empty() && std::binary_search(forbidden.begin(), forbidden.end(), undirected(a, b));
}

void flipSlivers(const std::vector<Vec2>& points, std::vector<Triangle>& triangles,
                 const std::vector<std::uint64_t>& forbidden) {
  constexpr double kSliverQuality = 1e-2;
  auto quality = [&](const Triangle& t) { return triangleQuality(points[t[0]], points[t[1]], points[t[2]]); };
  std::vector<std::size_t> work;
  for (std::size_t f = 0; f < triangles.size(); ++f)
    if (quality(triangles[f]) < kSliverQuality) work.push_back(f);
  if (work.empty()) return;  // most caps: no sliver, nothing to index
  // Directed edge -> (triangle, corner the edge starts at).
  std::unordered_map<std::uint64_t, std::pair<std::size_t, int>> directed;
  std::unordered_set<std::uint64_t> edges;
  directed.reserve(3 * triangles.size());
  edges.reserve(3 * triangles.size());
  auto key = [](std::int32_t a, std::int32_t b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  };
  auto index = [&](std::size_t f) {
    for (int k = 0; k < 3; ++k) {
      directed[key(triangles[f][k], triangles[f][(k + 1) % 3])] = {f, k};
      edges.insert(undirected(triangles[f][k], triangles[f][(k + 1) % 3]));
    }
  };
  auto unindex = [&](std::size_t f) {
    for (int k = 0; k < 3; ++k) {
      directed.erase(key(triangles[f][k], triangles[f][(k + 1) % 3]));
      edges.erase(undirected(triangles[f][k], triangles[f][(k + 1) % 3]));
    }
  };
  for (std::size_t f = 0; f < triangles.size(); ++f) index(f);

  std::size_t budget = 8 * triangles.size() + 16;
  while (!work.empty() && budget-- > 0) {
    const std::size_t f = work.back();
    work.pop_back();
    const Triangle t = triangles[f];
    const double q = quality(t);
    if (q >= kSliverQuality) continue;
    // The longest edge p->q of the sliver, r the corner across from it.
    int longest = 0;
    double longestLength = -1.0;
    for (int k = 0; k < 3; ++k) {
      const double length = (points[t[(k + 1) % 3]] - points[t[k]]).squaredNorm();
      if (length > longestLength) longestLength = length, longest = k;
    }
    const std::int32_t p = t[longest], q2 = t[(longest + 1) % 3], r = t[(longest + 2) % 3];
    const auto across = directed.find(key(q2, p));
    if (across == directed.end()) continue;  // on the cap's boundary
    const std::size_t g = across->second.first;
    const Triangle u = triangles[g];
    const int corner = across->second.second;
    if (u[corner] != q2 || u[(corner + 1) % 3] != p) continue;  // a repeated edge (loops touching): leave it
    const std::int32_t s = u[(corner + 2) % 3];
    if (s == r || isForbidden(forbidden, r, s) || edges.count(undirected(r, s))) continue;
    const Triangle first = {p, s, r}, second = {s, q2, r};
    const double before = std::min(q, quality(u));
    const double after = std::min(quality(first), quality(second));
    if (!(after > before) || quality(first) <= 0.0 || quality(second) <= 0.0) continue;
    unindex(f);
    unindex(g);
    triangles[f] = first;
    triangles[g] = second;
    index(f);
    index(g);
    if (quality(first) < kSliverQuality) work.push_back(f);
    if (quality(second) < kSliverQuality) work.push_back(g);
  }
}

// Whether d lies inside the circle through a, b, c (counter-clockwise), by more than rounding: coordinates are
// taken relative to d, and the determinant must exceed a small fraction of its terms' size.
bool insideCircumcircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const Vec2 pa = a - d, pb = b - d, pc = c - d;
  const double la = pa.squaredNorm(), lb = pb.squaredNorm(), lc = pc.squaredNorm();
  const double t1 = la * (pb.x() * pc.y() - pb.y() * pc.x());
  const double t2 = lb * (pc.x() * pa.y() - pc.y() * pa.x());
  const double t3 = lc * (pa.x() * pb.y() - pa.y() * pb.x());
  return t1 + t2 + t3 > 1e-9 * (std::abs(t1) + std::abs(t2) + std::abs(t3));
}

// Lawson's flips to the constrained Delaunay triangulation of the cap (its loops' edges are the constraints).
// Ear clipping of a loop of many close points (a cut through a dense mesh) leaves fans of long thin triangles
// meeting at a few corners; a later plane crossing such a cap cuts those thin triangles at points that crowd
// together near the corners, closer than a binary STL's floats can tell apart, at any offset (a million-face
// knight lost a plane to this). Delaunay triangles are as round as the loop allows, and the points a later cut
// makes on them are spread as the loop's own points are. Diagonals in `avoid` or already in the cap are never
// made; each flip must leave two triangles of positive area; a budget ends the loop whatever rounding does.
void flipToDelaunay(const std::vector<Vec2>& points, std::vector<Triangle>& triangles,
                    const std::vector<std::uint64_t>& forbidden) {
  const std::size_t n = triangles.size();
  if (n < 2) return;
  // Each directed edge 3f + k (from corner k of face f) and the one across it (-1 on the boundary, and where an
  // edge is repeated because loops touch: nothing is flipped there).
  std::vector<std::pair<std::uint64_t, std::int32_t>> sorted(3 * n);
  auto key = [](std::int32_t a, std::int32_t b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  };
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k)
      sorted[3 * f + k] = {key(triangles[f][k], triangles[f][(k + 1) % 3]), static_cast<std::int32_t>(3 * f + k)};
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::int32_t> across(3 * n, -1);
  auto single = [&](std::uint64_t edge) -> std::int32_t {
    auto it = std::lower_bound(sorted.begin(), sorted.end(), std::make_pair(edge, std::int32_t{-1}));
    if (it == sorted.end() || it->first != edge) return -1;
    if (it + 1 != sorted.end() && (it + 1)->first == edge) return -1;
    return it->second;
  };
  // A corner that starts more than one boundary edge is where loops touch: no diagonal is made to it, since
  // the fans around it are not one and the same diagonal might exist in the other.
  std::vector<char> touching(points.size(), 0), startsBoundary(points.size(), 0);
  for (std::size_t e = 0; e < 3 * n; ++e) {
    const Triangle& t = triangles[e / 3];
    const std::int32_t a = t[e % 3], b = t[(e % 3 + 1) % 3];
    if (single(key(a, b)) < 0) continue;
    across[e] = single(key(b, a));
    if (across[e] < 0) {
      if (startsBoundary[a]) touching[a] = 1;
      startsBoundary[a] = 1;
    }
  }
  auto area = [&](std::int32_t a, std::int32_t b, std::int32_t c) {
    const Vec2 &pa = points[a], &pb = points[b], &pc = points[c];
    return (pb - pa).x() * (pc - pa).y() - (pb - pa).y() * (pc - pa).x();
  };
  auto link = [&](std::int32_t e, std::int32_t twin) {
    across[e] = twin;
    if (twin >= 0) across[twin] = e;
  };
  std::vector<std::int32_t> work;
  for (std::size_t e = 0; e < 3 * n; ++e)
    if (across[e] > static_cast<std::int32_t>(e)) work.push_back(static_cast<std::int32_t>(e));
  std::size_t budget = 16 * n + 16;
  while (!work.empty() && budget > 0) {
    const std::int32_t e = work.back();
    work.pop_back();
    const std::int32_t twin = across[e];
    if (twin < 0) continue;
    const std::int32_t f = e / 3, k = e % 3, g = twin / 3, j = twin % 3;
    const Triangle t = triangles[f], u = triangles[g];
    const std::int32_t p = t[k], q = t[(k + 1) % 3], r = t[(k + 2) % 3], s = u[(j + 2) % 3];
    if (r == s || touching[r] || touching[s] || !insideCircumcircle(points[p], points[q], points[r], points[s])) continue;
    if (isForbidden(forbidden, r, s)) continue;
    if (!(area(p, s, r) > 0.0) || !(area(s, q, r) > 0.0)) continue;  // the quadrilateral is not convex
    --budget;
    const std::int32_t rp = across[3 * f + (k + 2) % 3], qr = across[3 * f + (k + 1) % 3];
    const std::int32_t ps = across[3 * g + (j + 1) % 3], sq = across[3 * g + (j + 2) % 3];
    triangles[f] = {p, s, r};  // edges p->s, s->r, r->p
    triangles[g] = {s, q, r};  // edges s->q, q->r, r->s
    link(3 * f, ps);
    link(3 * f + 2, rp);
    link(3 * g, sq);
    link(3 * g + 1, qr);
    link(3 * f + 1, 3 * g + 2);
    for (std::int32_t outer : {3 * f, 3 * f + 2, 3 * g, 3 * g + 1}) work.push_back(outer);
  }
}

}  // namespace

Result<std::vector<Triangle>> triangulateCap(const std::vector<CapEdge>& edges, const std::vector<CapEdge>& meshEdges,
                                             const std::vector<Vec3>& positions, const Plane& plane) {
  std::vector<Triangle> triangles;
  if (edges.empty()) return triangles;

  // Local numbering of the cap's vertices.
  std::vector<std::int32_t> globalOf;
  globalOf.reserve(edges.size());
  for (const CapEdge& e : edges) globalOf.push_back(e[0]);
  std::sort(globalOf.begin(), globalOf.end());
  globalOf.erase(std::unique(globalOf.begin(), globalOf.end()), globalOf.end());
  std::vector<std::int32_t> localOf(positions.size(), -1);
  for (std::size_t i = 0; i < globalOf.size(); ++i) localOf[globalOf[i]] = static_cast<std::int32_t>(i);
  for (const CapEdge& e : edges)
    if (localOf[e[1]] < 0)
      return Error{ErrorCode::Internal, "a cross-section edge ends at a vertex no edge leaves", "clipping cap"};

  Vec3 u, v;
  planeBasis(plane.normal, u, v);
  const Vec3 origin = positions[globalOf.front()];
  std::vector<Vec2> points(globalOf.size());
  for (std::size_t i = 0; i < globalOf.size(); ++i) {
    const Vec3 d = positions[globalOf[i]] - origin;
    points[i] = Vec2(d.dot(u), d.dot(v));
  }

  Result<std::vector<Loop>> chained = chainLoops(edges, localOf, points);
  if (!chained) return chained.error();
  std::vector<Loop>& loops = chained.value();
  for (Loop& loop : loops) {
    loop.min = loop.max = points[loop.vertices.front()];
    const std::size_t n = loop.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& a = points[loop.vertices[i]];
      const Vec2& b = points[loop.vertices[(i + 1) % n]];
      loop.area += 0.5 * (a.x() * b.y() - a.y() * b.x());
      loop.min = loop.min.cwiseMin(a);
      loop.max = loop.max.cwiseMax(a);
    }
  }

  // Holes go to the smallest outer loop around them: with islands inside holes, the outer loops around a hole
  // are nested and the smallest is the one it belongs to.
  std::vector<std::size_t> outers;
  for (std::size_t i = 0; i < loops.size(); ++i)
    if (loops[i].area >= 0.0) outers.push_back(i);
  std::vector<PolygonWithHoles> regions(loops.size());
  std::vector<char> isRegion(loops.size(), 0);
  for (std::size_t i : outers) {
    regions[i].outer = loops[i].vertices;
    isRegion[i] = 1;
  }
  std::vector<std::int32_t> stamp(points.size(), -1);
  std::int32_t stampValue = 0;
  for (std::size_t h = 0; h < loops.size(); ++h) {
    if (loops[h].area >= 0.0) continue;
    std::size_t parent = loops.size();
    for (std::size_t o : outers) {
      if (!boxContains(loops[o], loops[h])) continue;
      if (parent != loops.size() && loops[o].area >= loops[parent].area) continue;
      if (pointInLoop(testPoint(loops[h], loops[o], points, stamp, stampValue++), loops[o], points)) parent = o;
    }
    if (parent == loops.size()) {
      // A hole outside every outer loop can only come from rounding on a sliver; closing it on its own keeps
      // the mesh closed.
      regions[h].outer = loops[h].vertices;
      isRegion[h] = 1;
    } else {
      regions[parent].holes.push_back(loops[h].vertices);
    }
  }

  std::vector<std::array<std::int32_t, 2>> avoid;
  for (const CapEdge& e : meshEdges)
    if (localOf[e[0]] >= 0 && localOf[e[1]] >= 0) avoid.push_back({localOf[e[0]], localOf[e[1]]});
  // The same pairs as sorted undirected keys, made once for every region's flips.
  std::vector<std::uint64_t> forbidden;
  forbidden.reserve(avoid.size());
  for (const auto& pair : avoid) forbidden.push_back(undirected(pair[0], pair[1]));
  std::sort(forbidden.begin(), forbidden.end());

  for (std::size_t r = 0; r < regions.size(); ++r) {
    if (!isRegion[r]) continue;
    Result<std::vector<Triangle>> part = triangulatePolygon(points, regions[r], avoid);
    if (!part)
      return Error{ErrorCode::Internal, "cap triangulation failed: " + part.error().describe(), "clipping cap"};
    flipSlivers(points, part.value(), forbidden);
    flipToDelaunay(points, part.value(), forbidden);
    for (const Triangle& t : part.value()) triangles.push_back({globalOf[t[0]], globalOf[t[1]], globalOf[t[2]]});
  }
  return triangles;
}

}  // namespace multidir::core::detail

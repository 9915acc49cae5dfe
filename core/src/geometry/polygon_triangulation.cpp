#include "multidir/core/geometry/polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_set>

namespace multidir::core {
namespace {

// Turns whose determinant is within this fraction of the magnitude of its two products count as straight:
// cross-section points come from edge/plane intersections and carry rounding far above double's epsilon.
constexpr double kCollinearFactor = 1e-12;

struct Node {
  std::int32_t vertex;  // index into the caller's points
  double x;
  double y;
  std::int32_t prev;
  std::int32_t next;
};

// How hard to look for an ear. Each level accepts what the previous refused; the clipper only moves to the
// next level after a full turn around the polygon found nothing, so the output degrades only where it must.
enum class Pass {
  Strict,   // convex beyond rounding, no other vertex inside or on the triangle
  Relaxed,  // vertices on the triangle's boundary allowed (the remaining polygon then touches itself)
  Exact,    // plain double signs: nearly straight corners become thin, non-zero triangles
};
// When even Exact finds nothing, the most convex corner is clipped anyway so that the loops stay closed.

int signWithin(double left, double right) {
  const double det = left - right;
  const double bound = kCollinearFactor * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return 0;
}

// +1 when o -> a -> b turns counter-clockwise, -1 clockwise, 0 straight within rounding.
int orient(const Node& o, const Node& a, const Node& b) {
  return signWithin((a.x - o.x) * (b.y - o.y), (a.y - o.y) * (b.x - o.x));
}

double rawTurn(const Node& o, const Node& a, const Node& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool samePoint(const Node& a, const Node& b) { return a.x == b.x && a.y == b.y; }

class EarClipper {
 public:
  EarClipper(const std::vector<Vec2>& points, const Vec2& origin, std::vector<Triangle>& out)
      : m_points(points), m_origin(origin), m_out(out) {}

  void avoidDiagonals(const std::vector<std::array<std::int32_t, 2>>& pairs) {
    for (const auto& p : pairs) m_avoid.push_back(pairKey(p[0], p[1]));
    std::sort(m_avoid.begin(), m_avoid.end());
  }

  std::int32_t addLoop(const std::vector<std::int32_t>& loop) {
    const auto first = static_cast<std::int32_t>(m_nodes.size());
    const auto count = static_cast<std::int32_t>(loop.size());
    for (std::int32_t i = 0; i < count; ++i) {
      const Vec2 p = m_points[loop[i]] - m_origin;
      m_nodes.push_back({loop[i], p.x(), p.y(), first + (i + count - 1) % count, first + (i + 1) % count});
    }
    return first;
  }

  // Joins every hole to the polygon that starts at `outer`, leftmost holes first, so that a bridge cast to the
  // left never meets a hole that is not yet joined.
  void joinHoles(std::int32_t outer, const std::vector<std::int32_t>& holeStarts) {
    std::vector<std::int32_t> leftmost;
    leftmost.reserve(holeStarts.size());
    for (std::int32_t start : holeStarts) leftmost.push_back(leftmostNode(start));
    std::sort(leftmost.begin(), leftmost.end(), [this](std::int32_t a, std::int32_t b) {
      return m_nodes[a].x < m_nodes[b].x || (m_nodes[a].x == m_nodes[b].x && m_nodes[a].y < m_nodes[b].y);
    });

    std::unordered_set<std::int32_t> joinedVertices;
    forEachNode(outer, [&](std::int32_t n) { joinedVertices.insert(m_nodes[n].vertex); });
    for (std::int32_t hole : leftmost) {
      if (!spliceAtSharedVertex(outer, hole, joinedVertices)) {
        std::int32_t bridge = findBridge(hole, outer);
        if (bridge < 0) bridge = nearestNode(outer, hole);
        split(bridge, hole);
      }
      forEachNode(hole, [&](std::int32_t n) { joinedVertices.insert(m_nodes[n].vertex); });
    }
  }

  void clip(std::int32_t ear) {
    Pass pass = Pass::Strict;
    std::int32_t stop = ear;
    while (m_nodes[ear].prev != m_nodes[ear].next) {
      const std::int32_t next = m_nodes[ear].next;
      if (isEar(ear, pass)) {
        emit(ear);
        ear = stop = next;
        continue;
      }
      ear = next;
      if (ear != stop) continue;
      // A full turn found nothing: accept more, but never go back, so that degenerate input costs O(n^2).
      if (pass == Pass::Strict) {
        pass = Pass::Relaxed;
      } else if (pass == Pass::Relaxed) {
        pass = Pass::Exact;
      } else {
        const std::int32_t forced = forcedEar(ear);
        ear = stop = m_nodes[forced].next;
        emit(forced);
      }
    }
  }

 private:
  template <typename F>
  void forEachNode(std::int32_t start, F&& f) const {
    std::int32_t n = start;
    do {
      f(n);
      n = m_nodes[n].next;
    } while (n != start);
  }

  std::int32_t leftmostNode(std::int32_t start) const {
    std::int32_t best = start;
    forEachNode(start, [&](std::int32_t n) {
      const Node& p = m_nodes[n];
      const Node& b = m_nodes[best];
      if (p.x < b.x || (p.x == b.x && p.y < b.y)) best = n;
    });
    return best;
  }

  // Whether the direction from node a towards point b lies inside the polygon's angle at a (boundary included).
  bool locallyInside(std::int32_t a, const Node& b) const {
    const Node& p = m_nodes[m_nodes[a].prev];
    const Node& o = m_nodes[a];
    const Node& n = m_nodes[m_nodes[a].next];
    const bool leftOfOutgoing = orient(o, n, b) >= 0;
    const bool rightOfIncomingReversed = orient(o, p, b) <= 0;
    if (orient(p, o, n) >= 0) return leftOfOutgoing && rightOfIncomingReversed;
    return leftOfOutgoing || rightOfIncomingReversed;
  }

  // A hole that shares a vertex index with the polygon touches it there: join the two at that vertex, which
  // needs no bridge and keeps every triangle free of repeated indices.
  bool spliceAtSharedVertex(std::int32_t outer, std::int32_t hole,
                            const std::unordered_set<std::int32_t>& joinedVertices) {
    std::int32_t shared = -1;
    forEachNode(hole, [&](std::int32_t n) {
      if (shared < 0 && joinedVertices.count(m_nodes[n].vertex) != 0) shared = n;
    });
    if (shared < 0) return false;
    const Node& holeNext = m_nodes[m_nodes[shared].next];
    std::int32_t target = -1;
    std::int32_t fallback = -1;
    forEachNode(outer, [&](std::int32_t n) {
      if (m_nodes[n].vertex != m_nodes[shared].vertex) return;
      if (fallback < 0) fallback = n;
      if (target < 0 && locallyInside(n, holeNext)) target = n;
    });
    if (target < 0) target = fallback;
    if (target < 0) return false;
    const std::int32_t targetNext = m_nodes[target].next;
    const std::int32_t sharedNext = m_nodes[shared].next;
    m_nodes[target].next = sharedNext;
    m_nodes[sharedNext].prev = target;
    m_nodes[shared].next = targetNext;
    m_nodes[targetNext].prev = shared;
    return true;
  }

  // Eberly's bridge: cast a ray from the hole's leftmost point to the left, take the nearest edge it meets, and
  // among the vertices that could hide that edge's endpoint pick the one seen at the smallest angle.
  std::int32_t findBridge(std::int32_t hole, std::int32_t outer) const {
    const Node& h = m_nodes[hole];
    double hitX = -std::numeric_limits<double>::infinity();
    std::int32_t candidate = -1;
    forEachNode(outer, [&](std::int32_t n) {
      const Node& p = m_nodes[n];
      const Node& q = m_nodes[p.next];
      // Edges that run downwards have the polygon's inside on their right, facing the hole.
      if (!(h.y <= p.y && h.y >= q.y && q.y != p.y)) return;
      const double x = p.x + (h.y - p.y) * (q.x - p.x) / (q.y - p.y);
      if (x <= h.x && x > hitX) {
        hitX = x;
        candidate = p.x < q.x ? n : p.next;
      }
    });
    if (candidate < 0) return -1;

    const Node m = m_nodes[candidate];
    const Node hit{-1, hitX, h.y, -1, -1};
    const bool below = h.y < m.y;
    const Node& t0 = below ? h : hit;
    const Node& t2 = below ? hit : h;
    std::int32_t best = candidate;
    double bestTan = std::numeric_limits<double>::infinity();
    forEachNode(candidate, [&](std::int32_t n) {
      const Node& p = m_nodes[n];
      if (!(h.x >= p.x && p.x >= m.x && h.x != p.x)) return;
      if (orient(t0, m, p) < 0 || orient(m, t2, p) < 0 || orient(t2, t0, p) < 0) return;
      const double tan = std::abs(h.y - p.y) / (h.x - p.x);
      if (!locallyInside(n, h)) return;
      if (tan < bestTan || (tan == bestTan && p.x > m_nodes[best].x)) {
        best = n;
        bestTan = tan;
      }
    });
    return best;
  }

  std::int32_t nearestNode(std::int32_t outer, std::int32_t hole) const {
    const Node& h = m_nodes[hole];
    std::int32_t best = outer;
    double bestDistance = std::numeric_limits<double>::infinity();
    forEachNode(outer, [&](std::int32_t n) {
      const double d = std::hypot(m_nodes[n].x - h.x, m_nodes[n].y - h.y);
      if (d < bestDistance) {
        bestDistance = d;
        best = n;
      }
    });
    return best;
  }

  // Links a -> b and back through copies of both: a, b, (around the hole), b', a', (on around the polygon).
  void split(std::int32_t a, std::int32_t b) {
    if (m_nodes[a].vertex == m_nodes[b].vertex) {
      const std::int32_t aNext = m_nodes[a].next;
      const std::int32_t bNext = m_nodes[b].next;
      m_nodes[a].next = bNext;
      m_nodes[bNext].prev = a;
      m_nodes[b].next = aNext;
      m_nodes[aNext].prev = b;
      return;
    }
    const auto a2 = static_cast<std::int32_t>(m_nodes.size());
    const std::int32_t b2 = a2 + 1;
    m_nodes.push_back(m_nodes[a]);
    m_nodes.push_back(m_nodes[b]);
    const std::int32_t aNext = m_nodes[a].next;
    const std::int32_t bPrev = m_nodes[b].prev;
    m_nodes[a].next = b;
    m_nodes[b].prev = a;
    m_nodes[a2].next = aNext;
    m_nodes[aNext].prev = a2;
    m_nodes[b2].next = a2;
    m_nodes[a2].prev = b2;
    m_nodes[bPrev].next = b2;
    m_nodes[b2].prev = bPrev;
  }

  bool blocks(const Node& a, const Node& b, const Node& c, const Node& p, Pass pass) const {
    if (pass == Pass::Exact) return rawTurn(a, b, p) > 0 && rawTurn(b, c, p) > 0 && rawTurn(c, a, p) > 0;
    const int s0 = orient(a, b, p);
    const int s1 = orient(b, c, p);
    const int s2 = orient(c, a, p);
    if (pass == Pass::Strict) return s0 >= 0 && s1 >= 0 && s2 >= 0;
    return s0 > 0 && s1 > 0 && s2 > 0;
  }

  bool isEar(std::int32_t ear, Pass pass) const {
    const Node& a = m_nodes[m_nodes[ear].prev];
    const Node& b = m_nodes[ear];
    const Node& c = m_nodes[b.next];
    if (a.vertex == c.vertex) return false;
    if (!m_avoid.empty() && std::binary_search(m_avoid.begin(), m_avoid.end(), pairKey(a.vertex, c.vertex)))
      return false;
    const bool convex = pass == Pass::Exact ? rawTurn(a, b, c) > 0 : orient(a, b, c) > 0;
    if (!convex) return false;
    const double minX = std::min({a.x, b.x, c.x}), maxX = std::max({a.x, b.x, c.x});
    const double minY = std::min({a.y, b.y, c.y}), maxY = std::max({a.y, b.y, c.y});
    for (std::int32_t n = c.next; n != b.prev; n = m_nodes[n].next) {
      const Node& p = m_nodes[n];
      if (p.x < minX || p.x > maxX || p.y < minY || p.y > maxY) continue;
      if (samePoint(p, a) || samePoint(p, b) || samePoint(p, c)) continue;
      if (blocks(a, b, c, p, pass)) return false;
    }
    return true;
  }

  // The corner whose triangle turns most to the left, preferring corners whose neighbours differ.
  std::int32_t forcedEar(std::int32_t start) const {
    std::int32_t best = -1;
    double bestTurn = -std::numeric_limits<double>::infinity();
    forEachNode(start, [&](std::int32_t n) {
      const Node& a = m_nodes[m_nodes[n].prev];
      const Node& c = m_nodes[m_nodes[n].next];
      if (a.vertex == c.vertex) return;
      const double turn = rawTurn(a, m_nodes[n], c);
      if (turn > bestTurn) {
        bestTurn = turn;
        best = n;
      }
    });
    return best < 0 ? start : best;
  }

  void emit(std::int32_t ear) {
    const std::int32_t prev = m_nodes[ear].prev;
    const std::int32_t next = m_nodes[ear].next;
    m_out.push_back({m_nodes[prev].vertex, m_nodes[ear].vertex, m_nodes[next].vertex});
    m_nodes[prev].next = next;
    m_nodes[next].prev = prev;
  }

  static std::uint64_t pairKey(std::int32_t a, std::int32_t b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }

  const std::vector<Vec2>& m_points;
  Vec2 m_origin;
  std::vector<std::uint64_t> m_avoid;
  std::vector<Triangle>& m_out;
  std::vector<Node> m_nodes;
};

Status checkLoop(const std::vector<Vec2>& points, const std::vector<std::int32_t>& loop, const std::string& name) {
  if (loop.size() < 3)
    return Error{ErrorCode::InvalidParameter,
                 "a loop needs at least 3 vertices, this one has " + std::to_string(loop.size()), name};
  const auto count = static_cast<std::int64_t>(points.size());
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const std::int32_t v = loop[i];
    if (v < 0 || v >= count)
      return Error{ErrorCode::InvalidParameter,
                   "vertex index " + std::to_string(v) + " at position " + std::to_string(i) + " is outside the " +
                       std::to_string(count) + " points given",
                   name};
    if (!points[v].allFinite())
      return Error{ErrorCode::InvalidParameter, "point " + std::to_string(v) + " is not finite", name};
    if (loop[(i + 1) % loop.size()] == v)
      return Error{ErrorCode::InvalidParameter,
                   "vertex " + std::to_string(v) + " repeats on consecutive corners at position " + std::to_string(i),
                   name};
  }
  return Done{};
}

}  // namespace

Result<std::vector<Triangle>> triangulatePolygon(const std::vector<Vec2>& points, const PolygonWithHoles& polygon,
                                                 const std::vector<std::array<std::int32_t, 2>>& avoid) {
  if (Status s = checkLoop(points, polygon.outer, "outer loop"); !s) return s.error();
  std::size_t corners = polygon.outer.size();
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    if (Status s = checkLoop(points, polygon.holes[h], "hole " + std::to_string(h)); !s) return s.error();
    corners += polygon.holes[h].size() + 2;
  }

  std::vector<Triangle> triangles;
  triangles.reserve(corners);
  // Coordinates relative to a point of the loop keep the turn tests' rounding relative to the polygon's size.
  EarClipper clipper(points, points[polygon.outer.front()], triangles);
  clipper.avoidDiagonals(avoid);
  const std::int32_t outer = clipper.addLoop(polygon.outer);
  std::vector<std::int32_t> holes;
  holes.reserve(polygon.holes.size());
  for (const auto& hole : polygon.holes) holes.push_back(clipper.addLoop(hole));
  clipper.joinHoles(outer, holes);
  clipper.clip(outer);
  return triangles;
}

}  // namespace multidir::core

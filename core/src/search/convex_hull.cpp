#include "multidir/core/search/convex_hull.h"
#include "detail/edge_key.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "multidir/core/common/units.h"

namespace multidir::core {
namespace {

struct HullFace {
  std::int32_t v[3];
  Vec3 normal;   // unit, outward
  double offset; // normal . x on the face
  bool alive = true;
  std::vector<std::int32_t> outside;  // points strictly above the face, not yet on the hull
};

class Quickhull {
 public:
  Quickhull(const std::vector<Vec3>& points, double eps) : m_p(points), m_eps(eps) {}

  Status run() {
    std::int32_t s[4];
    if (Status st = simplex(s); !st) return st;
    const Vec3 inside = (m_p[s[0]] + m_p[s[1]] + m_p[s[2]] + m_p[s[3]]) / 4.0;
    const int faces[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    for (const auto& f : faces) {
      std::int32_t a = s[f[0]], b = s[f[1]], c = s[f[2]];
      const Vec3 n = (m_p[b] - m_p[a]).cross(m_p[c] - m_p[a]);
      if (n.dot(inside - m_p[a]) > 0) std::swap(b, c);
      addFace(a, b, c);
    }
    std::vector<std::int32_t> all;
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(m_p.size()); ++i)
      if (i != s[0] && i != s[1] && i != s[2] && i != s[3]) all.push_back(i);
    assign(all, 0);
    // Expand the first face that still has outside points with its farthest point, until none is left.
    for (std::size_t f = 0; f < m_faces.size(); ++f) {
      while (m_faces[f].alive && !m_faces[f].outside.empty()) expand(static_cast<std::int32_t>(f));
    }
    return Done{};
  }

  ConvexHull result() const {
    ConvexHull hull;
    std::unordered_map<std::int32_t, std::int32_t> index;
    for (const HullFace& f : m_faces) {
      if (!f.alive) continue;
      Triangle t;
      for (int k = 0; k < 3; ++k) {
        auto [it, inserted] = index.emplace(f.v[k], static_cast<std::int32_t>(hull.vertices.size()));
        if (inserted) hull.vertices.push_back(m_p[f.v[k]]);
        t[k] = it->second;
      }
      hull.triangles.push_back(t);
    }
    return hull;
  }

 private:
  double distance(const HullFace& f, std::int32_t p) const { return f.normal.dot(m_p[p]) - f.offset; }

  Status simplex(std::int32_t s[4]) {
    const std::int32_t n = static_cast<std::int32_t>(m_p.size());
    std::int32_t lo = 0, hi = 0;
    for (std::int32_t i = 1; i < n; ++i) {
      if (m_p[i].x() < m_p[lo].x()) lo = i;
      if (m_p[i].x() > m_p[hi].x()) hi = i;
    }
    if (lo == hi) {  // all x equal: take the farthest pair from point 0
      for (std::int32_t i = 1; i < n; ++i)
        if ((m_p[i] - m_p[0]).norm() > (m_p[hi] - m_p[0]).norm()) hi = i;
    }
    if ((m_p[hi] - m_p[lo]).norm() <= m_eps)
      return Error{ErrorCode::InvalidParameter, "all points coincide: there is no solid to rest", "convex hull"};
    const Vec3 axis = (m_p[hi] - m_p[lo]).normalized();
    std::int32_t third = -1;
    double best = m_eps;
    for (std::int32_t i = 0; i < n; ++i) {
      const Vec3 d = m_p[i] - m_p[lo];
      const double dist = (d - axis * axis.dot(d)).norm();
      if (dist > best) best = dist, third = i;
    }
    if (third < 0) return Error{ErrorCode::InvalidParameter, "the points lie on one line: they enclose no solid", "convex hull"};
    const Vec3 normal = (m_p[hi] - m_p[lo]).cross(m_p[third] - m_p[lo]).normalized();
    std::int32_t fourth = -1;
    best = m_eps;
    for (std::int32_t i = 0; i < n; ++i) {
      const double dist = std::abs(normal.dot(m_p[i] - m_p[lo]));
      if (dist > best) best = dist, fourth = i;
    }
    if (fourth < 0) return Error{ErrorCode::InvalidParameter, "the points lie in one plane: they enclose no solid", "convex hull"};
    s[0] = lo, s[1] = hi, s[2] = third, s[3] = fourth;
    return Done{};
  }

  std::int32_t addFace(std::int32_t a, std::int32_t b, std::int32_t c) {
    HullFace f;
    f.v[0] = a, f.v[1] = b, f.v[2] = c;
    f.normal = (m_p[b] - m_p[a]).cross(m_p[c] - m_p[a]).normalized();
    f.offset = f.normal.dot(m_p[a]);
    const auto id = static_cast<std::int32_t>(m_faces.size());
    m_faces.push_back(std::move(f));
    m_edges[detail::directedEdgeKey(a, b)] = id;
    m_edges[detail::directedEdgeKey(b, c)] = id;
    m_edges[detail::directedEdgeKey(c, a)] = id;
    return id;
  }

  // Gives each point to the first face (from `firstFace` on) it lies above; points above none are inside.
  void assign(const std::vector<std::int32_t>& points, std::size_t firstFace) {
    for (std::int32_t p : points) {
      for (std::size_t f = firstFace; f < m_faces.size(); ++f) {
        if (m_faces[f].alive && distance(m_faces[f], p) > m_eps) {
          m_faces[f].outside.push_back(p);
          break;
        }
      }
    }
  }

  void expand(std::int32_t start) {
    const HullFace& seed = m_faces[start];
    std::int32_t apex = seed.outside.front();
    for (std::int32_t p : seed.outside)
      if (distance(seed, p) > distance(seed, apex)) apex = p;
    // The faces the apex sees, connected to the seed face.
    std::vector<std::int32_t> visible = {start};
    std::vector<char> isVisible(m_faces.size(), 0);
    isVisible[start] = 1;
    for (std::size_t i = 0; i < visible.size(); ++i) {
      const HullFace& f = m_faces[visible[i]];
      for (int k = 0; k < 3; ++k) {
        const auto it = m_edges.find(detail::directedEdgeKey(f.v[(k + 1) % 3], f.v[k]));
        if (it == m_edges.end()) continue;
        const std::int32_t g = it->second;
        if (!isVisible[g] && m_faces[g].alive && distance(m_faces[g], apex) > m_eps) {
          isVisible[g] = 1;
          visible.push_back(g);
        }
      }
    }
    // Horizon: edges of visible faces whose neighbour is not visible.
    std::vector<std::pair<std::int32_t, std::int32_t>> horizon;
    std::vector<std::int32_t> orphans;
    for (std::int32_t id : visible) {
      HullFace& f = m_faces[id];
      for (int k = 0; k < 3; ++k) {
        const std::int32_t a = f.v[k], b = f.v[(k + 1) % 3];
        const auto it = m_edges.find(detail::directedEdgeKey(b, a));
        if (it == m_edges.end() || !isVisible[it->second]) horizon.emplace_back(a, b);
      }
      for (std::int32_t p : f.outside)
        if (p != apex) orphans.push_back(p);
      f.outside.clear();
      f.alive = false;
    }
    for (std::int32_t id : visible) {
      const HullFace& f = m_faces[id];
      for (int k = 0; k < 3; ++k) {
        const auto it = m_edges.find(detail::directedEdgeKey(f.v[k], f.v[(k + 1) % 3]));
        if (it != m_edges.end() && it->second == id) m_edges.erase(it);
      }
    }
    const std::size_t firstNew = m_faces.size();
    for (const auto& [a, b] : horizon) addFace(a, b, apex);
    assign(orphans, firstNew);
  }

  const std::vector<Vec3>& m_p;
  double m_eps;
  std::vector<HullFace> m_faces;
  std::unordered_map<std::uint64_t, std::int32_t> m_edges;  // directed edge -> the face it belongs to
};

}  // namespace

Result<ConvexHull> convexHull(const std::vector<Vec3>& points) {
  if (points.size() < 4)
    return Error{ErrorCode::EmptyMesh, "a solid needs at least 4 points to have a hull", "convex hull"};
  double scale = 1.0;
  for (const Vec3& p : points) {
    if (!p.allFinite()) return Error{ErrorCode::NonFiniteVertex, "a point is NaN or infinite", "convex hull"};
    scale = std::max(scale, p.cwiseAbs().maxCoeff());
  }
  Quickhull qh(points, 1e-9 * scale * 1e2);
  if (Status s = qh.run(); !s) return s.error();
  return qh.result();
}

std::vector<Eigen::Vector2d> convexHull2d(std::vector<Eigen::Vector2d> pts) {
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y(); });
  if (pts.size() < 3) return pts;
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2d> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i - 1]) <= 0) --k;
    h[k++] = pts[i - 1];
  }
  h.resize(k - 1);
  return h;
}

}  // namespace multidir::core

#include "multidir/core/samples/implicit_surface.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>

namespace multidir::core::samples {
namespace {

// A cube corner as a bit mask: bit 0 = +x, bit 1 = +y, bit 2 = +z.
Vec3 cornerOffset(int mask) { return Vec3(mask & 1, (mask >> 1) & 1, (mask >> 2) & 1); }

// The six tetrahedra of the Kuhn (Freudenthal) split of a cube: one per order of the three axes, each a
// monotone path from corner 0 to corner 7. Every cube face is cut along the diagonal from its lowest to
// its highest corner, so neighbouring cubes match. Each tetrahedron is listed positively oriented.
using Tetrahedron = std::array<int, 4>;
std::array<Tetrahedron, 6> kuhnTetrahedra() {
  const std::array<std::array<int, 3>, 6> axisOrders = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  std::array<Tetrahedron, 6> out{};
  for (std::size_t n = 0; n < axisOrders.size(); ++n) {
    const auto& order = axisOrders[n];
    const int v1 = 1 << order[0];
    const int v2 = v1 | (1 << order[1]);
    Tetrahedron t = {0, v1, v2, 7};
    const Vec3 o = cornerOffset(t[0]);
    if ((cornerOffset(t[1]) - o).cross(cornerOffset(t[2]) - o).dot(cornerOffset(t[3]) - o) < 0.0) std::swap(t[2], t[3]);
    out[n] = t;
  }
  return out;
}

// Makes an ordering of the local vertices {0,1,2,3} an even permutation by swapping its last two entries
// if needed, so a positively oriented tetrahedron stays positively oriented and the first two stay put.
std::array<int, 4> evenPermutation(std::array<int, 4> p) {
  int inversions = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) inversions += p[a] > p[b] ? 1 : 0;
  if (inversions % 2 != 0) std::swap(p[2], p[3]);
  return p;
}

class Polygonizer {
 public:
  Polygonizer(const BoundingBox& bounds, double cell, std::array<long long, 3> counts, std::vector<double> values)
      : m_origin(bounds.min), m_cell(cell), m_n(counts), m_values(std::move(values)), m_tets(kuhnTetrahedra()) {}

  TriangleMesh run() {
    m_edgeVertex.reserve(static_cast<std::size_t>(m_values.size() / 16 + 1024));
    for (long long k = 0; k + 1 < m_n[2]; ++k)
      for (long long j = 0; j + 1 < m_n[1]; ++j)
        for (long long i = 0; i + 1 < m_n[0]; ++i) marchCube(i, j, k);
    m_mesh.resetOrigins();
    return std::move(m_mesh);
  }

 private:
  long long pointIndex(long long i, long long j, long long k) const { return i + m_n[0] * (j + m_n[1] * k); }
  Vec3 pointPosition(long long index) const {
    const long long i = index % m_n[0];
    const long long j = (index / m_n[0]) % m_n[1];
    const long long k = index / (m_n[0] * m_n[1]);
    return m_origin + m_cell * Vec3(double(i), double(j), double(k));
  }

  void marchCube(long long i, long long j, long long k) {
    std::array<long long, 8> corner{};
    int insideCount = 0;
    for (int m = 0; m < 8; ++m) {
      corner[m] = pointIndex(i + (m & 1), j + ((m >> 1) & 1), k + ((m >> 2) & 1));
      insideCount += m_values[corner[m]] < 0.0 ? 1 : 0;
    }
    if (insideCount == 0 || insideCount == 8) return;
    for (const Tetrahedron& t : m_tets) marchTetrahedron(corner, t);
  }

  // The surface vertex on the grid edge between cube corners a and b (a is a subset of b as masks, so
  // the edge is named by its lower grid point and its direction, whichever tetrahedron asks for it).
  std::int32_t edgeVertex(const std::array<long long, 8>& corner, int a, int b) {
    if ((a & b) != a) std::swap(a, b);
    const long long lower = corner[a];
    const long long upper = corner[b];
    const std::uint64_t id = static_cast<std::uint64_t>(lower) * 8u + static_cast<std::uint64_t>(a ^ b);
    const auto found = m_edgeVertex.find(id);
    if (found != m_edgeVertex.end()) return found->second;
    const double fa = m_values[lower];
    const double fb = m_values[upper];
    const double t = fa / (fa - fb);
    const Vec3 pa = pointPosition(lower);
    const Vec3 pb = pointPosition(upper);
    const auto index = static_cast<std::int32_t>(m_mesh.vertices.size());
    m_mesh.vertices.push_back(pa + t * (pb - pa));
    m_edgeVertex.emplace(id, index);
    return index;
  }

  void marchTetrahedron(const std::array<long long, 8>& corner, const Tetrahedron& tet) {
    std::array<int, 4> inside{};
    std::array<int, 4> outside{};
    int nIn = 0;
    int nOut = 0;
    for (int v = 0; v < 4; ++v) {
      if (m_values[corner[tet[v]]] < 0.0)
        inside[nIn++] = v;
      else
        outside[nOut++] = v;
    }
    if (nIn == 0 || nIn == 4) return;
    auto e = [&](int a, int b) { return edgeVertex(corner, tet[a], tet[b]); };
    if (nIn == 1 || nIn == 3) {
      // The lone vertex cut off by one triangle; the triangle faces away from it when it is inside.
      const int lone = nIn == 1 ? inside[0] : outside[0];
      std::array<int, 4> order = {lone, 0, 0, 0};
      for (int v = 0, n = 1; v < 4; ++v)
        if (v != lone) order[n++] = v;
      const std::array<int, 4> p = evenPermutation(order);
      if (nIn == 1)
        m_mesh.triangles.push_back({e(p[0], p[1]), e(p[0], p[2]), e(p[0], p[3])});
      else
        m_mesh.triangles.push_back({e(p[0], p[1]), e(p[0], p[3]), e(p[0], p[2])});
      return;
    }
    // Two inside (i, j), two outside (k, l): the quad ik, il, jl, jk, split along its shorter diagonal.
    const std::array<int, 4> p = evenPermutation({inside[0], inside[1], outside[0], outside[1]});
    const std::int32_t ik = e(p[0], p[2]);
    const std::int32_t il = e(p[0], p[3]);
    const std::int32_t jl = e(p[1], p[3]);
    const std::int32_t jk = e(p[1], p[2]);
    const auto& x = m_mesh.vertices;
    if ((x[ik] - x[jl]).squaredNorm() <= (x[il] - x[jk]).squaredNorm()) {
      m_mesh.triangles.push_back({ik, il, jl});
      m_mesh.triangles.push_back({ik, jl, jk});
    } else {
      m_mesh.triangles.push_back({ik, il, jk});
      m_mesh.triangles.push_back({il, jl, jk});
    }
  }

  Vec3 m_origin;
  double m_cell;
  std::array<long long, 3> m_n;
  std::vector<double> m_values;
  std::array<Tetrahedron, 6> m_tets;
  std::unordered_map<std::uint64_t, std::int32_t> m_edgeVertex;
  TriangleMesh m_mesh;
};

// Seven edge directions per grid point keep every vertex index within int32 below this many points.
constexpr long long kGridPointLimit = 1LL << 28;

Error invalid(const std::string& message, const std::string& where) {
  return Error{ErrorCode::InvalidParameter, message, where};
}

}  // namespace

Result<TriangleMesh> polygonize(const SignedDistance& sdf, const BoundingBox& bounds, double cellSizeMm,
                                const PolygonizeOptions& options) {
  const char* where = "polygonize";
  if (!sdf) return invalid("no signed distance function was given", where);
  if (!(std::isfinite(cellSizeMm) && cellSizeMm > 0.0))
    return invalid("the cell size must be a finite length > 0 mm (got " + std::to_string(cellSizeMm) + ")", where);
  if (!(std::isfinite(options.zeroGuardFraction) && options.zeroGuardFraction > 0.0 && options.zeroGuardFraction < 0.5))
    return invalid("the zero guard must be a fraction of the cell size in (0, 0.5)", where);
  if (!(options.maxGridPoints >= 8 && options.maxGridPoints <= kGridPointLimit))
    return invalid("the grid point budget must be in [8, " + std::to_string(kGridPointLimit) + "]", where);
  if (!bounds.min.allFinite() || !bounds.max.allFinite() || !(bounds.max.array() > bounds.min.array()).all())
    return invalid("the box must be finite with max > min on every axis", where);

  std::array<long long, 3> counts{};
  double points = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double cells = std::ceil((bounds.max[a] - bounds.min[a]) / cellSizeMm);
    points *= cells + 1.0;
    if (!(points <= double(options.maxGridPoints)))
      return invalid("the grid would have more than " + std::to_string(options.maxGridPoints) +
                         " points; use a larger cell size or a smaller box",
                     where);
    counts[a] = static_cast<long long>(cells) + 1;
  }

  const double guard = options.zeroGuardFraction * cellSizeMm;
  std::vector<double> values(static_cast<std::size_t>(counts[0] * counts[1] * counts[2]));
  std::size_t index = 0;
  for (long long k = 0; k < counts[2]; ++k)
    for (long long j = 0; j < counts[1]; ++j)
      for (long long i = 0; i < counts[0]; ++i, ++index) {
        const Vec3 p = bounds.min + cellSizeMm * Vec3(double(i), double(j), double(k));
        double f = sdf(p);
        if (!std::isfinite(f))
          return invalid("the signed distance is not finite at grid point (" + std::to_string(i) + ", " +
                             std::to_string(j) + ", " + std::to_string(k) + ")",
                         where);
        // Values near zero would put crossings on top of grid points: zero-area triangles and
        // coincident vertices. Moving them outside shifts the surface by at most the guard.
        if (std::abs(f) < guard) f = guard;
        const bool onBoundary =
            i == 0 || j == 0 || k == 0 || i == counts[0] - 1 || j == counts[1] - 1 || k == counts[2] - 1;
        if (onBoundary && f < 0.0)
          return invalid("the solid reaches the box boundary at grid point (" + std::to_string(i) + ", " +
                             std::to_string(j) + ", " + std::to_string(k) +
                             "); enlarge the box so the surface lies strictly inside",
                         where);
        values[index] = f;
      }

  TriangleMesh mesh = Polygonizer(bounds, cellSizeMm, counts, std::move(values)).run();
  if (mesh.empty())
    return Error{ErrorCode::EmptyMesh, "the signed distance is positive at every grid point: nothing is inside", where};
  return mesh;
}

}  // namespace multidir::core::samples

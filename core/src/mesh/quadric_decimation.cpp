#include "mesh/quadric_decimation.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include "detail/huge_pages.h"
#include "detail/parallel.h"

namespace multidir::core::detail {
namespace {

// Cosine of the largest turn of a face's normal a collapse may cause.
constexpr double kMinNormalCosine = 0.5;
// Triangle quality 4 sqrt(3) area / (sum of squared edges): 1 equilateral, 0 degenerate. 0.1 is about a
// 1:12 sliver.
constexpr double kMinQuality = 0.1;
// Each pass collapses only among the cheapest share of the edges it scored, so costly edges wait for a later
// pass (scored again then) instead of going early because nothing cheaper was near.
constexpr double kPassShare = 0.25;
// Never fewer faces than this, however flat the model.
constexpr std::size_t kMinFaces = 100;
// Faces or vertices per task of the parallel loops: each task writes its own slots, so the results do not
// depend on the thread count, and a block is big enough that handing it out costs nothing.
constexpr int kBlock = 8192;
// The collapses of a pass run in slabs across the model's longest axis, at least this many vertices each
// (fewer slabs, fewer edges near a border left to the one-thread rest of the pass), at most kMaxSlabs; the
// count depends on the mesh alone, never on the threads.
constexpr std::size_t kSlabVertices = 32768;
constexpr int kMaxSlabs = 64;
// The slabs' borders sit at quantiles of the vertices along the axis, found to one bin of this many.
constexpr int kSlabBins = 4096;

int blockCount(std::size_t items) { return static_cast<int>((items + kBlock - 1) / kBlock); }

// The symmetric 4x4 matrix sum of area * (n.x + d)^2 over planes, as its ten distinct entries.
struct Quadric {
  double xx = 0, xy = 0, xz = 0, xw = 0, yy = 0, yz = 0, yw = 0, zz = 0, zw = 0, ww = 0;
  double weight = 0;  // the sum of the weights: error / weight is a mean squared distance

  static Quadric ofPlane(const Vec3& n, double d, double weight) {
    Quadric q;
    q.xx = weight * n.x() * n.x(), q.xy = weight * n.x() * n.y(), q.xz = weight * n.x() * n.z();
    q.xw = weight * n.x() * d, q.yy = weight * n.y() * n.y(), q.yz = weight * n.y() * n.z();
    q.yw = weight * n.y() * d, q.zz = weight * n.z() * n.z(), q.zw = weight * n.z() * d, q.ww = weight * d * d;
    q.weight = weight;
    return q;
  }
  Quadric& operator+=(const Quadric& o) {
    xx += o.xx, xy += o.xy, xz += o.xz, xw += o.xw, yy += o.yy, yz += o.yz, yw += o.yw, zz += o.zz, zw += o.zw;
    ww += o.ww, weight += o.weight;
    return *this;
  }
  [[nodiscard]] double error(const Vec3& p) const {
    const double x = p.x(), y = p.y(), z = p.z();
    return xx * x * x + 2 * xy * x * y + 2 * xz * x * z + 2 * xw * x + yy * y * y + 2 * yz * y * z + 2 * yw * y +
           zz * z * z + 2 * zw * z + ww;
  }
};

// An edge as the passes sort it: small, since each pass partitions all of them (the merged point is found
// again, identically, for the few the pass considers).
struct Candidate {
  double cost;
  double lengthSquared;  // ties (flat regions cost nothing) go to the shorter edge
  std::int32_t a, b;
};

// A candidate about to be checked and taken: b merges into a, which moves to target.
struct Collapse {
  std::int32_t a, b;
  Vec3 target;
  double meanSquaredDistance;  // the error over the quadric's weight
};

double quality(const Vec3& p0, const Vec3& p1, const Vec3& p2, double doubleArea) {
  const double edges = (p1 - p0).squaredNorm() + (p2 - p1).squaredNorm() + (p0 - p2).squaredNorm();
  return edges > 0 ? 2.0 * std::sqrt(3.0) * doubleArea / edges : 0.0;
}

// Where the merged vertex goes: the quadric's minimum when it is well defined and near the edge, otherwise
// the best of the midpoint and the two ends.
Vec3 bestPoint(const Quadric& q, const Vec3& a, const Vec3& b) {
  Eigen::Matrix3d m;
  m << q.xx, q.xy, q.xz, q.xy, q.yy, q.yz, q.xz, q.yz, q.zz;
  const double scale = (q.xx + q.yy + q.zz) / 3.0;
  const double det = m.determinant();
  const Vec3 mid = 0.5 * (a + b);
  if (scale > 0 && std::abs(det) > 1e-6 * scale * scale * scale) {
    const Vec3 optimum = m.inverse() * Vec3(-q.xw, -q.yw, -q.zw);
    if (optimum.allFinite() && (optimum - mid).squaredNorm() <= (b - a).squaredNorm()) return optimum;
  }
  Vec3 best = mid;
  double bestError = q.error(mid);
  for (const Vec3* p : {&a, &b})
    if (const double e = q.error(*p); e < bestError) best = *p, bestError = e;
  return best;
}

// The plane quadric of face t, or nothing (false) for a face without area.
bool faceQuadric(const std::vector<Vec3>& points, const Triangle& t, Quadric& q) {
  const Vec3 n = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
  const double doubleArea = n.norm();
  if (!(doubleArea > 0)) return false;
  const Vec3 unit = n / doubleArea;
  q = Quadric::ofPlane(unit, -unit.dot(points[t[0]]), 0.5 * doubleArea);
  return true;
}

class Decimator {
 public:
  Decimator(const TriangleMesh& mesh, int threads)
      : m_removed(mesh.triangles.size(), 0), m_stamp(mesh.vertices.size(), 0), m_touched(mesh.vertices.size(), 0),
        m_absorbed(mesh.vertices.size(), -1), m_threads(resolveThreadCount(threads)) {
    // The big arrays in huge pages (detail/huge_pages.h): a million-face mesh's quadrics alone take 40 MB.
    reserveInHugePages(m_points, mesh.vertices.size());
    m_points.assign(mesh.vertices.begin(), mesh.vertices.end());
    reserveInHugePages(m_triangles, mesh.triangles.size());
    m_triangles.assign(mesh.triangles.begin(), mesh.triangles.end());
    reserveInHugePages(m_quadrics, mesh.vertices.size());
    m_quadrics.resize(mesh.vertices.size());
    m_faces = m_triangles.size();
  }

  // Whether the mesh is a closed, consistently oriented 2-manifold, from each vertex's faces (the same verdict
  // as edgeCensus(mesh).closedOriented(), which sorts every half-edge; the caller runs that only to say what is
  // wrong). Builds the faces around each vertex and the vertex quadrics on the way: call once, first.
  bool prepare() {
    const std::int32_t vertexCount = static_cast<std::int32_t>(m_points.size());
    for (const Triangle& t : m_triangles)
      for (std::int32_t v : t)
        if (v < 0 || v >= vertexCount) return false;
    buildVertexFaces();
    const int blocks = blockCount(m_points.size());
    std::vector<char> blockOk(static_cast<std::size_t>(blocks), 1);
    detail::parallelFor(blocks, m_threads, [&](int block) {
      std::vector<std::pair<std::int32_t, std::int32_t>> fan;  // (next, previous) corner of each face at v
      std::vector<std::int32_t> previous;
      const std::size_t end = std::min(m_points.size(), static_cast<std::size_t>(block + 1) * kBlock);
      for (std::size_t v = static_cast<std::size_t>(block) * kBlock; v < end; ++v) {
        // The vertex quadric: its faces' quadrics summed in ascending face order, as one pass over the faces
        // would sum them.
        Quadric sum;
        fan.clear();
        for (std::int32_t i = m_firstFace[v]; i < m_firstFace[v + 1]; ++i) {
          const Triangle& t = m_triangles[m_faceOfVertex[i]];
          Quadric q;
          if (faceQuadric(m_points, t, q)) sum += q;
          const int k = t[0] == static_cast<std::int32_t>(v) ? 0 : t[1] == static_cast<std::int32_t>(v) ? 1 : 2;
          fan.emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
        }
        m_quadrics[v] = sum;
        if (!isOneClosedFan(static_cast<std::int32_t>(v), fan, previous)) blockOk[block] = 0;
      }
    });
    return std::all_of(blockOk.begin(), blockOk.end(), [](char ok) { return ok != 0; });
  }

  void run(std::size_t targetFaces, double freeToleranceMm, std::size_t fineBelowFaces, double fineToleranceMm) {
    assignSlabs();
    const double freeMeanSquared = freeToleranceMm * freeToleranceMm;
    const double fineMeanSquared = std::min(fineToleranceMm, freeToleranceMm) * std::min(fineToleranceMm, freeToleranceMm);
    std::vector<Candidate> candidates;
    bool first = true;
    while (m_faces > kMinFaces) {
      if (!first) {  // prepare() built the first pass's face lists
        compactFaces();
        buildVertexFaces();
      }
      // Edges away from the last pass's collapses keep their scores: neither end moved or gained a quadric.
      if (!first)
        candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                        [&](const Candidate& c) { return m_touched[c.a] || m_touched[c.b]; }),
                         candidates.end());
      addScoredEdges(candidates, first);
      first = false;
      if (candidates.empty()) return;
      const auto share = std::max<std::size_t>(1, static_cast<std::size_t>(kPassShare * candidates.size()));
      const auto cheaper = [](const Candidate& x, const Candidate& y) {
        if (x.cost != y.cost) return x.cost < y.cost;
        if (x.lengthSquared != y.lengthSquared) return x.lengthSquared < y.lengthSquared;
        return x.a != y.a ? x.a < y.a : x.b < y.b;
      };
      const auto shareEnd = candidates.begin() + static_cast<std::ptrdiff_t>(share);
      std::nth_element(candidates.begin(), shareEnd - 1, candidates.end(), cheaper);
      parallelSort(candidates.begin(), shareEnd, cheaper, m_threads, kBlock);
      std::fill(m_touched.begin(), m_touched.end(), 0);
      std::fill(m_absorbed.begin(), m_absorbed.end(), -1);
      // Each collapse changes what the next ones may do, so the share is taken in order. (Planning every edge
      // of the share on threads beforehand was tried: less than half of them are still untouched when their
      // turn comes, so it cost more than it saved.) But a collapse reads and writes only the faces around its
      // edge and their corners: the edges whose faces lie inside one slab go first, each slab in order on its
      // own thread, as many as leave more than targetFaces faces (no tolerance applies above it), then the
      // rest in order on one thread.
      std::vector<char> decided(share, 0);
      std::size_t collapsed = 0;
      const std::size_t floorFaces = std::max(targetFaces, kMinFaces);
      for (const std::vector<std::uint8_t>& slabs : m_slabs)
        if (m_faces > floorFaces + 2)  // each collapse removes the two faces of its edge
          collapsed += collapseWithinSlabs(candidates, share, slabs, (m_faces - floorFaces - 1) / 2, decided);
      for (std::size_t i = 0; i < share && m_faces > kMinFaces; ++i) {
        if (decided[i] || m_touched[candidates[i].a] || m_touched[candidates[i].b]) continue;
        const Collapse c = planned(candidates[i].a, candidates[i].b);
        if (m_faces <= targetFaces &&
            c.meanSquaredDistance > (m_faces <= fineBelowFaces ? fineMeanSquared : freeMeanSquared))
          continue;
        if (!allowed(c, nextMarks())) continue;
        m_faces -= collapse(c);
        ++collapsed;
      }
      if (collapsed == 0) return;
    }
  }

  TriangleMesh result() const {
    TriangleMesh out;
    std::vector<std::int32_t> index(m_points.size(), -1);
    for (std::size_t f = 0; f < m_triangles.size(); ++f) {
      if (m_removed[f]) continue;
      Triangle t = m_triangles[f];
      for (std::int32_t& v : t) {
        if (index[v] < 0) {
          index[v] = static_cast<std::int32_t>(out.vertices.size());
          out.vertices.push_back(m_points[v]);
        }
        v = index[v];
      }
      out.triangles.push_back(t);
    }
    out.resetOrigins();
    return out;
  }

 private:
  // Labels every vertex with its slab across the longest axis of the bounding box, twice: m_slabs[0] in
  // slabs of about equal vertex counts, m_slabs[1] shifted by half a slab (one more slab), so that edges left
  // at a border of the first go in the second. None for a mesh of one slab: its passes stay on one thread.
  void assignSlabs() {
    const std::size_t vertexCount = m_points.size();
    const std::size_t slabCount = std::clamp<std::size_t>(vertexCount / kSlabVertices, 1, kMaxSlabs);
    m_slabs.clear();
    if (slabCount == 1) return;
    Vec3 low = m_points[0], high = m_points[0];
    for (const Vec3& p : m_points) low = low.cwiseMin(p), high = high.cwiseMax(p);
    int axis = 0;
    (high - low).maxCoeff(&axis);
    const double span = high[axis] - low[axis];
    const auto binOf = [&](const Vec3& p) {
      return span > 0 ? std::min(kSlabBins - 1, static_cast<int>((p[axis] - low[axis]) / span * kSlabBins)) : 0;
    };
    std::vector<std::size_t> before(kSlabBins + 1, 0);  // vertices in the bins below each bin
    for (const Vec3& p : m_points) ++before[static_cast<std::size_t>(binOf(p)) + 1];
    for (int bin = 0; bin < kSlabBins; ++bin) before[bin + 1] += before[bin];
    m_slabs.assign(2, std::vector<std::uint8_t>(vertexCount));
    for (std::size_t v = 0; v < vertexCount; ++v) {
      const std::size_t halfSlab = before[static_cast<std::size_t>(binOf(m_points[v]))] * 2 * slabCount / vertexCount;
      m_slabs[0][v] = static_cast<std::uint8_t>(halfSlab / 2);
      m_slabs[1][v] = static_cast<std::uint8_t>((halfSlab + 1) / 2);
    }
  }

  // Takes, in order, the share's undecided candidates whose faces (those around both ends) have every corner
  // in one slab of `slabs`, each slab on its own thread: a collapse changes only those faces and its
  // survivor, so no slab sees another's work, and each slab's result is the one of its own order, whatever
  // the threads. At most maxCollapses in all (an equal part per slab, the rest left undecided): the caller
  // sizes it so that the faces stay above the target, where no tolerance applies. Marks what it decided;
  // returns the collapses taken.
  std::size_t collapseWithinSlabs(const std::vector<Candidate>& candidates, std::size_t share,
                                  const std::vector<std::uint8_t>& slabs, std::size_t maxCollapses,
                                  std::vector<char>& decided) {
    const int slabCount = 1 + *std::max_element(slabs.begin(), slabs.end());
    const std::size_t perSlab = maxCollapses / static_cast<std::size_t>(slabCount);
    if (perSlab == 0) return 0;
    std::vector<std::vector<std::int32_t>> inSlab(static_cast<std::size_t>(slabCount));
    for (std::size_t i = 0; i < share; ++i)
      if (!decided[i] && slabs[candidates[i].a] == slabs[candidates[i].b])
        inSlab[slabs[candidates[i].a]].push_back(static_cast<std::int32_t>(i));
    // The link check's two stamps per candidate, from the candidate's index: unique whichever slab runs it.
    const int firstMark = m_stampCount;
    m_stampCount += 2 * static_cast<int>(share) + 2;
    std::vector<std::size_t> removedFaces(static_cast<std::size_t>(slabCount), 0), taken(removedFaces);
    detail::parallelFor(slabCount, m_threads, [&](int slab) {
      for (const std::int32_t i : inSlab[static_cast<std::size_t>(slab)]) {
        if (taken[static_cast<std::size_t>(slab)] == perSlab) break;
        const Candidate& candidate = candidates[static_cast<std::size_t>(i)];
        // Both ends are in this slab, so only this thread moves them in this round; a moved end stays moved
        // for the pass, and the one-thread rest would skip the edge as well.
        if (m_touched[candidate.a] || m_touched[candidate.b]) {
          decided[static_cast<std::size_t>(i)] = 1;
          continue;
        }
        bool inside = true;
        const auto inThisSlab = [&](std::int32_t f) {
          for (const std::int32_t v : m_triangles[f]) inside = inside && slabs[v] == slab;
        };
        forFacesAround(candidate.a, inThisSlab);
        forFacesAround(candidate.b, inThisSlab);
        if (!inside) continue;  // left to the next slabs or to the one-thread rest
        decided[static_cast<std::size_t>(i)] = 1;
        const Collapse c = planned(candidate.a, candidate.b);
        if (!allowed(c, firstMark + 2 * i)) continue;
        removedFaces[static_cast<std::size_t>(slab)] += collapse(c);
        ++taken[static_cast<std::size_t>(slab)];
      }
    });
    for (int slab = 0; slab < slabCount; ++slab) m_faces -= removedFaces[slab];
    return std::accumulate(taken.begin(), taken.end(), std::size_t{0});
  }

  // Two fresh stamps for one link check on one thread.
  int nextMarks() {
    m_stampCount += 2;
    return m_stampCount - 2;
  }

  // Drops removed faces once they are most of the array, so that a pass costs what is left, not what was
  // loaded (a 640,000-face mesh takes some 20 passes to reach 10,000). Faces are known by index within a
  // pass only: the candidates name vertices.
  void compactFaces() {
    if (2 * m_faces > m_triangles.size()) return;
    std::size_t kept = 0;
    for (std::size_t f = 0; f < m_triangles.size(); ++f)
      if (!m_removed[f]) m_triangles[kept++] = m_triangles[f];
    m_triangles.resize(kept);
    m_removed.assign(kept, 0);
  }

  // The faces around each vertex, as ranges of one flat array (rebuilt each pass: collapses only ever touch
  // faces around vertices they mark, which the rest of the pass leaves alone).
  void buildVertexFaces() {
    m_firstFace.assign(m_points.size() + 1, 0);
    for (std::size_t f = 0; f < m_triangles.size(); ++f)
      if (!m_removed[f])
        for (std::int32_t v : m_triangles[f]) ++m_firstFace[static_cast<std::size_t>(v) + 1];
    for (std::size_t v = 0; v < m_points.size(); ++v) m_firstFace[v + 1] += m_firstFace[v];
    reserveInHugePages(m_faceOfVertex, static_cast<std::size_t>(m_firstFace.back()));
    m_faceOfVertex.resize(m_firstFace.back());
    std::vector<std::int32_t> next(m_firstFace.begin(), m_firstFace.end() - 1);
    for (std::size_t f = 0; f < m_triangles.size(); ++f)
      if (!m_removed[f])
        for (std::int32_t v : m_triangles[f]) m_faceOfVertex[next[v]++] = static_cast<std::int32_t>(f);
  }

  // The live faces around v: its own list and, once it absorbed a vertex this pass, that vertex's list (whose
  // faces now name v). A vertex absorbs at most one per pass: it is touched after.
  template <typename Visit>
  void forFacesAround(std::int32_t v, Visit visit) const {
    for (std::int32_t u = v; u >= 0; u = u == v ? m_absorbed[v] : -1)
      for (std::int32_t i = m_firstFace[u]; i < m_firstFace[u + 1]; ++i)
        if (!m_removed[m_faceOfVertex[i]]) visit(m_faceOfVertex[i]);
  }

  // Whether the faces around v, given as the (next, previous) corners of each, meet every neighbour across
  // exactly one edge each way and form one fan: each half-edge from v once, its opposite once, and the faces
  // joined across those edges in a single cycle. `previous` is scratch space.
  static bool isOneClosedFan(std::int32_t v, std::vector<std::pair<std::int32_t, std::int32_t>>& fan,
                             std::vector<std::int32_t>& previous) {
    if (fan.empty()) return true;  // an unused vertex
    std::sort(fan.begin(), fan.end());
    previous.clear();
    for (std::size_t i = 0; i < fan.size(); ++i) {
      if (fan[i].first == v || fan[i].second == v || fan[i].first == fan[i].second) return false;  // degenerate
      if (i > 0 && fan[i].first == fan[i - 1].first) return false;  // the half-edge v->next twice
      previous.push_back(fan[i].second);
    }
    std::sort(previous.begin(), previous.end());
    for (std::size_t i = 0; i < fan.size(); ++i)
      if (previous[i] != fan[i].first) return false;  // an edge at v with one face, or two facing the same way
    // Around the fan: the face after (v, next, previous) is the one whose next is this one's previous.
    std::size_t face = 0, steps = 0;
    do {
      const auto after = std::lower_bound(fan.begin(), fan.end(), std::make_pair(fan[face].second, std::numeric_limits<std::int32_t>::min()));
      face = static_cast<std::size_t>(after - fan.begin());
      ++steps;
    } while (face != 0 && steps <= fan.size());
    return steps == fan.size();
  }

  // Scores every edge (the first pass) or those with a touched end (later passes), in face order, on threads:
  // each block of faces counts its edges, then writes them at its own place.
  void addScoredEdges(std::vector<Candidate>& out, bool all) const {
    const auto scores = [&](const Triangle& t, int k) {
      const std::int32_t a = t[k], b = t[(k + 1) % 3];
      if (a > b) return false;  // each edge of a closed mesh is seen once each way
      return all || m_touched[a] || m_touched[b];
    };
    const int blocks = blockCount(m_triangles.size());
    std::vector<std::size_t> start(static_cast<std::size_t>(blocks) + 1, 0);
    detail::parallelFor(blocks, m_threads, [&](int block) {
      const std::size_t end = std::min(m_triangles.size(), static_cast<std::size_t>(block + 1) * kBlock);
      std::size_t count = 0;
      for (std::size_t f = static_cast<std::size_t>(block) * kBlock; f < end; ++f)
        if (!m_removed[f])
          for (int k = 0; k < 3; ++k) count += scores(m_triangles[f], k) ? 1 : 0;
      start[static_cast<std::size_t>(block) + 1] = count;
    });
    start[0] = out.size();
    for (int block = 0; block < blocks; ++block) start[block + 1] += start[block];
    reserveInHugePages(out, start.back());
    out.resize(start.back());
    detail::parallelFor(blocks, m_threads, [&](int block) {
      const std::size_t end = std::min(m_triangles.size(), static_cast<std::size_t>(block + 1) * kBlock);
      std::size_t next = start[block];
      for (std::size_t f = static_cast<std::size_t>(block) * kBlock; f < end; ++f) {
        if (m_removed[f]) continue;
        const Triangle& t = m_triangles[f];
        for (int k = 0; k < 3; ++k) {
          if (!scores(t, k)) continue;
          const std::int32_t a = t[k], b = t[(k + 1) % 3];
          Quadric q = m_quadrics[a];
          q += m_quadrics[b];
          const double cost = std::max(0.0, q.error(bestPoint(q, m_points[a], m_points[b])));
          out[next++] = {cost, (m_points[a] - m_points[b]).squaredNorm(), a, b};
        }
      }
    });
  }

  Collapse planned(std::int32_t a, std::int32_t b) const {
    Quadric q = m_quadrics[a];
    q += m_quadrics[b];
    const Vec3 target = bestPoint(q, m_points[a], m_points[b]);
    const double cost = std::max(0.0, q.error(target));
    return {a, b, target, q.weight > 0 ? cost / q.weight : INFINITY};
  }

  // Whether the collapse keeps the rules of the header; `firstMark` and the next are stamps no other check
  // uses.
  bool allowed(const Collapse& c, int firstMark) {
    // Link condition: a and b share exactly the two vertices opposite their edge.
    const int mark = firstMark + 1;
    forFacesAround(c.a, [&](std::int32_t f) {
      for (std::int32_t v : m_triangles[f]) m_stamp[v] = mark;
    });
    const int seen = firstMark + 2;
    int common = 0;
    forFacesAround(c.b, [&](std::int32_t f) {
      for (std::int32_t v : m_triangles[f])
        if (v != c.a && v != c.b && m_stamp[v] == mark) {
          m_stamp[v] = seen;
          ++common;
        }
    });
    if (common != 2) return false;
    // No face turns over or becomes a sliver.
    bool ok = true;
    auto check = [&](std::int32_t f) {
      if (!ok) return;
      const Triangle& t = m_triangles[f];
      const bool hasA = t[0] == c.a || t[1] == c.a || t[2] == c.a;
      const bool hasB = t[0] == c.b || t[1] == c.b || t[2] == c.b;
      if (hasA && hasB) return;  // goes with the edge
      std::array<Vec3, 3> before{m_points[t[0]], m_points[t[1]], m_points[t[2]]};
      std::array<Vec3, 3> after = before;
      for (int k = 0; k < 3; ++k)
        if (t[k] == c.a || t[k] == c.b) after[k] = c.target;
      const Vec3 n0 = (before[1] - before[0]).cross(before[2] - before[0]);
      const Vec3 n1 = (after[1] - after[0]).cross(after[2] - after[0]);
      const double area1 = n1.norm(), area0 = n0.norm();
      if (!(area1 > 0) || n0.dot(n1) < kMinNormalCosine * area0 * area1) {
        ok = false;
        return;
      }
      const double q1 = quality(after[0], after[1], after[2], area1);
      if (q1 < kMinQuality && q1 < quality(before[0], before[1], before[2], area0)) ok = false;
    };
    forFacesAround(c.a, check);
    forFacesAround(c.b, check);
    return ok;
  }

  // Collapses the edge; returns the faces it removed (the caller counts them: slabs run side by side).
  std::size_t collapse(const Collapse& c) {
    m_points[c.a] = c.target;
    m_quadrics[c.a] += m_quadrics[c.b];
    std::size_t removed = 0;
    forFacesAround(c.b, [&](std::int32_t f) {
      Triangle& t = m_triangles[f];
      if (t[0] == c.a || t[1] == c.a || t[2] == c.a) {
        m_removed[f] = 1;
        ++removed;
        return;
      }
      for (std::int32_t& v : t)
        if (v == c.b) v = c.a;
    });
    m_absorbed[c.a] = c.b;
    // Only edges at a changed (a moved and took b's quadric); every other edge keeps its score, and the live
    // face lists keep every later check of this pass exact.
    m_touched[c.a] = m_touched[c.b] = 1;
    return removed;
  }

  std::vector<Vec3> m_points;
  std::vector<Triangle> m_triangles;
  std::vector<Quadric> m_quadrics;
  std::vector<char> m_removed;
  std::vector<int> m_stamp;
  int m_stampCount = 0;
  std::vector<char> m_touched;         // moved or gone this pass
  std::vector<std::int32_t> m_absorbed;  // the vertex each one absorbed this pass, or -1
  std::vector<std::int32_t> m_firstFace, m_faceOfVertex;
  std::size_t m_faces = 0;
  int m_threads = 1;
  std::vector<std::vector<std::uint8_t>> m_slabs;  // each vertex's slab, in two shifted slabbings (none: one slab)
};

}  // namespace

std::optional<TriangleMesh> quadricDecimation(const TriangleMesh& mesh, std::size_t targetFaces, double freeToleranceMm,
                                              int threads, std::size_t fineBelowFaces, double fineToleranceMm) {
  Decimator decimator(mesh, threads);
  if (!decimator.prepare()) return std::nullopt;
  decimator.run(targetFaces, freeToleranceMm, fineBelowFaces, fineToleranceMm);
  return decimator.result();
}

}  // namespace multidir::core::detail

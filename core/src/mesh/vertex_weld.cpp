#include "mesh/vertex_weld.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

#include "detail/flat_index.h"
#include "detail/huge_pages.h"
#include "detail/parallel.h"

namespace multidir::core::detail {
namespace {

// A point's coordinates as bits for hashing, -0 as +0 (they compare equal).
std::array<std::int64_t, 3> bitsOf(const Vec3& p) {
  std::array<std::int64_t, 3> bits{};
  for (int i = 0; i < 3; ++i) {
    const double c = p[i] == 0.0 ? 0.0 : p[i];
    std::memcpy(&bits[static_cast<std::size_t>(i)], &c, sizeof(double));
  }
  return bits;
}

std::uint64_t hashOf(const std::array<std::int64_t, 3>& c) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
  return h;
}

// Both searches below work on threads, each of kWeldPartitions slices of the hash space by itself in point
// order, so the answer does not depend on the thread count; a slice's table is small enough to stay in
// cache, where one table for two million STL corners would miss on every probe.
constexpr int kWeldPartitions = 64;
constexpr std::size_t kWeldBlock = 16384;  // points per task of the loops over all of them

int sliceOfHash(std::uint64_t hash) { return static_cast<int>(FlatIndex::mix(hash) >> 58); }  // the top 6 bits

std::pair<std::size_t, std::size_t> blockRange(int block, std::size_t count) {
  const std::size_t begin = static_cast<std::size_t>(block) * kWeldBlock;
  return {begin, std::min(count, begin + kWeldBlock)};
}

int blockCount(std::size_t count) { return static_cast<int>((count + kWeldBlock - 1) / kWeldBlock); }

// The items [0, count) for which keyOf(i) gives a slice (>= 0; -1 leaves an item out), grouped by slice and in
// item order within each (a counting sort: slice-major, then block, then item). sliceStart[s] is where slice
// s begins in the result.
template <typename SliceOf>
std::vector<std::int32_t> groupedBySlice(std::size_t count, int threads, SliceOf sliceOf,
                                         std::vector<std::size_t>& sliceStart) {
  const int blocks = blockCount(count);
  std::vector<std::uint8_t> slice(count);
  std::vector<std::size_t> counts(static_cast<std::size_t>(blocks) * kWeldPartitions, 0);
  parallelFor(blocks, threads, [&](int block) {
    const auto [begin, end] = blockRange(block, count);
    std::size_t* blockCounts = &counts[static_cast<std::size_t>(block) * kWeldPartitions];
    for (std::size_t i = begin; i < end; ++i) {
      const int s = sliceOf(i);
      slice[i] = static_cast<std::uint8_t>(s < 0 ? 0xff : s);
      if (s >= 0) ++blockCounts[s];
    }
  });
  sliceStart.assign(kWeldPartitions + 1, 0);
  std::vector<std::size_t> offsets(counts.size());
  std::size_t next = 0;
  for (int s = 0; s < kWeldPartitions; ++s) {
    sliceStart[static_cast<std::size_t>(s)] = next;
    for (int block = 0; block < blocks; ++block) {
      const std::size_t i = static_cast<std::size_t>(block) * kWeldPartitions + static_cast<std::size_t>(s);
      offsets[i] = next;
      next += counts[i];
    }
  }
  sliceStart[kWeldPartitions] = next;
  std::vector<std::int32_t> order;
  reserveInHugePages(order, next);
  order.resize(next);
  parallelFor(blocks, threads, [&](int block) {
    const auto [begin, end] = blockRange(block, count);
    std::size_t* blockOffsets = &offsets[static_cast<std::size_t>(block) * kWeldPartitions];
    for (std::size_t i = begin; i < end; ++i)
      if (slice[i] != 0xff) order[blockOffsets[slice[i]]++] = static_cast<std::int32_t>(i);
  });
  return order;
}

// For every used point, the first used point with exactly its coordinates (itself for a first occurrence;
// -0 and +0 are one coordinate); -1 for unused points. Also the largest |coordinate| of a used point.
std::vector<std::int32_t> firstEqualPoints(const std::vector<Vec3>& points, const std::vector<char>& used, int threads,
                                           double& maxAbs) {
  const std::size_t count = points.size();
  std::vector<double> blockMax(static_cast<std::size_t>(blockCount(count)), 0.0);
  std::vector<std::size_t> sliceStart;
  const std::vector<std::int32_t> order = groupedBySlice(
      count, threads,
      [&](std::size_t v) {
        if (!used[v]) return -1;
        double& largest = blockMax[v / kWeldBlock];  // each block's own slot
        largest = std::max(largest, points[v].cwiseAbs().maxCoeff());
        return sliceOfHash(hashOf(bitsOf(points[v])));
      },
      sliceStart);
  maxAbs = 0.0;
  for (const double m : blockMax) maxAbs = std::max(maxAbs, m);
  std::vector<std::int32_t> first = filledInHugePages<std::int32_t>(count, -1);
  parallelFor(kWeldPartitions, threads, [&](int slice) {
    const std::size_t begin = sliceStart[static_cast<std::size_t>(slice)];
    const std::size_t end = sliceStart[static_cast<std::size_t>(slice) + 1];
    FlatIndex seen(end - begin);
    for (std::size_t i = begin; i < end; ++i) {
      const auto v = static_cast<std::size_t>(order[i]);
      const Vec3& p = points[v];
      std::int32_t& same = seen.find(hashOf(bitsOf(p)), [&](std::int32_t w) {
        const Vec3& q = points[static_cast<std::size_t>(w)];
        return q.x() == p.x() && q.y() == p.y() && q.z() == p.z();
      });
      if (same < 0) same = static_cast<std::int32_t>(v);
      first[v] = same;
    }
  });
  return first;
}

using Cell = std::array<std::int64_t, 3>;

// Spelled out: std::array's == calls memcmp, which was a sixth of the load's time.
bool sameCell(const Cell& a, const Cell& b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

// The distinct points (first occurrences) in a grid of cells four times the tolerance wide: along each axis a
// point lies within the tolerance of at most one side of its cell, and of neither when it lies in the middle
// (kBorderShare of the cell from each side, with room for rounding), so whatever is that close to it lies in
// its cell or the next one on that side: 1 to 8 cells, 3.4 on average, where cells twice the tolerance wide
// always took 8. Each cell's points are chained in point order.
constexpr double kCellTolerances = 4.0;
constexpr double kBorderShare = 0.3;  // 1.2 tolerances: a point farther from the border has nothing across it
class WeldGrid {
 public:
  WeldGrid(const std::vector<Vec3>& points, const std::vector<std::int32_t>& distinct, double tolerance, int threads)
      : m_points(points), m_distinct(distinct), m_cellSize(kCellTolerances * tolerance), m_toleranceSquared(tolerance * tolerance) {
    reserveInHugePages(m_cells, distinct.size());
    m_cells.resize(distinct.size());
    m_next.assign(distinct.size(), -1);
    std::vector<std::size_t> sliceStart;
    const std::vector<std::int32_t> order = groupedBySlice(
        distinct.size(), threads,
        [&](std::size_t i) {
          m_cells[i] = cellOf(points[static_cast<std::size_t>(distinct[i])]);
          return sliceOfHash(hashOf(m_cells[i]));
        },
        sliceStart);
    m_slices.reserve(kWeldPartitions);
    for (int s = 0; s < kWeldPartitions; ++s)
      m_slices.emplace_back(sliceStart[static_cast<std::size_t>(s) + 1] - sliceStart[static_cast<std::size_t>(s)]);
    // Each slice's cells and chains by itself: a point's chain links and its cell's head belong to its slice.
    std::vector<std::int32_t> last(distinct.size(), -1);
    parallelFor(kWeldPartitions, threads, [&](int s) {
      for (std::size_t k = sliceStart[static_cast<std::size_t>(s)]; k < sliceStart[static_cast<std::size_t>(s) + 1]; ++k) {
        const std::int32_t i = order[k];
        std::int32_t& head = headOf(s, m_cells[static_cast<std::size_t>(i)]);
        if (head < 0) {
          head = i;
        } else {
          m_next[static_cast<std::size_t>(last[static_cast<std::size_t>(head)])] = i;
        }
        last[static_cast<std::size_t>(head)] = i;
      }
    });
  }

  // Calls visit(j) for the distinct points j in the cells that may hold points within the tolerance of
  // distinct point i, each cell's in point order, until visit returns false for that cell.
  template <typename Visit>
  void forNearbyCandidates(std::size_t i, Visit visit) const {
    const Cell& cell = m_cells[i];
    const Vec3& p = m_points[static_cast<std::size_t>(m_distinct[i])];
    Cell side{};  // -1 or +1: the neighbour along that axis that may hold near points; 0: none may
    for (int a = 0; a < 3; ++a) {
      const double within = p[a] / m_cellSize - static_cast<double>(cell[static_cast<std::size_t>(a)]);
      side[static_cast<std::size_t>(a)] = within < kBorderShare ? -1 : within > 1.0 - kBorderShare ? 1 : 0;
    }
    for (int corner = 0; corner < 8; ++corner) {
      if (((corner & 1) && side[0] == 0) || ((corner & 2) && side[1] == 0) || ((corner & 4) && side[2] == 0)) continue;
      const Cell near{cell[0] + ((corner & 1) ? side[0] : 0), cell[1] + ((corner & 2) ? side[1] : 0),
                      cell[2] + ((corner & 4) ? side[2] : 0)};
      const std::uint64_t hash = hashOf(near);
      for (std::int32_t j = headOf(sliceOfHash(hash), near); j >= 0; j = m_next[static_cast<std::size_t>(j)])
        if (!visit(static_cast<std::size_t>(j))) break;
    }
  }

  [[nodiscard]] bool within(std::size_t i, std::size_t j) const {
    return (m_points[static_cast<std::size_t>(m_distinct[i])] - m_points[static_cast<std::size_t>(m_distinct[j])])
               .squaredNorm() <= m_toleranceSquared;
  }

 private:
  [[nodiscard]] Cell cellOf(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / m_cellSize)),
            static_cast<std::int64_t>(std::floor(p.y() / m_cellSize)),
            static_cast<std::int64_t>(std::floor(p.z() / m_cellSize))};
  }
  // The first point of `cell` (in slice s, the slice of its hash), or the empty slot where it goes; -1 when
  // empty. Only the slice's own builder writes; the searches only read.
  std::int32_t& headOf(int s, const Cell& cell) const {
    return m_slices[static_cast<std::size_t>(s)].find(
        hashOf(cell), [&](std::int32_t j) { return sameCell(m_cells[static_cast<std::size_t>(j)], cell); });
  }

  const std::vector<Vec3>& m_points;
  const std::vector<std::int32_t>& m_distinct;
  double m_cellSize, m_toleranceSquared;
  std::vector<Cell> m_cells;         // of each distinct point
  std::vector<std::int32_t> m_next;  // the next distinct point in the same cell, or -1
  mutable std::vector<FlatIndex> m_slices;
};

}  // namespace

std::vector<std::int32_t> weldVertices(const std::vector<Vec3>& points, const std::vector<char>& used, double tolerance,
                                       int threads, std::vector<Vec3>& welded, std::size_t& merged,
                                       std::vector<std::int64_t>& firstMerged, std::size_t firstFew) {
  threads = resolveThreadCount(threads);
  const std::size_t count = points.size();
  double maxAbs = 0.0;
  const std::vector<std::int32_t> firstEqual = firstEqualPoints(points, used, threads, maxAbs);
  // The first occurrences, in point order.
  std::vector<std::int32_t> distinct;
  for (std::size_t v = 0; v < count; ++v)
    if (firstEqual[v] == static_cast<std::int32_t>(v)) distinct.push_back(static_cast<std::int32_t>(v));
  // With a zero tolerance, or coordinates too large for integer cells, only identical points merge.
  const bool exactOnly = !(tolerance > 0.0) || maxAbs / tolerance > 1e15;
  // The distinct points with an earlier one within the tolerance, on threads, each point by itself: the
  // choice below depends on the order, but a point with no earlier one near it is kept whatever came before.
  std::vector<char> crowded(distinct.size(), 0);
  std::optional<WeldGrid> grid;
  if (!exactOnly) {
    grid.emplace(points, distinct, tolerance, threads);
    parallelFor(blockCount(distinct.size()), threads, [&](int block) {
      const auto [begin, end] = blockRange(block, distinct.size());
      for (std::size_t i = begin; i < end; ++i)
        grid->forNearbyCandidates(i, [&](std::size_t j) {
          if (j >= i) return false;  // chains run in point order
          if (grid->within(i, j)) crowded[i] = 1;
          return crowded[i] == 0;
        });
    });
  }
  // In point order: each distinct point goes to the earliest kept one within the tolerance, else is kept.
  std::vector<std::int32_t> indexOf(distinct.size(), -1);
  std::vector<char> kept(distinct.size(), 0);
  reserveInHugePages(welded, distinct.size());
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    std::int32_t found = -1;  // the earliest, as a distinct point's place
    if (crowded[i])
      grid->forNearbyCandidates(i, [&](std::size_t j) {
        if (j >= i || (found >= 0 && j >= static_cast<std::size_t>(found))) return false;  // chains run in point order
        if (kept[j] && grid->within(i, j)) found = static_cast<std::int32_t>(j);
        return true;
      });
    if (found >= 0) {
      indexOf[i] = indexOf[static_cast<std::size_t>(found)];
      continue;
    }
    kept[i] = 1;
    indexOf[i] = static_cast<std::int32_t>(welded.size());
    welded.push_back(points[static_cast<std::size_t>(distinct[i])]);
  }
  // Every used point where its first occurrence went.
  std::vector<std::int32_t> placeOf(count, -1);
  for (std::size_t i = 0; i < distinct.size(); ++i) placeOf[static_cast<std::size_t>(distinct[i])] = static_cast<std::int32_t>(i);
  std::vector<std::int32_t> map;
  reserveInHugePages(map, count);
  map.resize(count);
  parallelFor(blockCount(count), threads, [&](int block) {
    const auto [begin, end] = blockRange(block, count);
    for (std::size_t v = begin; v < end; ++v)
      map[v] = used[v] ? indexOf[static_cast<std::size_t>(placeOf[static_cast<std::size_t>(firstEqual[v])])] : -1;
  });
  std::size_t usedCount = 0;
  for (const char u : used) usedCount += u ? 1 : 0;
  merged = usedCount - welded.size();
  for (std::size_t v = 0; v < count && firstMerged.size() < std::min(firstFew, merged); ++v) {
    if (!used[v]) continue;
    const auto first = static_cast<std::size_t>(firstEqual[v]);
    if (first != v || !kept[static_cast<std::size_t>(placeOf[v])]) firstMerged.push_back(static_cast<std::int64_t>(v));
  }
  return map;
}

}  // namespace multidir::core::detail

#pragma once
// What has been printed so far, as bead samples in the model frame, hashed into cubes for the support check
// (b): which samples lie near a point.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace multidir::slicing::audit {

// One sample of a printed bead: the top of its centre line (the nozzle's path), model frame.
struct BeadSample {
  Eigen::Vector3f point;
  std::uint16_t direction = 0;  // index into the caller's table of printing directions (and bead sizes)
};

class MaterialGrid {
 public:
  explicit MaterialGrid(double cellMm) : m_cell(cellMm) {}
  void add(const BeadSample& sample);
  // Calls visit(sample) for the samples in the cells within `radiusMm` of p (a superset of those within the
  // radius) until visit returns true; returns whether one did.
  template <typename Visit>
  bool any(const Eigen::Vector3d& p, double radiusMm, Visit visit) const {
    const int reach = static_cast<int>(std::ceil(radiusMm / m_cell));
    const Eigen::Vector3i c = cellOf(p);
    for (int i = c.x() - reach; i <= c.x() + reach; ++i)
      for (int j = c.y() - reach; j <= c.y() + reach; ++j)
        for (int k = c.z() - reach; k <= c.z() + reach; ++k) {
          const auto found = m_cells.find(key(i, j, k));
          if (found == m_cells.end()) continue;
          for (const BeadSample& s : found->second)
            if (visit(s)) return true;
        }
    return false;
  }
  std::size_t size() const { return m_count; }

 private:
  Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const;
  static std::int64_t key(int i, int j, int k);

  double m_cell;
  std::size_t m_count = 0;
  std::unordered_map<std::int64_t, std::vector<BeadSample>> m_cells;
};

}  // namespace multidir::slicing::audit

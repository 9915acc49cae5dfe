#include "material_grid.h"

#include <cmath>

namespace multidir::slicing::audit {

Eigen::Vector3i MaterialGrid::cellOf(const Eigen::Vector3d& p) const {
  return Eigen::Vector3i(static_cast<int>(std::floor(p.x() / m_cell)), static_cast<int>(std::floor(p.y() / m_cell)),
                         static_cast<int>(std::floor(p.z() / m_cell)));
}

std::int64_t MaterialGrid::key(int i, int j, int k) {
  return (static_cast<std::int64_t>(i) & 0x1FFFFF) | ((static_cast<std::int64_t>(j) & 0x1FFFFF) << 21) |
         ((static_cast<std::int64_t>(k) & 0x1FFFFF) << 42);
}

void MaterialGrid::add(const BeadSample& sample) {
  const Eigen::Vector3i c = cellOf(sample.point.cast<double>());
  m_cells[key(c.x(), c.y(), c.z())].push_back(sample);
  ++m_count;
}

}  // namespace multidir::slicing::audit

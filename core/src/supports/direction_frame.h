#pragma once
// Coordinates along a printing direction: height along it, and a fixed planar frame perpendicular to it.
#include <Eigen/Core>
#include <cmath>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

class DirectionFrame {
 public:
  // `up` must be unit length. The planar axes depend only on `up`, so every region printed along one
  // direction samples on one grid.
  explicit DirectionFrame(const Vec3& up) : m_up(up) {
    Vec3 helper = Vec3::UnitX();
    if (std::abs(up.y()) < std::abs(up.x()) && std::abs(up.y()) <= std::abs(up.z())) helper = Vec3::UnitY();
    else if (std::abs(up.z()) < std::abs(up.x()) && std::abs(up.z()) < std::abs(up.y())) helper = Vec3::UnitZ();
    m_u = up.cross(helper).normalized();
    m_v = up.cross(m_u);
  }
  const Vec3& up() const { return m_up; }
  double height(const Vec3& p) const { return m_up.dot(p); }
  Eigen::Vector2d planar(const Vec3& p) const { return {m_u.dot(p), m_v.dot(p)}; }
  Vec3 horizontal(const Vec3& p) const { return p - m_up.dot(p) * m_up; }

 private:
  Vec3 m_up, m_u, m_v;
};

}  // namespace multidir::core::detail

#include "multidir/assembly/plates.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "multidir/core/apart/bed_fit.h"

namespace multidir::assembly {

using core::TriangleMesh;
using core::Vec3;

namespace {

std::string numbered(const char* stem, std::size_t index) {
  char text[32];
  std::snprintf(text, sizeof text, "%s-%02zu", stem, index + 1);
  return text;
}

TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Isometry3d& motion) {
  TriangleMesh out = mesh;
  for (Vec3& v : out.vertices) v = motion * v;
  return out;
}

std::string sizeText(double x, double y, double z) {
  char text[64];
  std::snprintf(text, sizeof text, "%.1f x %.1f x %.1f mm", x, y, z);
  return text;
}

// An open row of a plate: where the next item goes, and how deep the row is.
struct Shelf {
  double y = 0, depth = 0, x = 0;
};

}  // namespace

core::Result<PlateLayout> arrangeOnPlates(const std::vector<TriangleMesh>& parts, const std::vector<Vec3>& printingDirections,
                                          const std::vector<TriangleMesh>& dowels, const std::vector<Vec3>& dowelAxes,
                                          const PlateOptions& options) {
  const Eigen::Vector2d room = options.bedMax - options.bedMin - Eigen::Vector2d::Constant(2.0 * options.marginMm);
  const core::BuildVolume volume{room.x(), room.y(), options.maxHeightMm};
  struct Laid {
    std::string name;
    Eigen::Isometry3d pose;
    Vec3 size;
    const TriangleMesh* mesh;
  };
  std::vector<Laid> laid;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const core::BedPose pose = core::layOnBed(parts[i], printingDirections[i], volume);
    laid.push_back({numbered("part", i), pose.modelToBed, pose.sizeMm, &parts[i]});
  }
  for (std::size_t i = 0; i < dowels.size(); ++i) {
    const core::BedPose pose = core::layOnBed(dowels[i], dowelAxes[i], volume);
    laid.push_back({numbered("dowel", i), pose.modelToBed, pose.sizeMm, &dowels[i]});
  }
  for (const Laid& item : laid)
    if (item.size.x() > room.x() + 1e-9 || item.size.y() > room.y() + 1e-9 || item.size.z() > options.maxHeightMm + 1e-9)
      return core::Error{core::ErrorCode::InvalidParameter,
                         item.name + " lies " + sizeText(item.size.x(), item.size.y(), item.size.z()) +
                             ", more than the bed's room " + sizeText(room.x(), room.y(), options.maxHeightMm) +
                             ": cut the plan for this printer (multidir apart --printer)",
                         item.name};

  // Deepest first (ties: the order given), each into the first plate and row with room.
  std::vector<std::size_t> order(laid.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return laid[a].size.y() > laid[b].size.y(); });
  std::vector<std::vector<Shelf>> plates;
  std::vector<Eigen::Vector3d> at(laid.size());
  std::vector<int> plateOf(laid.size());
  for (std::size_t k : order) {
    const Vec3& size = laid[k].size;
    bool placed = false;
    for (std::size_t p = 0; p < plates.size() && !placed; ++p) {
      for (Shelf& shelf : plates[p])
        if (shelf.x + size.x() <= room.x() + 1e-9 && size.y() <= shelf.depth + 1e-9) {
          at[k] = Vec3(shelf.x, shelf.y, 0);
          shelf.x += size.x() + options.spacingMm;
          plateOf[k] = static_cast<int>(p);
          placed = true;
          break;
        }
      if (placed) break;
      const double top = plates[p].empty() ? 0 : plates[p].back().y + plates[p].back().depth + options.spacingMm;
      if (top + size.y() <= room.y() + 1e-9) {
        plates[p].push_back({top, size.y(), size.x() + options.spacingMm});
        at[k] = Vec3(0, top, 0);
        plateOf[k] = static_cast<int>(p);
        placed = true;
      }
    }
    if (!placed) {
      plates.push_back({Shelf{0, size.y(), size.x() + options.spacingMm}});
      at[k] = Vec3::Zero();
      plateOf[k] = static_cast<int>(plates.size() - 1);
    }
  }
  PlateLayout layout;
  layout.plates = static_cast<int>(plates.size());
  for (std::size_t k = 0; k < laid.size(); ++k) {
    PlateItem item;
    item.name = laid[k].name;
    item.plate = plateOf[k];
    const Vec3 corner(options.bedMin.x() + options.marginMm, options.bedMin.y() + options.marginMm, 0);
    item.modelToPlate = Eigen::Translation3d(corner + at[k]) * laid[k].pose;
    item.mesh = transformed(*laid[k].mesh, item.modelToPlate);
    layout.items.push_back(std::move(item));
  }
  return layout;
}

TriangleMesh plateMesh(const PlateLayout& layout, int plate) {
  TriangleMesh out;
  for (const PlateItem& item : layout.items) {
    if (item.plate != plate) continue;
    const auto base = static_cast<std::int32_t>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), item.mesh.vertices.begin(), item.mesh.vertices.end());
    for (const core::Triangle& t : item.mesh.triangles) out.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  out.resetOrigins();
  return out;
}

}  // namespace multidir::assembly

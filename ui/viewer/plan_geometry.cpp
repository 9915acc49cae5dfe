#include "ui/viewer/plan_geometry.h"

#include <algorithm>
#include <cmath>

namespace multidir::ui {
namespace {

bool hasCapOf(const core::TriangleMesh& mesh, std::int32_t planeId) {
  return std::any_of(mesh.origins.begin(), mesh.origins.end(),
                     [planeId](const core::FaceOrigin& origin) { return origin.isCap() && origin.index == planeId; });
}

}  // namespace

std::vector<int> supportingRegions(const core::Decomposition& plan) {
  std::vector<int> parents(plan.regions.size(), -1);
  for (std::size_t i = 1; i < plan.regions.size(); ++i) {
    const std::int32_t plane = plan.regions[i].clippingIndex;
    if (plane < 0) continue;
    // The latest earlier region with that cap: a later cut may split the region below, and then both
    // pieces carry part of the cap; the base then rests on whichever comes last, which is printed last.
    for (std::size_t j = i; j-- > 0;) {
      if (hasCapOf(plan.regions[j].mesh, plane)) {
        parents[i] = static_cast<int>(j);
        break;
      }
    }
  }
  return parents;
}

std::vector<core::Vec3> explodeOffsets(const core::Decomposition& plan, double distanceMm) {
  const std::vector<int> parents = supportingRegions(plan);
  std::vector<core::Vec3> offsets(plan.regions.size(), core::Vec3::Zero());
  if (!std::isfinite(distanceMm)) return offsets;
  // Parents come before their children in printing order, so one pass in that order suffices.
  for (std::size_t i = 1; i < plan.regions.size(); ++i) {
    const core::Vec3 base = parents[i] >= 0 ? offsets[static_cast<std::size_t>(parents[i])] : core::Vec3::Zero();
    offsets[i] = base + distanceMm * plan.regions[i].printingDirection.normalized();
  }
  return offsets;
}

std::vector<PlaneDisc> planeDiscs(const core::Decomposition& plan) {
  std::vector<PlaneDisc> discs(plan.clippingPlanes.size());
  for (std::size_t k = 0; k < discs.size(); ++k) {
    const core::Plane& plane = plan.clippingPlanes[k];
    PlaneDisc& disc = discs[k];
    disc.normal = plane.normal.normalized();
    // Area-weighted centroid of the cap faces, then the farthest cap corner from it.
    core::Vec3 weighted = core::Vec3::Zero();
    double area = 0.0;
    for (const core::Region& region : plan.regions) {
      const core::TriangleMesh& mesh = region.mesh;
      for (std::size_t f = 0; f < mesh.faceCount() && f < mesh.origins.size(); ++f) {
        if (!mesh.origins[f].isCap() || mesh.origins[f].index != static_cast<std::int32_t>(k)) continue;
        const double a = mesh.faceArea(f);
        weighted += a * (mesh.corner(f, 0) + mesh.corner(f, 1) + mesh.corner(f, 2)) / 3.0;
        area += a;
      }
    }
    if (!(area > 0.0)) continue;
    disc.center = plane.project(weighted / area);
    double radius = 0.0;
    for (const core::Region& region : plan.regions) {
      const core::TriangleMesh& mesh = region.mesh;
      for (std::size_t f = 0; f < mesh.faceCount() && f < mesh.origins.size(); ++f) {
        if (!mesh.origins[f].isCap() || mesh.origins[f].index != static_cast<std::int32_t>(k)) continue;
        for (int c = 0; c < 3; ++c) radius = std::max(radius, (plane.project(mesh.corner(f, c)) - disc.center).norm());
      }
    }
    disc.radiusMm = kPlaneDiscMargin * radius;
  }
  return discs;
}

}  // namespace multidir::ui

#pragma once
// Where the plan view puts things: how far the exploded view moves each region, and where the clipping
// planes' discs go. Pure geometry (no VTK), so it can be tested.
#include <vector>

#include "multidir/core/search/decomposition.h"

namespace multidir::ui {

// The region each region was printed on: the earlier region that carries a cap of the plane that cut it off
// (its base). -1 for the first region, and for a region whose base is found on no earlier region.
[[nodiscard]] std::vector<int> supportingRegions(const core::Decomposition& plan);

// Exploded view: region i moves along its printing direction by `distanceMm`, plus whatever moved the
// region it stands on, so every region stays clear of the one below it. One offset per region.
[[nodiscard]] std::vector<core::Vec3> explodeOffsets(const core::Decomposition& plan, double distanceMm);

// A disc showing one clipping plane where it cut the model: centred on the cut (the centroid of that
// plane's cap faces over all regions) and a little larger than it.
struct PlaneDisc {
  core::Vec3 center = core::Vec3::Zero();
  core::Vec3 normal = core::Vec3::UnitZ();
  double radiusMm = 0.0;  // 0 when the plane left no cap (nothing to show)
};

// How much larger than the cut the disc is drawn.
constexpr double kPlaneDiscMargin = 1.2;

// One disc per clipping plane, in clipping order.
[[nodiscard]] std::vector<PlaneDisc> planeDiscs(const core::Decomposition& plan);

}  // namespace multidir::ui

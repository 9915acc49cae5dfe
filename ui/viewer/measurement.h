#pragma once
// A distance measured in the 3D view (View > Measure distance): two points picked on the model's surface,
// in the model's own coordinates (mm, the frame of the file it was read from), and the straight distance
// between them (docs/architecture.md, "The 3D view").
#include <optional>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::ui {

struct Measurement {
  std::optional<core::Vec3> first;
  std::optional<core::Vec3> second;  // set only after first

  [[nodiscard]] bool complete() const { return first && second; }
  // The Euclidean distance between the two points (mm); nullopt until both are picked.
  [[nodiscard]] std::optional<double> distanceMm() const {
    if (!complete()) return std::nullopt;
    return (*second - *first).norm();
  }
};

}  // namespace multidir::ui

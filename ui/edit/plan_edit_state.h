#pragma once
// What one step of plan editing is: the clipping planes in clipping order and the plane selected in the
// editor. Undo and redo go back and forth between such states, so they restore exactly what was there.
#include <vector>

#include "multidir/core/geometry/plane.h"

namespace multidir::ui {

struct PlanEditState {
  std::vector<core::Plane> planes;  // in clipping order (plane k cuts region N-k off)
  int selectedPlane = -1;           // index into planes, -1: none
};

// Bit-for-bit equal planes: an edited plane list is compared with the one it came from, never with a
// recomputed one, so no tolerance is wanted (a tolerance would merge two states a person told apart).
[[nodiscard]] inline bool samePlanes(const std::vector<core::Plane>& a, const std::vector<core::Plane>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].normal != b[i].normal || a[i].offset != b[i].offset) return false;
  }
  return true;
}

}  // namespace multidir::ui

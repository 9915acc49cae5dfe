#include "ui/viewer/standard_view.h"

#include <cmath>

namespace multidir::ui {

core::Vec3 frontSideFor(const core::Vec3& up) {
  const core::Vec3 reference = std::abs(up.z()) > 0.9 ? core::Vec3(0.0, -1.0, 0.0) : core::Vec3::UnitZ();
  return (reference - reference.dot(up) * up).normalized();
}

ViewOrientation orientationOf(StandardView view, const core::Vec3& up) {
  const core::Vec3 front = frontSideFor(up);
  // Seen from the front with `up` up on screen, the right of the screen (right-handed axes).
  const core::Vec3 right = (-front).cross(up);
  switch (view) {
    case StandardView::Front: return {front, up};
    case StandardView::Back: return {-front, up};
    case StandardView::Right: return {right, up};
    case StandardView::Left: return {-right, up};
    case StandardView::Top: return {up, -front};
    case StandardView::Bottom: return {-up, front};
    case StandardView::Iso: return {(front + right + up).normalized(), up};
    case StandardView::Home: break;
  }
  return {(front + 0.55 * right + 0.45 * up).normalized(), up};
}

}  // namespace multidir::ui

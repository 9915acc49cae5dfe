#include "ui/device/device_snapshot.h"

#include <cmath>

namespace multidir::ui {

core::MachineSpec machineForDevice(DeviceKind kind, const std::optional<core::MachineSpec>& profile,
                                   bool* usedProfile) {
  const core::MachineKind wanted =
      kind == DeviceKind::RotaryPlatform ? core::MachineKind::RotaryPlatform : core::MachineKind::TiltRotate;
  const bool fits = profile && profile->kind == wanted && core::validate(*profile).ok();
  if (usedProfile) *usedProfile = fits;
  if (fits) return *profile;
  core::MachineSpec spec;  // the documented defaults: -60..60 degrees in 1 degree steps, tilt up to 90 degrees
  spec.kind = wanted;
  if (profile) {
    spec.up = profile->up;
    // Keep the default axis unless it would no longer be perpendicular to the profile's up.
    if (std::abs(spec.rotationAxis.dot(spec.up)) > 1e-9) spec.rotationAxis = core::platformFrameX(spec.up);
  }
  return spec;
}

}  // namespace multidir::ui

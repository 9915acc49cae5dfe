#include "number_text.h"

#include <cstdio>

namespace multidir::cli {

std::string withThousands(long long value) {
  std::string digits = std::to_string(value < 0 ? -value : value);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(static_cast<std::size_t>(i), ",");
  return value < 0 ? "-" + digits : digits;
}

std::string formatNumber(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string machineAnglesText(core::MachineKind kind, const core::MachineAngles& angles) {
  switch (kind) {
    case core::MachineKind::ThreeAxis:
      return "-";
    case core::MachineKind::RotaryPlatform:
      return "rotary " + formatNumber("%6.1f", angles.rotaryDegrees);
    case core::MachineKind::TiltRotate:
    case core::MachineKind::Apart:
      return "tilt " + formatNumber("%5.1f", angles.tiltDegrees) + "  azimuth " +
             formatNumber("%6.1f", angles.azimuthDegrees);
  }
  return "";
}

}  // namespace multidir::cli

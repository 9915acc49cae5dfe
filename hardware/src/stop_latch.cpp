#include "multidir/hardware/stop_latch.h"

namespace multidir::hardware {

const char* stopKindName(StopKind kind) {
  switch (kind) {
    case StopKind::None: return "none";
    case StopKind::Stop: return "stop";
    case StopKind::EmergencyStop: return "emergency stop";
  }
  return "?";
}

}  // namespace multidir::hardware

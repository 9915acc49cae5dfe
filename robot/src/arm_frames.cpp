#include "multidir/robot/arm_frames.h"

#include <cmath>

namespace multidir::robot {

std::array<Eigen::Isometry3d, 7> armFrames(const ArmModel& arm, const Joints& q) {
  std::array<Eigen::Isometry3d, 7> frames;
  frames[0] = Eigen::Isometry3d::Identity();
  for (std::size_t j = 0; j < 6; ++j) {
    // Standard DH: Rz(theta) Tz(d) Tx(a) Rx(alpha).
    Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
    step.rotate(Eigen::AngleAxisd(q[j], Eigen::Vector3d::UnitZ()));
    step.translate(Eigen::Vector3d(arm.a[j], 0.0, arm.d[j]));
    step.rotate(Eigen::AngleAxisd(arm.alpha[j], Eigen::Vector3d::UnitX()));
    frames[j + 1] = frames[j] * step;
  }
  return frames;
}

}  // namespace multidir::robot

#pragma once
// The arm's DH frames for drawing it (the studio's cell view draws its links as simple solids between them).
#include <Eigen/Geometry>

#include <array>

#include "multidir/robot/ur_kinematics.h"

namespace multidir::robot {

// Frames 0 (the base) to 6 (the flange) in the base frame: frame i+1 = frame i * DH(joint i). frames[6] is
// forwardKinematics(arm, joints).
std::array<Eigen::Isometry3d, 7> armFrames(const ArmModel& arm, const Joints& joints);

}  // namespace multidir::robot

#pragma once
// What the robot tests share to build a UR job and run it: a pose as URScript writes it, the cell's TCP at a joint
// pose, and a UR simulator on four consecutive free ports (the --robot HOST:PORT convention: dashboard, secondary,
// real-time, RTDE).
#include <unistd.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <memory>
#include <string>

#include "multidir/hardware/ur_simulator.h"
#include "multidir/robot/ur_kinematics.h"

namespace multidir::test {

// p[x, y, z, rx, ry, rz] in metres and a rotation vector, from a pose in millimetres.
inline std::string urPose(const Eigen::Isometry3d& p) {
  const Eigen::AngleAxisd aa(p.linear());
  const Eigen::Vector3d r = aa.axis() * aa.angle();
  const Eigen::Vector3d t = p.translation() / 1000.0;
  char text[200];
  std::snprintf(text, sizeof text, "p[%.9f, %.9f, %.9f, %.12f, %.12f, %.12f]", t.x(), t.y(), t.z(), r.x(), r.y(),
                r.z());
  return text;
}

// The UR5's TCP (the platform centre, 50 mm off the flange) at `joints`, moved by `offset` (mm).
inline Eigen::Isometry3d ur5TcpAt(const robot::Joints& joints, const Eigen::Vector3d& offset) {
  Eigen::Isometry3d pose = robot::forwardKinematics(*robot::armModel("ur5"), joints);
  pose.translation() += pose.linear() * Eigen::Vector3d(0, 0, 50.0) + offset;
  return pose;
}

// A started simulator on the first four free consecutive ports from `firstPort` (offset by the process id, so that
// test programs running side by side look in different places); null when none were free.
inline std::unique_ptr<hardware::UrSimulator> startUrSimulatorOnFreePorts(hardware::UrSimulatorOptions options,
                                                                          int firstPort) {
  for (int base = firstPort + static_cast<int>(::getpid() % 200) * 30; base < 65000; base += 7) {
    options.dashboardPort = base;
    options.secondaryPort = base + 1;
    options.realtimePort = base + 2;
    options.rtdePort = base + 3;
    auto simulator = std::make_unique<hardware::UrSimulator>(options);
    if (simulator->start().ok()) return simulator;
  }
  return nullptr;
}

}  // namespace multidir::test
